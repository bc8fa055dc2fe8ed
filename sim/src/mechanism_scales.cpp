#include "unfurl/sim/mechanism_scales.hpp"

#include "unfurl/sim/elements/joint_driver.hpp"

#include <algorithm>
#include <cmath>

namespace unfurl::sim {

double mechanism_length(const Model& model) {
  double sum = 0, mass = 0;
  for (int i = 0; i < model.size(); ++i) {
    const Body& b = model.bodies[i];
    sum += 0.5 * b.inertia_com.trace() + b.mass * (b.com - model.joints[i].child_point).squaredNorm();
    mass += b.mass;
  }
  return mass > 0 && sum > 0 ? std::sqrt(sum / mass) : 1.0;
}

MechanismScales mechanism_scales(const Scene& scene, Sweep& sweep) {
  const Model& model = scene.model;
  MechanismScales s;
  s.length = mechanism_length(model);
  sweep.set_configuration(scene.q0.data());
  s.inertia.assign(model.nv, 0.0);
  for (int i = 0; i < model.size(); ++i)
    for (int r = 0; r < model.joints[i].dof(); ++r)
      s.inertia[(model.first_velocity[i] + r).value] = sweep.articulated_inertia(i, r);
  for (int c = 0; c < model.nv; ++c)
    if (model.joint_of_velocity[c] < 0) s.inertia[c] = 1;  // an elastic coordinate's modal mass
  // The joints' stiffness with every latch engaged, as they will be.
  std::vector<double> stiffness(model.nv, 0.0), damping(model.nv, 0.0);
  const std::vector<Pose> no_poses;
  const std::vector<Vec6> no_velocities;
  for (const auto& e : scene.elements)
    e->add_joint_stiffness(ElementState{model, Positions(scene.q0.data()), Rates(scene.dq0.data()), no_poses,
                                        no_velocities, Vec6::Zero(), true, nullptr},
                           RatesOut(stiffness.data()), RatesOut(damping.data()));
  double rate = 0;
  for (int c = 0; c < model.nv; ++c) {
    const bool linear = model.velocity_unit(c) == "m/s";
    if (s.inertia[c] > 0) rate = std::max(rate, std::sqrt(stiffness[c] / s.inertia[c]));
    rate = std::max(rate, std::abs(scene.dq0[c]) / (linear ? s.length : 1.0));
  }
  // What the drivers make it do.
  for (const JointDriver* d : scene.elements_of<JointDriver>())
    rate = std::max(rate, d->peak_rate() / (model.joints[d->joint].type == JointType::prismatic ? s.length : 1.0));
  rate = std::max(rate, std::sqrt(scene.gravity().norm() / s.length));
  // Nothing moves it by itself: one turn over the run.
  s.rate = rate > 0 ? rate : 2 * M_PI / scene.run.t_end;
  return s;
}

}  // namespace unfurl::sim
