// A driver on one joint: the joint's coordinate follows a prescribed
// function of time from its initial value, as a motor under position
// control holds it, or as the prescribed spin-up of Simo and Vu-Quoc's
// beam. The sweep takes the joint's rate and acceleration from the driver
// instead of from its momentum (sweep.hpp: the joint passes its whole
// articulated inertia to its parent), so the motion is exact, not a stiff
// servo's. What it takes to drive the joint is reported like a reaction,
// from the accelerations: the torque (a slider's force) along the joint
// beyond what the joint's other elements apply, in loads.csv as
// drive_torque.<joint>; the work it puts in counts in the energy balance.
//
// Profiles, from `start` over `duration`, s = (t - start) / duration in
// [0, 1]:
// - move: by `amount` (rad; m on a slider) with a cycloidal motion whose
//   rate and acceleration are zero at both ends, then held:
//     x = amount (s - sin(2 pi s) / (2 pi))
// - spin_up: the rate rises to `amount` (rad/s; m/s) along the same
//   cycloid and then holds:
//     x' = amount (s - sin(2 pi s) / (2 pi))
//   Simo and Vu-Quoc's spin-up is amount 6 rad/s over 15 s, after which
//   x = 6 t - 45.
#pragma once

#include <cmath>
#include <optional>
#include <string>

#include "unfurl/sim/elements/joint_element.hpp"

namespace unfurl::sim {

class JointDriver : public JointElement {
 public:
  using JointElement::JointElement;

  enum class Profile { move, spin_up };
  Profile profile = Profile::move;
  double amount = 0;    // the move (rad, m) or the final rate (rad/s, m/s)
  double duration = 1;  // s
  double start = 0;     // s

  // The displacement from the initial position, its rate and acceleration.
  struct Motion {
    double x = 0, rate = 0, acceleration = 0;
  };
  Motion at(double t) const;
  // The largest |rate| it reaches: 2 amount / duration for a move, amount
  // for a spin-up.
  double peak_rate() const { return profile == Profile::move ? 2 * std::abs(amount) / duration : std::abs(amount); }

  std::string kind() const override { return "driver"; }
  std::string list() const override { return "drivers"; }
  // The sweep moves the joint; the driver applies nothing of its own.
  void add_forces(const ElementState&, ElementForces&) const override {}
  std::shared_ptr<ForceElement> scaled(double L, double M, const Model& model) const override;
  // drive_torque: filled from the accelerations (Dynamics::loads).
  std::vector<LoadColumn> load_columns(const Model& model) const override;
  std::vector<ElementPeak> peaks() const override { return {{"peak_drive_torque"}}; }
  void validate(const Scene& scene, const std::string& field) const override;
  std::vector<ElementParameter> parameters(const Model& model) const override;
  std::string note() const override;
};

const char* driver_profile_name(JointDriver::Profile profile);
std::optional<JointDriver::Profile> parse_driver_profile(const std::string& name);

}  // namespace unfurl::sim
