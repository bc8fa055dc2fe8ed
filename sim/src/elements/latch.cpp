#include "unfurl/sim/elements/latch.hpp"

#include <cstdio>

#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/scene_validation.hpp"

namespace unfurl::sim {

void Latch::add_forces(const ElementState& s, ElementForces& out) const {
  if (!s.engaged) return;
  out.Q[w_index(s.model)] += torque(s.q[q_index(s.model)], s.w[w_index(s.model)]);
}

double Latch::potential_energy(const ElementState& s) const { return s.engaged ? energy(s.q[q_index(s.model)]) : 0.0; }

double Latch::dissipated_power(const ElementState& s) const {
  if (!s.engaged) return 0.0;
  const double q = s.q[q_index(s.model)], w = s.w[w_index(s.model)];
  return -(torque(q, w) - elastic_torque(q)) * w;
}

void Latch::add_joint_stiffness(const ElementState& s, RatesOut k, RatesOut c) const {
  if (!s.engaged) return;
  k[w_index(s.model)] += stiffness;
  c[w_index(s.model)] += damping;
}

std::vector<LoadColumn> Latch::load_columns(const Model& model) const { return {column(model, "latch_torque")}; }

void Latch::load_values(const ElementState& s, double* values) const {
  values[0] = s.engaged ? torque(s.q[q_index(s.model)], s.w[w_index(s.model)]) : 0.0;
}

std::string Latch::note() const {
  char text[64];
  std::snprintf(text, sizeof text, "catches at %.4g", position);
  return text;
}

std::vector<ElementParameter> Latch::parameters(const Model& model) const {
  return {{"stiffness", "stiffness [" + stiffness_unit(model) + "]", stiffness, 10, 1e-9, 1e12,
           "k_L of the engaged latch: tau = -k_L (q - position) - c_L dq"},
          {"damping", "damping [" + damping_unit(model) + "]", damping, 0.1, 0, 1e12, "c_L of the engaged latch"},
          {"free_play", "free play [" + angle_unit(model, joint) + "]", free_play, 1e-4, 0, 1,
           "backlash: the latch bites beyond position +- free play / 2"}};
}

LatchState::LatchState(const std::vector<const Latch*>& latches, const std::vector<double>& q0_of_latch)
    : side_(latches.size()), position_(latches.size()), engaged_(latches.size(), 0) {
  for (std::size_t l = 0; l < latches.size(); ++l) {
    const double offset = q0_of_latch[l] - latches[l]->position;
    side_[l] = offset >= 0 ? 1.0 : -1.0;
    position_[l] = latches[l]->position;
    engaged_[l] = offset == 0 ? 1 : 0;
  }
}

double LatchState::switching_value(int l, double q) const { return engaged_[l] ? 1.0 : side_[l] * (q - position_[l]); }

int LatchState::engaged_count() const {
  int n = 0;
  for (char e : engaged_) n += e;
  return n;
}

void Latch::validate(const Scene& scene, const std::string& field) const {
  JointElement::validate(scene, field);
  check_positive(stiffness, field + ".stiffness");
  check_non_negative(damping, field + ".damping");
  check_non_negative(free_play, field + ".free_play");
  for (const Latch* other : scene.latches()) {
    if (other == this) break;
    if (other->joint == joint) throw SceneInvalid(field + ".joint", "this joint already has a latch");
  }
}

std::shared_ptr<ForceElement> Latch::scaled(double L, double M, const Model& model) const {
  auto l = std::make_shared<Latch>(*this);
  l->position *= angle_scale(model, L);
  l->free_play *= angle_scale(model, L);
  l->stiffness *= stiffness_scale(model, L, M);
  l->damping *= stiffness_scale(model, L, M);
  return l;
}

}  // namespace unfurl::sim
