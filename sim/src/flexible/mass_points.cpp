#include "unfurl/sim/flexible/mass_points.hpp"

#include "flexible/cubic_hermite_shape.hpp"

namespace unfurl::sim::flexible {

std::vector<MassPoint> plate_mass_points(const PlateSpec& s) {
  std::vector<MassPoint> points;
  const double hx = s.length_x / s.elements_x, hy = s.length_y / s.elements_y;
  const int row = s.elements_x + 1;
  for (int ey = 0; ey < s.elements_y; ++ey)
    for (int ex = 0; ex < s.elements_x; ++ex)
      for (int gx = 0; gx < 4; ++gx) {
        const CubicHermiteShape X(GaussFour::x[gx], hx);
        for (int gy = 0; gy < 4; ++gy) {
          const CubicHermiteShape Y(GaussFour::x[gy], hy);
          MassPoint p;
          p.m = s.mass_per_area * GaussFour::w[gx] * GaussFour::w[gy] * hx * hy;
          p.r = {(ex + GaussFour::x[gx]) * hx, (ey + GaussFour::x[gy]) * hy, 0};
          p.N.setZero(3, 16);
          p.R.setZero(3, 16);
          for (int corner = 0; corner < 4; ++corner) {
            const int cx = corner % 2, cy = corner / 2, node = ex + cx + (ey + cy) * row;
            for (int k = 0; k < 4; ++k) {
              const int fx = 2 * cx + (k == plate_w_x || k == plate_w_xy);
              const int fy = 2 * cy + (k == plate_w_y || k == plate_w_xy);
              p.dofs.push_back(4 * node + k);
              p.N(2, 4 * corner + k) = X.N[fx] * Y.N[fy];
            }
          }
          points.push_back(std::move(p));
        }
      }
  return points;
}

std::vector<MassPoint> beam_mass_points(const BeamSection& s) {
  std::vector<MassPoint> points;
  const double h = s.length / s.elements;
  for (int e = 0; e < s.elements; ++e)
    for (int g = 0; g < 4; ++g) {
      const double xi = GaussFour::x[g];
      const CubicHermiteShape S(xi, h);
      MassPoint p;
      p.m = s.mass_per_length * GaussFour::w[g] * h;
      p.r = {(e + xi) * h, 0, 0};
      for (int node = e; node <= e + 1; ++node)
        for (int k = 0; k < 6; ++k) p.dofs.push_back(6 * node + k);
      p.N.setZero(3, 12);
      p.R.setZero(3, 12);
      // Columns: 6 a node; stretch linear, bending cubic (w' = -theta_y,
      // v' = theta_z), twist linear.
      for (int end = 0; end < 2; ++end) {
        const int c = 6 * end;
        p.N(0, c + beam_u_x) = end ? xi : 1 - xi;
        p.N(1, c + beam_u_y) = S.N[2 * end];
        p.N(1, c + beam_theta_z) = S.N[2 * end + 1];
        p.N(2, c + beam_u_z) = S.N[2 * end];
        p.N(2, c + beam_theta_y) = -S.N[2 * end + 1];
        p.R(0, c + beam_theta_x) = end ? xi : 1 - xi;
      }
      p.J(0, 0) = s.polar_inertia_per_length * GaussFour::w[g] * h;
      points.push_back(std::move(p));
    }
  return points;
}

namespace {

// The slopes v' and w' of every mode at xi in element e: 2 x m.
Eigen::MatrixXd beam_slopes(const Eigen::MatrixXd& shape, int e, double xi, double h) {
  const CubicHermiteShape S(xi, h);
  Eigen::MatrixXd slopes = Eigen::MatrixXd::Zero(2, shape.cols());
  for (int end = 0; end < 2; ++end) {
    const int node = 6 * (e + end);
    slopes.row(0) += S.dN[2 * end] * shape.row(node + beam_u_y) + S.dN[2 * end + 1] * shape.row(node + beam_theta_z);
    slopes.row(1) += S.dN[2 * end] * shape.row(node + beam_u_z) - S.dN[2 * end + 1] * shape.row(node + beam_theta_y);
  }
  return slopes;
}

// integral over [e h, (e + upto) h] of the slopes' squares, by four Gauss
// points on that span (exact: the integrand is of degree 4).
Eigen::MatrixXd squared_slopes(const Eigen::MatrixXd& shape, int e, double upto, double h) {
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(shape.cols(), shape.cols());
  for (int g = 0; g < 4; ++g) {
    const Eigen::MatrixXd s = beam_slopes(shape, e, upto * GaussFour::x[g], h);
    G.noalias() += upto * GaussFour::w[g] * h * s.transpose() * s;
  }
  return G;
}

}  // namespace

std::vector<Shortening> beam_shortening(const BeamSection& section, const Eigen::MatrixXd& shape) {
  std::vector<Shortening> out;
  const double h = section.length / section.elements;
  Eigen::MatrixXd before = Eigen::MatrixXd::Zero(shape.cols(), shape.cols());  // up to element e's start
  for (int e = 0; e < section.elements; ++e) {
    for (int g = 0; g < 4; ++g)
      out.push_back({Eigen::Vector3d::UnitX(), before + squared_slopes(shape, e, GaussFour::x[g], h)});
    before += squared_slopes(shape, e, 1.0, h);
  }
  return out;
}

Eigen::MatrixXd mass_matrix(const std::vector<MassPoint>& points, int size) {
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(size, size);
  for (const MassPoint& p : points) {
    const Eigen::MatrixXd local = p.m * p.N.transpose() * p.N + p.R.transpose() * p.J * p.R;
    for (size_t a = 0; a < p.dofs.size(); ++a)
      for (size_t b = 0; b < p.dofs.size(); ++b) M(p.dofs[a], p.dofs[b]) += local(a, b);
  }
  return M;
}

}  // namespace unfurl::sim::flexible
