#include "unfurl/sim/torque_margin.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "unfurl/sim/dynamics.hpp"
#include "unfurl/sim/elements/all.hpp"
#include "unfurl/sim/kinematics.hpp"

namespace unfurl::sim {

namespace {

constexpr int kQuasiStaticPoints = 101;

// The elements whose generalized forces count as harness torques on any
// driven joint: all but the joint elements (springs, dampers, friction,
// stops, latches: each acts on its own joint) and joint compliance.
std::vector<std::size_t> harness_elements(const Scene& scene) {
  std::vector<std::size_t> harness;
  for (std::size_t k = 0; k < scene.elements.size(); ++k) {
    const ForceElement& e = *scene.elements[k];
    if (!dynamic_cast<const Latch*>(&e) && !dynamic_cast<const JointElement*>(&e) &&
        !dynamic_cast<const JointCompliance*>(&e))
      harness.push_back(k);
  }
  return harness;
}

// What acts on one driven joint, and how to weigh it.
class JointMargin {
 public:
  JointMargin(const Scene& scene, const MechanismScales& scales, int joint, double direction,
              const TorqueMarginFactors& f)
      : model_(scene.model), joint_(joint), s_(direction), f_(f) {
    const std::size_t c = model_.velocity_of(joint).value;
    inertia_ = scales.inertia.size() > c ? scales.inertia[c] : 0.0;
    for (const auto& e : scene.elements)
      if (const auto* own = dynamic_cast<const JointElement*>(e.get()); own && own->joint == joint_)
        own_.push_back(own);
  }

  // The torques at positions q and rates w (w = 0: at rest), `harness`
  // the generalized force each of harness_elements() puts on the joint
  // there.
  TorqueMarginPoint at(double t, const std::vector<double>& q, const std::vector<double>& w,
                       const Eigen::VectorXd& harness) const {
    TorqueMarginPoint p;
    p.t = t;
    p.q = q[model_.position_of(joint_).value];
    const double rate = w[model_.velocity_of(joint_).value];
    const double moving = s_ * rate;  // > 0 towards the latch
    for (const JointElement* e : own_) {
      if (const auto* spring = dynamic_cast<const JointSpring*>(e)) {
        const double elastic = s_ * spring->elastic_torque(p.q);
        (elastic > 0 ? p.drive : p.spring) += std::abs(elastic);
        if (moving > 0) p.damping += spring->damping * std::abs(rate);
      } else if (const auto* damper = dynamic_cast<const JointDamper*>(e)) {
        if (moving > 0) p.damping += damper->damping * std::abs(rate);
      } else if (const auto* friction = dynamic_cast<const JointFriction*>(e)) {
        p.friction += friction->coulomb + friction->viscous * std::abs(rate);
      } else if (const auto* stop = dynamic_cast<const JointStop*>(e)) {
        p.spring += std::max(0.0, -s_ * stop->torque(p.q, rate));
      } else if (const auto* limit = dynamic_cast<const JointLimit*>(e)) {
        p.spring += std::max(0.0, -s_ * limit->torque(p.q, rate));
      }  // a latch holds nothing before it engages
    }
    for (const double Q : harness) p.harness += std::max(0.0, -s_ * Q);
    p.inertia = f_.required_acceleration * inertia_;
    const double resisting = f_.spring * p.spring + f_.friction * p.friction + f_.damping * p.damping +
                             f_.harness * p.harness + f_.inertia * p.inertia;
    p.factor = resisting > 0 ? p.drive / resisting : std::numeric_limits<double>::infinity();
    return p;
  }

 private:
  const Model& model_;
  int joint_;
  double s_;
  const TorqueMarginFactors& f_;
  double inertia_ = 0;
  std::vector<const JointElement*> own_;  // the elements on joint_, in the scene's order
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
  std::vector<bool> sprung(scene.model.joints.size(), false);
  for (const auto& e : scene.elements)
    if (const auto* s = dynamic_cast<const JointSpring*>(e.get())) sprung[s->joint] = true;
  std::vector<int> joints;
  for (const Latch* latch : scene.latches()) {
    const int j = latch->joint;
    if (sprung[j] && std::find(joints.begin(), joints.end(), j) == joints.end()) joints.push_back(j);
  }
  return joints;
}

// Each driven joint's margin at every sample before its latch engages (the
// samples' rates and harness forces found once for all joints), then at
// kQuasiStaticPoints angles at rest.
std::vector<JointTorqueMargin> torque_margins(const Scene& scene, const Trajectory& run,
                                              const std::atomic<bool>* cancel) {
  const auto cancelled = [cancel] { return cancel && cancel->load(std::memory_order_relaxed); };
  const TorqueMarginFactors& factors = scene.torque_margin;
  std::vector<JointTorqueMargin> out;
  // Checked before the model is built: on a large array that alone takes
  // longer than an interrupt may wait.
  if (run.empty() || cancelled()) return out;
  Sweep sweep(scene.model);
  const MechanismScales scales = mechanism_scales(scene, sweep);
  // Only harness forces need the dynamics: building it calibrates the
  // regulator again, and placing the whole model for each driven joint at
  // each angle made the margins O(N^2) on arrays that have none.
  const std::vector<std::size_t> harness = harness_elements(scene);
  std::optional<Dynamics> dynamics;
  if (!harness.empty()) dynamics.emplace(scene);
  const auto harness_forces = [&](const std::vector<int>& coordinates, const double* q, const double* w) {
    return dynamics ? dynamics->element_joint_forces(harness, coordinates, q, w)
                    : Eigen::MatrixXd(0, static_cast<Eigen::Index>(coordinates.size()));
  };
  const Model& model = scene.model;
  const std::vector<const Latch*> latches = scene.latches();
  struct Travel {
    int c, rate;  // the joint's position and velocity coordinates
    double start, end, s, latched_at;
    JointMargin margin;
  };
  std::vector<Travel> travels;
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
    travels.push_back(
        {c, model.velocity_of(j).value, start, end, s, latched_at, JointMargin(scene, scales, j, s, factors)});
    out.emplace_back();
    out.back().joint = model.joints[j].name;
  }
  std::vector<int> rates;
  for (const Travel& x : travels) rates.push_back(x.rate);
  std::vector<double> w(model.nv);
  for (const Sample& sample : run.samples) {
    if (cancelled()) return out;
    if (std::none_of(travels.begin(), travels.end(), [&](const Travel& x) { return sample.t < x.latched_at; })) break;
    const std::vector<double> q(sample.y.begin(), sample.y.begin() + model.nq);
    rates_from_position_rates(model, q.data(), sample.q_dot.data(), w.data());
    const Eigen::MatrixXd Q = harness_forces(rates, q.data(), w.data());
    for (std::size_t i = 0; i < travels.size(); ++i)
      if (sample.t < travels[i].latched_at) out[i].run.push_back(travels[i].margin.at(sample.t, q, w, Q.col(i)));
  }
  const std::vector<double> at_rest(model.nv, 0.0);
  for (std::size_t i = 0; i < travels.size(); ++i) {
    const Travel& x = travels[i];
    if (cancelled()) return out;
    for (int k = 0; k < kQuasiStaticPoints; ++k) {
      const double target = x.start + (x.end - x.start) * k / (kQuasiStaticPoints - 1);
      const std::vector<double> q = state_at_angle(run, x.c, x.s, x.start, target);
      const Eigen::MatrixXd Q = harness_forces({x.rate}, q.data(), at_rest.data());
      out[i].quasi_static.push_back(x.margin.at(std::nan(""), q, at_rest, Q.col(0)));
    }
    out[i].worst_run = worst_of(out[i].run);
    out[i].worst_quasi_static = worst_of(out[i].quasi_static);
  }
  return out;
}

}  // namespace unfurl::sim
