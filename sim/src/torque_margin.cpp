#include "unfurl/sim/torque_margin.hpp"

#include <algorithm>
#include <cmath>

#include "unfurl/sim/dynamics.hpp"
#include "unfurl/sim/elements/all.hpp"
#include "unfurl/sim/kinematics.hpp"

namespace unfurl::sim {

namespace {

constexpr int kQuasiStaticPoints = 101;

// What acts on one driven joint, and how to weigh it.
class JointMargin {
 public:
  JointMargin(Dynamics& dynamics, int joint, double direction, const TorqueMarginFactors& f)
      : dynamics_(dynamics), model_(dynamics.model()), joint_(joint), s_(direction), f_(f) {
    const std::size_t c = model_.velocity_of(joint).value;
    inertia_ = dynamics.scales().inertia.size() > c ? dynamics.scales().inertia[c] : 0.0;
  }

  // The torques at positions q and rates w (w = 0: at rest).
  TorqueMarginPoint at(double t, const std::vector<double>& q, const std::vector<double>& w) {
    TorqueMarginPoint p;
    p.t = t;
    p.q = q[model_.position_of(joint_).value];
    const double rate = w[model_.velocity_of(joint_).value];
    const double moving = s_ * rate;  // > 0 towards the latch
    const Scene& scene = dynamics_.scene();
    for (std::size_t k = 0; k < scene.elements.size(); ++k) {
      const ForceElement& e = *scene.elements[k];
      if (const auto* spring = dynamic_cast<const JointSpring*>(&e)) {
        if (spring->joint != joint_) continue;
        const double elastic = s_ * spring->elastic_torque(p.q);
        (elastic > 0 ? p.drive : p.spring) += std::abs(elastic);
        if (moving > 0) p.damping += spring->damping * std::abs(rate);
      } else if (const auto* damper = dynamic_cast<const JointDamper*>(&e)) {
        if (damper->joint == joint_ && moving > 0) p.damping += damper->damping * std::abs(rate);
      } else if (const auto* friction = dynamic_cast<const JointFriction*>(&e)) {
        if (friction->joint == joint_) p.friction += friction->coulomb + friction->viscous * std::abs(rate);
      } else if (const auto* stop = dynamic_cast<const JointStop*>(&e)) {
        if (stop->joint == joint_) p.spring += std::max(0.0, -s_ * stop->torque(p.q, rate));
      } else if (dynamic_cast<const Latch*>(&e) || dynamic_cast<const JointElement*>(&e) ||
                 dynamic_cast<const JointCompliance*>(&e)) {
        continue;  // a latch holds nothing before it engages; others act on other joints
      } else {
        const Eigen::VectorXd Q = dynamics_.element_generalized_forces(k, q.data(), w.data());
        p.harness += std::max(0.0, -s_ * Q[model_.velocity_of(joint_).value]);
      }
    }
    p.inertia = f_.required_acceleration * inertia_;
    const double resisting = f_.spring * p.spring + f_.friction * p.friction + f_.damping * p.damping +
                             f_.harness * p.harness + f_.inertia * p.inertia;
    p.factor = resisting > 0 ? p.drive / resisting : std::numeric_limits<double>::infinity();
    return p;
  }

 private:
  Dynamics& dynamics_;
  const Model& model_;
  int joint_;
  double s_;
  const TorqueMarginFactors& f_;
  double inertia_ = 0;
};

int worst_of(const std::vector<TorqueMarginPoint>& points) {
  int worst = -1;
  for (int k = 0; k < static_cast<int>(points.size()); ++k)
    if (worst < 0 || points[k].factor < points[worst].factor) worst = k;
  return worst;
}

// The run's state where the joint's coordinate c first reached `target`
// moving in direction s (interpolated between samples), or the last
// sample's with c set to it.
std::vector<double> state_at_angle(const Trajectory& run, int c, double s, double start, double target) {
  const auto& samples = run.samples;
  for (std::size_t k = 1; k < samples.size(); ++k) {
    const double a = samples[k - 1].y[c], b = samples[k].y[c];
    if (s * (b - target) >= 0 && s * (a - target) < 0) {
      const double u = (target - a) / (b - a);
      std::vector<double> q(run.layout.nq);
      for (int i = 0; i < run.layout.nq; ++i) q[i] = samples[k - 1].y[i] + u * (samples[k].y[i] - samples[k - 1].y[i]);
      return q;
    }
  }
  const Sample& from = s * (target - start) <= 0 || samples.empty() ? samples.front() : samples.back();
  std::vector<double> q(from.y.begin(), from.y.begin() + run.layout.nq);
  q[c] = target;
  return q;
}

}  // namespace

double JointTorqueMargin::worst() const {
  double m = std::numeric_limits<double>::infinity();
  if (worst_run >= 0) m = std::min(m, run[worst_run].factor);
  if (worst_quasi_static >= 0) m = std::min(m, quasi_static[worst_quasi_static].factor);
  return m;
}

std::vector<int> driven_joints(const Scene& scene) {
  std::vector<int> joints;
  for (const Latch* latch : scene.latches()) {
    const int j = latch->joint;
    const bool sprung = std::any_of(scene.elements.begin(), scene.elements.end(), [&](const auto& e) {
      const auto* s = dynamic_cast<const JointSpring*>(e.get());
      return s && s->joint == j;
    });
    if (sprung && std::find(joints.begin(), joints.end(), j) == joints.end()) joints.push_back(j);
  }
  return joints;
}

std::vector<JointTorqueMargin> torque_margins(const Scene& scene, const Trajectory& run) {
  const TorqueMarginFactors& factors = scene.torque_margin;
  std::vector<JointTorqueMargin> out;
  if (run.empty()) return out;
  Dynamics dynamics(scene);
  const Model& model = scene.model;
  const std::vector<const Latch*> latches = scene.latches();
  for (const int j : driven_joints(scene)) {
    // Its first latch: where its travel ends.
    int l = 0;
    while (latches[l]->joint != j) ++l;
    const int c = model.position_of(j).value;
    const double start = scene.q0[c], end = latches[l]->position, s = end > start ? 1.0 : -1.0;
    if (end == start) continue;
    double latched_at = std::numeric_limits<double>::infinity();
    for (const LatchEvent& e : run.events)
      if (e.latch == l) latched_at = std::min(latched_at, e.t);
    JointMargin margin(dynamics, j, s, factors);
    JointTorqueMargin m;
    m.joint = model.joints[j].name;
    std::vector<double> w(model.nv);
    for (const Sample& sample : run.samples) {
      if (sample.t >= latched_at) break;
      const std::vector<double> q(sample.y.begin(), sample.y.begin() + model.nq);
      rates_from_position_rates(model, q.data(), sample.q_dot.data(), w.data());
      m.run.push_back(margin.at(sample.t, q, w));
    }
    const std::vector<double> at_rest(model.nv, 0.0);
    for (int k = 0; k < kQuasiStaticPoints; ++k) {
      const double target = start + (end - start) * k / (kQuasiStaticPoints - 1);
      m.quasi_static.push_back(margin.at(std::nan(""), state_at_angle(run, c, s, start, target), at_rest));
    }
    m.worst_run = worst_of(m.run);
    m.worst_quasi_static = worst_of(m.quasi_static);
    out.push_back(std::move(m));
  }
  return out;
}

}  // namespace unfurl::sim
