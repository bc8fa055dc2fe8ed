#include "unfurl/sim/flexible/plate_structure.hpp"

#include <Eigen/Core>
#include <algorithm>

#include "flexible/cubic_hermite_shape.hpp"

namespace unfurl::sim::flexible {
namespace {

using Vec16 = Eigen::Matrix<double, 16, 1>;
using Mat16 = Eigen::Matrix<double, 16, 16>;

int node_index(const PlateSpec& s, int i, int j) { return i + j * (s.elements_x + 1); }

// The element's mass and stiffness over its 16 degrees of freedom: the
// corners (0,0), (1,0), (0,1), (1,1), each with w, w_x, w_y, w_xy. The
// strain energy is (1/2) D [w_xx^2 + w_yy^2 + 2 nu w_xx w_yy +
// 2 (1 - nu) w_xy^2] over the area.
void element_matrices(const PlateSpec& s, double hx, double hy, Mat16& M, Mat16& K) {
  M.setZero();
  K.setZero();
  for (int gx = 0; gx < 4; ++gx) {
    const CubicHermiteShape X(GaussFour::x[gx], hx);
    for (int gy = 0; gy < 4; ++gy) {
      const CubicHermiteShape Y(GaussFour::x[gy], hy);
      Vec16 N, w_xx, w_yy, w_xy;
      for (int corner = 0; corner < 4; ++corner) {
        const int cx = corner % 2, cy = corner / 2;
        for (int k = 0; k < 4; ++k) {
          const int fx = 2 * cx + (k == plate_w_x || k == plate_w_xy);
          const int fy = 2 * cy + (k == plate_w_y || k == plate_w_xy);
          const int e = 4 * corner + k;
          N[e] = X.N[fx] * Y.N[fy];
          w_xx[e] = X.ddN[fx] * Y.N[fy];
          w_yy[e] = X.N[fx] * Y.ddN[fy];
          w_xy[e] = X.dN[fx] * Y.dN[fy];
        }
      }
      const double dA = GaussFour::w[gx] * GaussFour::w[gy] * hx * hy;
      M.noalias() += dA * s.mass_per_area * N * N.transpose();
      K.noalias() += dA * s.bending_stiffness *
                     (w_xx * w_xx.transpose() + w_yy * w_yy.transpose() +
                      s.poisson * (w_xx * w_yy.transpose() + w_yy * w_xx.transpose()) +
                      2 * (1 - s.poisson) * w_xy * w_xy.transpose());
    }
  }
}

}  // namespace

Structure plate_structure(const PlateSpec& s) {
  Structure plate;
  plate.dofs_per_node = 4;
  const double hx = s.length_x / s.elements_x, hy = s.length_y / s.elements_y;
  for (int j = 0; j <= s.elements_y; ++j)
    for (int i = 0; i <= s.elements_x; ++i) plate.nodes.emplace_back(i * hx, j * hy, 0.0);
  const int n = 4 * static_cast<int>(plate.nodes.size());
  plate.M.setZero(n, n);
  plate.K.setZero(n, n);
  // w along z; the rotation about x is w_y, about y -w_x.
  plate.node_motion.setZero(6, 4);
  plate.node_motion(2, plate_w) = 1;
  plate.node_motion(3, plate_w_y) = 1;
  plate.node_motion(4, plate_w_x) = -1;
  // w = v_z + w_x y - w_y x for the frame's motion (v, w).
  plate.rigid.setZero(n, 6);
  for (int node = 0; node < static_cast<int>(plate.nodes.size()); ++node) {
    const Eigen::Vector3d& r = plate.nodes[node];
    plate.rigid(plate.dof(node, plate_w), 2) = 1;
    plate.rigid(plate.dof(node, plate_w), 3) = r.y();
    plate.rigid(plate.dof(node, plate_w), 4) = -r.x();
    plate.rigid(plate.dof(node, plate_w_x), 4) = -1;
    plate.rigid(plate.dof(node, plate_w_y), 3) = 1;
  }
  // Every element is the same rectangle.
  Mat16 Me, Ke;
  element_matrices(s, hx, hy, Me, Ke);
  for (int ey = 0; ey < s.elements_y; ++ey)
    for (int ex = 0; ex < s.elements_x; ++ex) {
      int to[16];
      for (int corner = 0; corner < 4; ++corner)
        for (int k = 0; k < 4; ++k) to[4 * corner + k] = plate.dof(node_index(s, ex + corner % 2, ey + corner / 2), k);
      for (int a = 0; a < 16; ++a)
        for (int b = 0; b < 16; ++b) {
          plate.M(to[a], to[b]) += Me(a, b);
          plate.K(to[a], to[b]) += Ke(a, b);
        }
    }
  return plate;
}

std::vector<int> held_dofs(const PlateSpec& s, const PlateEdges& edges) {
  std::vector<int> held;
  auto hold = [&](int node, std::initializer_list<int> components) {
    for (int k : components) held.push_back(4 * node + k);
  };
  // Along an edge of constant x, w_y and w_xy are slopes along it.
  auto hold_edge = [&](EdgeSupport support, int node, int along_slope, int across_slope) {
    if (support == EdgeSupport::simply_supported) hold(node, {plate_w, along_slope});
    if (support == EdgeSupport::clamped) hold(node, {plate_w, along_slope, across_slope, plate_w_xy});
  };
  for (int j = 0; j <= s.elements_y; ++j) {
    hold_edge(edges.x0, node_index(s, 0, j), plate_w_y, plate_w_x);
    hold_edge(edges.x1, node_index(s, s.elements_x, j), plate_w_y, plate_w_x);
  }
  for (int i = 0; i <= s.elements_x; ++i) {
    hold_edge(edges.y0, node_index(s, i, 0), plate_w_x, plate_w_y);
    hold_edge(edges.y1, node_index(s, i, s.elements_y), plate_w_x, plate_w_y);
  }
  std::sort(held.begin(), held.end());
  held.erase(std::unique(held.begin(), held.end()), held.end());
  return held;
}

}  // namespace unfurl::sim::flexible
