#include "unfurl/studies/exact_pendulum.hpp"

#include <cmath>
#include <vector>

#include "unfurl/sim/elements/gravity.hpp"

namespace unfurl::studies {

double jacobi_sn(double u, double m) {
  // Descending Landen / AGM (Abramowitz and Stegun 16.4): a_n, c_n until
  // c_n vanishes, then phi_N = 2^N a_N u and back down.
  if (m == 0) return std::sin(u);
  std::vector<double> a{1.0}, c{std::sqrt(m)};
  double b = std::sqrt(1 - m);
  while (std::abs(c.back()) > 1e-16 * a.back() && a.size() < 40) {
    const double an = 0.5 * (a.back() + b);
    c.push_back(0.5 * (a.back() - b));
    b = std::sqrt(a.back() * b);
    a.push_back(an);
  }
  const int N = static_cast<int>(a.size()) - 1;
  double phi = std::ldexp(a[N] * u, N);
  for (int n = N; n > 0; --n) phi = 0.5 * (phi + std::asin(c[n] / a[n] * std::sin(phi)));
  return std::sin(phi);
}

double ExactPendulum::angle(double t) const {
  const double k = std::sin(phi0 / 2), m = k * k;
  const double K = std::comp_ellint_1(std::abs(k));
  return q_eq + 2 * std::asin(k * jacobi_sn(K - omega * t, m));
}

std::optional<ExactPendulum> exact_pendulum(const sim::Scene& scene) {
  const sim::Model& model = scene.model;
  if (model.size() != 1 || model.joints[0].type != sim::JointType::revolute || model.parent[0] != sim::kBase) return {};
  const sim::Vec3 gravity = scene.gravity();
  if (!model.base_velocity.isZero(0) || gravity.isZero(0)) return {};
  // Gravity alone acts.
  if (scene.elements.size() != scene.elements_of<sim::Gravity>().size() || !scene.loops.empty()) return {};
  const bool at_rest = scene.p0.empty() ? scene.dq0[0] == 0 : scene.p0[0] == 0;
  if (!at_rest) return {};

  const sim::Body& body = model.bodies[0];
  const sim::Joint& joint = model.joints[0];
  const sim::Vec3 a = joint.axis.normalized();
  // The centre of mass from the hinge, across the axis, in the child frame;
  // at angle q it is turned by q about a (frames coincide at q = 0).
  const sim::Vec3 d = body.com - joint.child_point;
  const sim::Vec3 d_perp = d - d.dot(a) * a;
  const double I_axis = a.dot(body.inertia_com * a) + body.mass * d_perp.squaredNorm();
  // g . (R(q) d_perp) = alpha cos q + beta sin q, so V = -m rho cos(q - q_eq).
  const double alpha = gravity.dot(d_perp), beta = gravity.dot(a.cross(d_perp));
  const double rho = std::hypot(alpha, beta);
  if (rho == 0 || I_axis <= 0) return {};
  ExactPendulum p;
  p.q_eq = std::atan2(beta, alpha);
  p.omega = std::sqrt(body.mass * rho / I_axis);
  p.phi0 = std::remainder(scene.q0[0] - p.q_eq, 2 * M_PI);
  if (std::abs(p.phi0) >= M_PI - 1e-9) return {};  // released upside down: no oscillation
  p.q_eq = scene.q0[0] - p.phi0;  // the equilibrium of the turn the pendulum starts in
  return p;
}

}  // namespace unfurl::studies
