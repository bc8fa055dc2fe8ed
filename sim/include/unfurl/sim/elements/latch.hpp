// Latches: a stop that catches a joint the first time it reaches its
// deployed position and from then on holds it with a stiff spring-damper.
// A latch never lets go. Whether it has engaged is the run's (LatchState),
// handed to the element as ElementState::engaged.
#pragma once

#include <vector>

#include "unfurl/sim/elements/joint_element.hpp"
#include "unfurl/sim/elements/push_only_stop.hpp"

namespace unfurl::sim {

class Latch : public JointElement {
 public:
  using JointElement::JointElement;

  double position = 0;   // the deployed angle (or length)
  double stiffness = 0;  // k_L
  double damping = 0;    // c_L
  // Backlash: the engaged latch lets the joint move freely within
  // position +- free_play / 2 and bites beyond, as a stop that pushes and
  // never pulls (the damping cannot hold the joint against the stop).
  double free_play = 0;

  // How far the joint is past the free play (signed; 0 inside it).
  double penetration(double q) const {
    const double e = q - position, half = 0.5 * free_play;
    return e > half ? e - half : e < -half ? e + half : 0.0;
  }
  double elastic_torque(double q) const { return -stiffness * penetration(q); }
  // tau_L = -k_L x - c_L dq once engaged, x = q - position without free
  // play, the penetration with it.
  double torque(double q, double dq) const {
    if (free_play == 0) return -stiffness * (q - position) - damping * dq;
    return push_only_torque(penetration(q), dq, stiffness, damping);
  }
  double energy(double q) const { return 0.5 * stiffness * penetration(q) * penetration(q); }

  std::string kind() const override { return "latch"; }
  std::string list() const override { return "latches"; }
  // Each of these acts only once the latch has engaged.
  void add_forces(const ElementState& s, ElementForces& out) const override;
  std::shared_ptr<ForceElement> scaled(double L, double M, const Model& model) const override;
  double potential_energy(const ElementState& s) const override;
  EnergyStore energy_store() const override { return EnergyStore::latches; }
  double dissipated_power(const ElementState& s) const override;
  bool dissipative() const override { return damping > 0; }
  void add_joint_stiffness(const ElementState& s, RatesOut stiffness, RatesOut damping) const override;
  std::vector<LoadColumn> load_columns(const Model& model) const override;  // latch_torque
  void load_values(const ElementState& s, double* values) const override;
  void validate(const Scene& scene, const std::string& field) const override;
  std::vector<ElementParameter> parameters(const Model& model) const override;
  std::string note() const override;
};

// The engagement state of a scene's latches along one run.
class LatchState {
 public:
  // `side` of each latch: the sign of q(0) - position, the side the joint
  // starts on; a latch whose joint starts at its position starts engaged.
  LatchState(const std::vector<const Latch*>& latches, const std::vector<double>& q0_of_latch);

  // The root function of latch l: s (q - position), crossing zero downwards
  // when the joint reaches the deployed position; +1 once engaged.
  double switching_value(int l, double q) const;
  // Its rate for a joint rate dq (0 once engaged).
  double switching_rate(int l, double dq) const { return engaged_[l] ? 0.0 : side_[l] * dq; }
  bool engaged(int l) const { return engaged_[l] != 0; }
  void engage(int l) { engaged_[l] = 1; }
  int size() const { return static_cast<int>(side_.size()); }
  int engaged_count() const;

 private:
  std::vector<double> side_;
  std::vector<double> position_;
  std::vector<char> engaged_;
};

}  // namespace unfurl::sim
