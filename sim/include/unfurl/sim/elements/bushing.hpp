// A bushing: a six-component spring-damper between a frame on one body and
// a frame on another (or the base), as MSC Adams' BUSHING and FIELD,
// Simscape's Bushing Joint and Chrono's ChLoadBodyBodyBushingGeneric. It
// makes a pin, a latch or a mount compliant, so the loads through a loop
// closed by it are determinate.
//
// Deflection x = (delta, phi), measured of frame b against frame a and given
// in frame a: delta the position of b's origin, phi = (alpha, beta, gamma)
// the x-y-z Bryant angles of b's orientation, R_ab = Rx(alpha) Ry(beta)
// Rz(gamma). Why Bryant angles and not the rotation vector: a bushing that
// stands for a pin turns through large angles about its axis (a pantograph's
// cross-link turns pi), and with x first the two bending angles stay the
// tilts of the pin whatever its turn; the rotation vector mixes them with
// the turn (their axes rotate by alpha/2 and scale by (alpha/2)/sin(alpha/2))
// and has no unique value at alpha = pi. The angles are smooth except at
// beta = +-pi/2 (a 90 degree tilt, far outside a bushing's range), and
// depend only on the two frames, not on the base's or the bodies' frames.
//
// Generalized force g = K x + C x' - preload (the preload is what the
// bushing pushes b with at zero deflection); stored energy 1/2 x'K x -
// preload . x, dissipated power x'.C.x'. Its wrench on b, in frame a, about
// b's origin: f_b = -g_delta, m_b = -E^-T g_phi, with E the map from
// Bryant-angle rates to relative angular velocity (omega = E phi'); on a, at
// a's origin: f_a = g_delta, m_a = delta x g_delta + E^-T g_phi. These are
// the exact gradient of the energy (the power balance closes to round-off)
// and they balance: sum of forces and moments zero.
#pragma once

#include <string>
#include <vector>

#include "unfurl/sim/force_element.hpp"

namespace unfurl::sim {

struct PointFrame;

// A bushing's deflection and its rate at one state, and the frames it is
// measured in.
struct BushingDeflection {
  Vec6 x = Vec6::Zero(), x_dot = Vec6::Zero();  // (delta, phi) and their rates
  Mat3 E = Mat3::Identity();                    // omega_rel = E phi', frame a
  Mat3 frame_a = Mat3::Identity();              // frame a's axes in the base frame (columns)
  Vec3 origin_a = Vec3::Zero(), origin_b = Vec3::Zero();  // base frame
};

// One of a bushing's two frames: its origin in its body's frame, and its
// axes turned from the body's by an angle about an axis (as written in the
// scene file, so it writes back exactly).
struct BushingFrame {
  int body = kBase;  // kBase: a frame fixed on the base
  Vec3 point = Vec3::Zero();
  Vec3 rotation_axis = Vec3::UnitX();
  double rotation_deg = 0;
  // Its axes (the columns) in its body's frame.
  Mat3 axes() const;
};

class Bushing : public ForceElement {
 public:
  std::string name;
  BushingFrame a, b;
  Mat6 stiffness = Mat6::Zero();  // rows and columns (x, y, z, rx, ry, rz)
  Mat6 damping = Mat6::Zero();
  Vec6 preload = Vec6::Zero();  // force (N) and moment (N m) on b at zero deflection, frame a

  // Between its two frames at a state, or between two given point frames.
  BushingDeflection deflection(const ElementState& s) const;
  BushingDeflection deflection(const PointFrame& A, const PointFrame& B) const;
  // The wrench on b: force (frame a) and moment (frame a, about b's origin).
  Vec6 wrench_on_b(const BushingDeflection& d) const;

  std::string kind() const override { return "bushing"; }
  std::string list() const override { return "bushings"; }
  std::string handle(const Model&) const override { return name; }
  void add_forces(const ElementState& s, ElementForces& out) const override;
  std::shared_ptr<ForceElement> scaled(double L, double M, const Model& model) const override;
  bool needs_poses() const override { return true; }
  std::optional<std::vector<int>> bodies() const override { return bodies_off_base({a.body, b.body}); }
  double potential_energy(const ElementState& s) const override;
  double dissipated_power(const ElementState& s) const override;
  bool dissipative() const override { return !damping.isZero(0); }
  // force.NAME.x..z, moment.NAME.x..z on b (frame a), energy.NAME.
  std::vector<LoadColumn> load_columns(const Model& model) const override;
  void load_values(const ElementState& s, double* values) const override;
  // peak_bushing_force and peak_bushing_moment: |f| and |m| on b.
  std::vector<ElementPeak> peaks() const override {
    return {{"peak_bushing_force", 0, 3}, {"peak_bushing_moment", 3, 3}};
  }
  // A valid, unique name; two distinct bodies; K and C symmetric and
  // positive semidefinite; the initial tilt inside +-80 degrees.
  void validate(const Scene& scene, const std::string& field) const override;
  // The diagonal of K and C.
  std::vector<ElementParameter> parameters(const Model& model) const override;
  std::vector<ElementLink> links() const override {
    return {{a.body, b.body, a.point, b.point, ElementLink::Style::bushing, a.axes().col(0)}};
  }
};

// The x-y-z Bryant angles of a rotation R = Rx(alpha) Ry(beta) Rz(gamma).
Vec3 bryant_angles(const Mat3& R);
// E(phi): omega = E phi' for R(phi) = Rx Ry Rz, omega in the first frame.
Mat3 bryant_rate_map(const Vec3& phi);

}  // namespace unfurl::sim
