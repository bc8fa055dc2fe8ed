#include "unfurl/sim/dynamics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "newton_preconditioner.hpp"

namespace unfurl {

namespace {

std::vector<double> latch_start_positions(const Scene& scene) {
  std::vector<double> q;
  for (const Latch& latch : scene.latches) q.push_back(scene.q0[scene.model.coordinate[latch.joint]]);
  return q;
}

}  // namespace

Dynamics::Dynamics(const Scene& scene)
    : scene_(scene),
      sweep_(scene_.model),
      latch_state_(scene_.latches, latch_start_positions(scene_)),
      loads_need_poses_(loads_need_poses(scene_.model, scene_.loads) || !scene_.point_springs.empty()),
      phi_(scene_.model.size()),
      v_(scene_.model.size()),
      mu_(scene_.model.size()),
      F_(scene_.model.size()),
      poses_(scene_.model.size()),
      bias_(scene_.model.size()),
      a_(scene_.model.size()),
      Q_(scene_.model.nv),
      Q_joint_(scene_.model.nv),
      ddq_(scene_.model.nv),
      w_(scene_.model.nv) {
  layout_.nq = scene_.model.nq;
  layout_.nv = scene_.model.nv;
  if (!scene_.loops.empty()) {
    auto components = active_loop_components(scene_.model, scene_.loops, scene_.q0, sweep_);
    layout_.m = static_cast<int>(components.size());
    regulator_.emplace(scene_.model, scene_.loops, std::move(components), scene_.regulator);
    sweep_.set_configuration(scene_.q0.data());
    regulator_->calibrate(sweep_);
    lambda_.resize(layout_.m);
    g_.resize(layout_.m);
    g_dot_.resize(layout_.m);
    d_.resize(layout_.m);
  }
  ydot_.resize(layout_.size());
  jv_y_.resize(layout_.size());
  jv_f_.resize(layout_.size());
  jv_y1_.resize(layout_.size());
}

Dynamics::~Dynamics() = default;

NewtonPreconditioner& Dynamics::preconditioner() {
  if (!preconditioner_) preconditioner_ = std::make_unique<NewtonPreconditioner>(*this);
  return *preconditioner_;
}

std::vector<double> Dynamics::initial_state() {
  const Model& model = scene_.model;
  std::vector<double> y(size(), 0.0);
  std::copy(scene_.q0.begin(), scene_.q0.end(), y.begin() + layout_.q());
  if (!scene_.p0.empty()) {
    std::copy(scene_.p0.begin(), scene_.p0.end(), y.begin() + layout_.p());
  } else {
    // p = A^T mu with mu the subtree momenta of the given joint rates.
    sweep_.set_configuration(scene_.q0.data());
    for (int i = 0; i < model.size(); ++i) {
      const int k = model.parent[i];
      v_[i] = sweep_.placement(i).transform_velocity(k == kBase ? model.base_velocity : v_[k]);
      for (int r = 0; r < model.joints[i].dof(); ++r)
        v_[i] += sweep_.motion_axes(i).col(r) * scene_.dq0[model.velocity[i] + r];
      F_[i] = model.bodies[i].spatial_mass() * v_[i];
    }
    sweep_.generalized_forces(F_, y.data() + layout_.p());
  }
  return y;
}

void Dynamics::joint_torques(const double* q, const double* dq, double* Q) const {
  const Model& model = scene_.model;
  for (const JointSpring& s : scene_.springs) {
    const int c = model.coordinate[s.joint];
    Q[c] += s.torque(q[c], dq[c]);
  }
  for (const JointFriction& f : scene_.friction) Q[model.coordinate[f.joint]] += f.torque(dq[model.coordinate[f.joint]]);
  for (int l = 0; l < latch_count(); ++l) {
    if (!latch_state_.engaged(l)) continue;
    const Latch& latch = scene_.latches[l];
    const int c = model.coordinate[latch.joint];
    Q[c] += latch.torque(q[c], dq[c]);
  }
}

void Dynamics::add_point_springs() {
  for (const PointSpring& s : scene_.point_springs) {
    const PointSpringGeometry g = point_spring_geometry(s, poses_, v_, scene_.model.base_velocity);
    add_point_spring_force(s, g, s.tension(g.length, g.rate), poses_, F_);
  }
}

double Dynamics::dissipation(const double* q, const double* dq) {
  const Model& model = scene_.model;
  double P = 0;
  if (!scene_.point_springs.empty()) {
    // The rate of a length is the same seen from the base at rest.
    sweep_.set_configuration(q);
    sweep_.poses(poses_);
    rates_from_position_rates(model, q, dq, w_.data());
    sweep_.velocities_from_rates(w_.data(), v_);
    for (const PointSpring& s : scene_.point_springs) {
      const PointSpringGeometry g = point_spring_geometry(s, poses_, v_, Vec6::Zero());
      P += (s.tension(g.length, g.rate) - s.elastic(g.length)) * g.rate;
    }
  }
  for (const JointSpring& s : scene_.springs) {
    const double w = dq[model.coordinate[s.joint]];
    P += s.damping * w * w;
  }
  for (const JointFriction& f : scene_.friction) P += f.dissipation(dq[model.coordinate[f.joint]]);
  for (int l = 0; l < latch_count(); ++l) {
    if (!latch_state_.engaged(l)) continue;
    const Latch& latch = scene_.latches[l];
    const int c = model.coordinate[latch.joint];
    P -= (latch.torque(q[c], dq[c]) - latch.elastic_torque(q[c])) * dq[c];
  }
  return P;
}

bool Dynamics::rhs(double t, const double* y, double* ydot) {
  ++rhs_calls_;
  return evaluate(t, y, ydot);
}

bool Dynamics::evaluate(double, const double* y, double* ydot) {
  const Model& model = scene_.model;
  const StateLayout& L = layout_;
  const double* q = y + L.q();
  const double* p = y + L.p();
  double* dq = ydot + L.q();
  double* dp = ydot + L.p();

  sweep_.set_configuration(q);
  sweep_.bias(p, phi_);
  sweep_.velocities(p, phi_, model.base_velocity, w_.data(), v_);
  sweep_.momenta(v_, phi_, mu_);
  position_rates(model, q, w_.data(), dq);
  const double* w = w_.data();

  for (Vec6& f : F_) f.setZero();
  if (loads_need_poses_ || regulator_) sweep_.poses(poses_);
  add_body_loads(model, scene_.loads, poses_, F_);
  add_point_springs();
  std::fill(Q_joint_.begin(), Q_joint_.end(), 0.0);
  joint_torques(q, w, Q_joint_.data());
  if (regulator_) {
    regulator_->gap(poses_, g_.data());
    regulator_->residual_rate(v_, g_dot_.data());
    if (regulator_->uses_feedforward()) {
      // d = eps a under every force but the loops'.
      sweep_.accelerations(v_, w, F_, Q_joint_.data(), bias_, a_, ddq_.data());
      regulator_->residual_rate(a_, d_.data());
    }
    if (!regulator_->control(sweep_, g_.data(), y + L.u(), g_dot_.data(), d_.data(), lambda_.data(), ydot + L.u()))
      return false;
    regulator_->apply(lambda_.data(), F_);
  }
  sweep_.generalized_forces(F_, Q_.data());
  sweep_.gyroscopic(v_, mu_, w, dp);
  for (int c = 0; c < L.nv; ++c) dp[c] += Q_[c] + Q_joint_[c];

  for (int k = 0; k < L.size(); ++k)
    if (!std::isfinite(ydot[k])) return false;
  return true;
}

bool Dynamics::jacobian_times(const double* y, const double* v, double* Jv) {
  const int n = size();
  const bool new_base = jv_engaged_ != latch_state_.engaged_count() || !std::equal(y, y + n, jv_y_.begin()) ||
                        (regulator_ && regulator_->factorizations() != jv_factorizations_);
  if (regulator_ && new_base) {
    sweep_.set_configuration(y + layout_.q());
    if (!regulator_->hold_gains(sweep_)) return false;
    jv_factorizations_ = regulator_->factorizations();
  } else if (regulator_) {
    regulator_->hold_last_gains();
  }
  bool ok = true;
  if (new_base) {
    std::copy_n(y, n, jv_y_.begin());
    jv_engaged_ = latch_state_.engaged_count();
    ok = evaluate(0, y, jv_f_.data());
    ++jacobian_product_evals_;
  }
  // Half the digits for the step, half for the difference.
  Eigen::Map<const Eigen::VectorXd> y_(y, n), v_(v, n);
  const double v_norm = v_.norm();
  if (ok && v_norm > 0) {
    const double sigma = std::sqrt(std::numeric_limits<double>::epsilon()) * std::max(1.0, y_.norm()) / v_norm;
    Eigen::Map<Eigen::VectorXd>(jv_y1_.data(), n) = y_ + sigma * v_;
    ok = evaluate(0, jv_y1_.data(), Jv);
    ++jacobian_product_evals_;
    for (int k = 0; k < n; ++k) Jv[k] = (Jv[k] - jv_f_[k]) / sigma;
  } else if (ok) {
    std::fill_n(Jv, n, 0.0);
  }
  if (regulator_) regulator_->release_gains();
  if (!ok) jv_engaged_ = -1;
  return ok;
}

void Dynamics::switching_functions(const double* y, double* values) const {
  for (int l = 0; l < latch_count(); ++l)
    values[l] = latch_state_.switching_value(l, y[layout_.q() + scene_.model.coordinate[scene_.latches[l].joint]]);
}

void Dynamics::loads(double t, const double* y, Loads& out, std::vector<ClosureError>* closure) {
  const Model& model = scene_.model;
  const StateLayout& L = layout_;
  evaluate(t, y, ydot_.data());
  const double* q = y + L.q();
  const double* dq = w_.data();  // the rates (a one-coordinate joint's q')
  out.joints.assign(model.size(), JointLoad{});
  for (const JointSpring& s : scene_.springs) {
    const int c = model.coordinate[s.joint];
    out.joints[s.joint].spring += s.elastic_torque(q[c]);
    out.joints[s.joint].damper += -s.damping * dq[c];
  }
  for (const JointFriction& f : scene_.friction) out.joints[f.joint].friction += f.torque(dq[model.coordinate[f.joint]]);
  out.point_spring_tension.clear();
  for (const PointSpring& s : scene_.point_springs) {
    const PointSpringGeometry g = point_spring_geometry(s, poses_, v_, model.base_velocity);
    out.point_spring_tension.push_back(s.tension(g.length, g.rate));
  }
  for (int l = 0; l < latch_count(); ++l) {
    if (!latch_state_.engaged(l)) continue;
    const Latch& latch = scene_.latches[l];
    const int c = model.coordinate[latch.joint];
    out.joints[latch.joint].latch += latch.torque(q[c], dq[c]);
  }
  // The applied forces again (the force pass consumed them), loop forces
  // included, then the accelerations and each joint's wrench, moved from
  // the child's origin to the hinge point.
  for (Vec6& f : F_) f.setZero();
  add_body_loads(model, scene_.loads, poses_, F_);
  add_point_springs();
  if (regulator_) regulator_->apply(lambda_.data(), F_);
  sweep_.accelerations(v_, dq, F_, Q_joint_.data(), bias_, a_, ddq_.data());
  for (int i = 0; i < model.size(); ++i) {
    const Vec6 f = sweep_.joint_wrench(i, bias_, a_);
    Vec6& r = out.joints[i].reaction;
    r.head<3>() = f.head<3>();
    r.tail<3>() = f.tail<3>() - model.joints[i].child_point.cross(f.head<3>());
  }
  out.loop_force.resize(L.m);
  for (int c = 0; c < L.m; ++c) out.loop_force[c] = -lambda_[c];
  if (!closure) return;
  // evaluate() placed the bodies wherever a loop needs them.
  closure->resize(scene_.loops.size());
  for (std::size_t l = 0; l < scene_.loops.size(); ++l)
    (*closure)[l] = closure_error(poses_[scene_.loops[l].body], poses_[scene_.loops[l].image]);
}

void Dynamics::observe(double t, const double* y, Observation& out) {
  const Model& model = scene_.model;
  const StateLayout& L = layout_;
  loads(t, y, out.loads);
  out.dq.assign(ydot_.begin() + L.q(), ydot_.begin() + L.q() + L.nq);
  out.rates = w_;
  out.velocity = v_;
  body_poses(model, y + L.q(), out.poses);

  EnergyParts& E = out.energy;
  E = EnergyParts{};
  for (int i = 0; i < model.size(); ++i)
    E.kinetic += 0.5 * v_[i].dot(model.bodies[i].spatial_mass() * v_[i]);
  for (const JointSpring& s : scene_.springs) E.springs += s.energy(y[L.q() + model.coordinate[s.joint]]);
  for (int l = 0; l < latch_count(); ++l)
    if (latch_state_.engaged(l))
      E.latches += scene_.latches[l].energy(y[L.q() + model.coordinate[scene_.latches[l].joint]]);
  E.gravity = gravity_energy(model, out.poses);
  out.momentum = system_momentum(model, out.poses, v_);
  for (const PointSpring& s : scene_.point_springs)
    E.springs += s.energy(point_spring_geometry(s, out.poses, v_, model.base_velocity).length);

  const int n_loops = static_cast<int>(scene_.loops.size());
  out.closure.resize(n_loops);
  for (int l = 0; l < n_loops; ++l)
    out.closure[l] = closure_error(out.poses[scene_.loops[l].body], out.poses[scene_.loops[l].image]);
  if (regulator_) {
    regulator_->gap(out.poses, g_.data());
    E.regulator = regulator_->energy(sweep_, g_.data(), y + L.u());
  }
}

}  // namespace unfurl
