#include "unfurl/sim/flexible/beam_structure.hpp"

#include <array>

#include "flexible/cubic_hermite_shape.hpp"

namespace unfurl::sim::flexible {
namespace {

// Adds the element between nodes e and e + 1 of one field: `component`
// the value's degree of freedom, `slope` the slope's (-1 for a linear
// field) with `slope_sign` the sign relating it to the value's derivative
// (w' = -theta_y, v' = theta_z), `stiffness` times the integral of the
// field's `derivative`-th derivative squared, `inertia` times that of its
// value squared.
void add_field(Structure& beam, int e, double h, int component, int slope, double slope_sign, int derivative,
               double stiffness, double inertia) {
  const bool cubic = slope >= 0;
  const int n = cubic ? 4 : 2;
  int to[4];
  double sign[4] = {1, 1, 1, 1};
  if (cubic) {
    to[0] = beam.dof(e, component), to[1] = beam.dof(e, slope);
    to[2] = beam.dof(e + 1, component), to[3] = beam.dof(e + 1, slope);
    sign[1] = sign[3] = slope_sign;
  } else {
    to[0] = beam.dof(e, component), to[1] = beam.dof(e + 1, component);
  }
  for (int g = 0; g < 4; ++g) {
    const double xi = GaussFour::x[g], dx = GaussFour::w[g] * h;
    std::array<double, 4> N, D;
    if (cubic) {
      const CubicHermiteShape S(xi, h);
      for (int a = 0; a < 4; ++a) N[a] = sign[a] * S.N[a], D[a] = sign[a] * (derivative == 2 ? S.ddN[a] : S.dN[a]);
    } else {
      N = {1 - xi, xi, 0, 0};
      D = {-1 / h, 1 / h, 0, 0};
    }
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) {
        beam.M(to[a], to[b]) += dx * inertia * N[a] * N[b];
        beam.K(to[a], to[b]) += dx * stiffness * D[a] * D[b];
      }
  }
}

}  // namespace

Structure beam_structure(const BeamSection& s) {
  Structure beam;
  beam.dofs_per_node = 6;
  const double h = s.length / s.elements;
  for (int i = 0; i <= s.elements; ++i) beam.nodes.emplace_back(i * h, 0.0, 0.0);
  const int n = 6 * static_cast<int>(beam.nodes.size());
  beam.M.setZero(n, n);
  beam.K.setZero(n, n);
  beam.node_motion = Eigen::MatrixXd::Identity(6, 6);
  // Translation v + w x r, rotation w.
  beam.rigid.setZero(n, 6);
  for (int node = 0; node <= s.elements; ++node) {
    const Eigen::Vector3d& r = beam.nodes[node];
    beam.rigid.block<3, 3>(beam.dof(node, beam_u_x), 0).setIdentity();
    beam.rigid.block<3, 3>(beam.dof(node, beam_u_x), 3) << 0, r.z(), -r.y(), -r.z(), 0, r.x(), r.y(), -r.x(), 0;
    beam.rigid.block<3, 3>(beam.dof(node, beam_theta_x), 3).setIdentity();
  }
  for (int e = 0; e < s.elements; ++e) {
    add_field(beam, e, h, beam_u_x, -1, 1, 1, s.axial_stiffness, s.mass_per_length);
    add_field(beam, e, h, beam_theta_x, -1, 1, 1, s.torsional_stiffness, s.polar_inertia_per_length);
    add_field(beam, e, h, beam_u_y, beam_theta_z, 1, 2, s.bending_stiffness_z, s.mass_per_length);
    add_field(beam, e, h, beam_u_z, beam_theta_y, -1, 2, s.bending_stiffness_y, s.mass_per_length);
  }
  return beam;
}

Eigen::MatrixXd geometric_stiffness(const BeamSection& s, const std::function<double(double)>& axial_force) {
  const int n = 6 * (s.elements + 1);
  Eigen::MatrixXd KG = Eigen::MatrixXd::Zero(n, n);
  const double h = s.length / s.elements;
  // Bending in xy (v, theta_z = v') and in xz (w, theta_y = -w').
  const int value[2] = {beam_u_y, beam_u_z}, slope[2] = {beam_theta_z, beam_theta_y};
  const double sign[2] = {1, -1};
  for (int e = 0; e < s.elements; ++e)
    for (int g = 0; g < 4; ++g) {
      const double xi = GaussFour::x[g];
      const CubicHermiteShape S(xi, h);
      const double N_dx = axial_force((e + xi) * h) * GaussFour::w[g] * h;
      for (int plane = 0; plane < 2; ++plane) {
        const int to[4] = {6 * e + value[plane], 6 * e + slope[plane], 6 * (e + 1) + value[plane],
                           6 * (e + 1) + slope[plane]};
        const double d[4] = {S.dN[0], sign[plane] * S.dN[1], S.dN[2], sign[plane] * S.dN[3]};
        for (int a = 0; a < 4; ++a)
          for (int b = 0; b < 4; ++b) KG(to[a], to[b]) += N_dx * d[a] * d[b];
      }
    }
  return KG;
}

}  // namespace unfurl::sim::flexible
