#include "unfurl/sim/elements/bushing.hpp"

#include "unfurl/sim/elements/point_frame.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdio>

#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/scene_validation.hpp"

namespace unfurl::sim {

namespace {

constexpr const char* kAxes[] = {"x", "y", "z"};
constexpr double kLargestTilt = 80.0 * M_PI / 180.0;  // E is singular at 90 degrees

// The point's velocity (base frame), in the bushing's own order of
// operations (the axes formed, then applied), which keeps its outputs bit
// for bit.
Vec3 point_rate(const PointFrame& F) {
  if (F.body == kBase) return F.velocity();
  const Mat3 to_base = F.to_base();
  return to_base * (F.v.head<3>() + F.v.tail<3>().cross(F.r));
}

bool symmetric(const Mat6& A) { return (A - A.transpose()).norm() <= 1e-12 * A.norm(); }

bool positive_semidefinite(const Mat6& A) {
  const Eigen::SelfAdjointEigenSolver<Mat6> eig(0.5 * (A + A.transpose()), Eigen::EigenvaluesOnly);
  return eig.eigenvalues().minCoeff() >= -1e-12 * A.norm();
}

}  // namespace

Mat3 BushingFrame::axes() const {
  if (rotation_deg == 0) return Mat3::Identity();
  return Eigen::AngleAxisd(rotation_deg * M_PI / 180.0, rotation_axis).toRotationMatrix();
}

Vec3 bryant_angles(const Mat3& R) {
  return {std::atan2(-R(1, 2), R(2, 2)), std::atan2(R(0, 2), std::hypot(R(1, 2), R(2, 2))),
          std::atan2(-R(0, 1), R(0, 0))};
}

Mat3 bryant_rate_map(const Vec3& phi) {
  const double ca = std::cos(phi[0]), sa = std::sin(phi[0]), cb = std::cos(phi[1]), sb = std::sin(phi[1]);
  Mat3 E;
  E << 1, 0, sb,  //
      0, ca, -sa * cb,  //
      0, sa, ca * cb;
  return E;
}

BushingDeflection Bushing::deflection(const PointFrame& A, const PointFrame& B) const {
  BushingDeflection d;
  d.frame_a = A.to_base() * a.axes();
  d.origin_a = A.position();
  d.origin_b = B.position();
  const Mat3 Ra_T = d.frame_a.transpose();
  const Vec3 delta = Ra_T * (d.origin_b - d.origin_a);
  const Vec3 phi = bryant_angles(Ra_T * B.to_base() * b.axes());
  d.E = bryant_rate_map(phi);
  const Vec3 omega_a = Ra_T * A.angular_velocity();
  d.x << delta, phi;
  d.x_dot.head<3>() = Ra_T * (point_rate(B) - point_rate(A)) - omega_a.cross(delta);
  d.x_dot.tail<3>() = d.E.inverse() * (Ra_T * B.angular_velocity() - omega_a);
  return d;
}

BushingDeflection Bushing::deflection(const ElementState& s) const {
  return deflection(point_frame(s, a.body, a.point), point_frame(s, b.body, b.point));
}

Vec6 Bushing::wrench_on_b(const BushingDeflection& d) const {
  const Vec6 g = stiffness * d.x + damping * d.x_dot - preload;
  Vec6 w;
  w << -g.head<3>(), -(d.E.transpose().inverse() * g.tail<3>());
  return w;
}

void Bushing::add_forces(const ElementState& s, ElementForces& out) const {
  const PointFrame A = point_frame(s, a.body, a.point), B = point_frame(s, b.body, b.point);
  const BushingDeflection d = deflection(A, B);
  const Vec6 w = wrench_on_b(d);
  const Vec3 f_b = d.frame_a * w.head<3>(), m_b = d.frame_a * w.tail<3>();
  add_point_wrench(s, B, f_b, m_b, out);
  // On a: the opposite force, and the opposite moment about b's origin
  // moved to a's: -m_b - (x_b - x_a) x f_b.
  add_point_wrench(s, A, -f_b, -m_b - (d.origin_b - d.origin_a).cross(f_b), out);
}

double Bushing::potential_energy(const ElementState& s) const {
  const Vec6 x = deflection(s).x;
  return 0.5 * x.dot(stiffness * x) - preload.dot(x);
}

double Bushing::dissipated_power(const ElementState& s) const {
  const Vec6 x_dot = deflection(s).x_dot;
  return x_dot.dot(damping * x_dot);
}

std::vector<LoadColumn> Bushing::load_columns(const Model&) const {
  std::vector<LoadColumn> columns;
  for (int a = 0; a < 3; ++a)
    columns.push_back({"bushing_force." + name + "." + kAxes[a], "N", "on body b in frame a", -1});
  for (int a = 0; a < 3; ++a)
    columns.push_back({"bushing_moment." + name + "." + kAxes[a], "N m", "on body b in frame a about b's origin", -1});
  columns.push_back({"bushing_energy." + name, "J", "", -1});
  return columns;
}

void Bushing::load_values(const ElementState& s, double* values) const {
  const BushingDeflection d = deflection(s);
  const Vec6 w = wrench_on_b(d);
  for (int k = 0; k < 6; ++k) values[k] = w[k];
  values[6] = 0.5 * d.x.dot(stiffness * d.x) - preload.dot(d.x);
}

std::vector<ElementParameter> Bushing::parameters(const Model& /*model*/) const {
  std::vector<ElementParameter> p;
  if (!stiffness.isDiagonal(0) || !damping.isDiagonal(0)) return p;  // the GUI edits the diagonal form
  for (int k = 0; k < 6; ++k) {
    const bool turn = k >= 3;
    const std::string axis = std::string(turn ? "r" : "") + kAxes[k % 3];
    p.push_back({"stiffness." + std::to_string(k), "stiffness " + axis + (turn ? " [N m/rad]" : " [N/m]"),
                 stiffness(k, k), 0.1 * std::max(stiffness(k, k), 1.0), 0, 1e15,
                 turn ? "rotational stiffness about frame a's axis" : "translational stiffness along frame a's axis"});
  }
  for (int k = 0; k < 6; ++k) {
    const bool turn = k >= 3;
    const std::string axis = std::string(turn ? "r" : "") + kAxes[k % 3];
    p.push_back({"damping." + std::to_string(k), "damping " + axis + (turn ? " [N m s/rad]" : " [N s/m]"),
                 damping(k, k), 0.1 * std::max(damping(k, k), 0.01), 0, 1e15,
                 turn ? "rotational damping about frame a's axis" : "translational damping along frame a's axis"});
  }
  return p;
}

void Bushing::validate(const Scene& scene, const std::string& field) const {
  if (!is_valid_name(name))
    throw SceneInvalid(
        field + ".name",
        "the name '" + name + "' has characters other than letters, digits, '_' and '-' (or is empty or over 64)");
  for (const Bushing* other : scene.elements_of<Bushing>()) {
    if (other == this) break;
    if (other->name == name) throw SceneInvalid(field + ".name", "a bushing named '" + name + "' already exists");
  }
  for (const int body : {a.body, b.body})
    if (body < kBase || body >= scene.model.size()) throw SceneInvalid(field, "no such body");
  if (a.body == b.body) throw SceneInvalid(field + ".body_b", "both frames are on one body: it would pull on itself");
  if (!stiffness.allFinite() || !symmetric(stiffness) || !positive_semidefinite(stiffness))
    throw SceneInvalid(field + ".stiffness",
                       "must be symmetric and positive semidefinite (a stiffness that stores energy, never gives it)");
  if (!damping.allFinite() || !symmetric(damping) || !positive_semidefinite(damping))
    throw SceneInvalid(field + ".damping", "must be symmetric and positive semidefinite (it may only dissipate)");
  if (!preload.allFinite()) throw SceneInvalid(field + ".preload", "must be finite");
  node_of_point(scene, a.body, a.point, field + ".point_a");
  node_of_point(scene, b.body, b.point, field + ".point_b");
  // At the initial state, at rest; a flexible body's node frames
  // undeformed (the body's own axes).
  std::vector<Pose> poses;
  body_poses(scene.model, scene.q0.data(), poses);
  const auto at_rest = [&](const BushingFrame& f) {
    PointFrame at;
    at.body = f.body;
    if (f.body != kBase) at.pose = poses[f.body];
    at.r = f.point;
    return at;
  };
  const double tilt = deflection(at_rest(a), at_rest(b)).x[4];
  if (std::abs(tilt) > kLargestTilt) {
    char degrees[32];
    std::snprintf(degrees, sizeof degrees, "%.1f", tilt * 180 / M_PI);
    throw SceneInvalid(field, std::string("frame b is tilted ") + degrees +
                                  " degrees about frame a's y axis at the initial state; the Bryant angles hold "
                                  "within +-80 (align the frames' x axes)");
  }
}

std::shared_ptr<ForceElement> Bushing::scaled(double L, double M, const Model&) const {
  auto s = std::make_shared<Bushing>(*this);
  s->a.point *= L;
  s->b.point *= L;
  // Work is M L^2: a component's force scales by M L^2 over its
  // coordinate's scale c (L along, 1 about), K_ij and C_ij by M L^2/(c_i c_j).
  Vec6 c;
  c << L, L, L, 1, 1, 1;
  for (int i = 0; i < 6; ++i) {
    s->preload[i] *= M * L * L / c[i];
    for (int j = 0; j < 6; ++j) {
      s->stiffness(i, j) *= M * L * L / (c[i] * c[j]);
      s->damping(i, j) *= M * L * L / (c[i] * c[j]);
    }
  }
  return s;
}

}  // namespace unfurl::sim
