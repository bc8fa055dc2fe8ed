#include "unfurl/sim/dynamics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "closure_rank.hpp"
#include "newton_preconditioner.hpp"
#include "sparse_closure_rank.hpp"
#include "subtree_spans.hpp"

namespace unfurl::sim {

namespace {

std::vector<double> latch_start_positions(const Scene& scene, const std::vector<const Latch*>& latches) {
  std::vector<double> q;
  for (const Latch* latch : latches) q.push_back(scene.q0[scene.model.position_of(latch->joint).value]);
  return q;
}

}  // namespace

Dynamics::Dynamics(const Scene& scene)
    : scene_(scene),
      sweep_(scene_.model),
      scales_(mechanism_scales(scene_, sweep_)),
      latches_(scene_.latches()),
      latch_of_element_(scene_.elements.size(), -1),
      latch_state_(latches_, latch_start_positions(scene_, latches_)),
      configured_q_(scene_.model.nq),
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
      w_(scene_.model.nv),
      h_(scene_.model.size()),
      centres_(scene_.model.size()) {
  layout_.nq = scene_.model.nq;
  layout_.nv = scene_.model.nv;
  columns_ = scene_.load_columns(&element_columns_);
  element_peaks_ = scene_.element_peaks();
  sensor_columns_ = sim::sensor_columns(scene_.sensors);
  bool dissipation_needs_poses = false;
  std::size_t most_columns = 0;
  for (std::size_t k = 0; k < scene_.elements.size(); ++k) {
    const ForceElement& e = *scene_.elements[k];
    elements_need_poses_ = elements_need_poses_ || e.needs_poses();
    dissipation_needs_poses = dissipation_needs_poses || (e.needs_poses() && e.dissipative());
    most_columns = std::max(most_columns, element_columns_[k].size());
    if (dynamic_cast<const Latch*>(&e)) {
      latch_of_element_[k] = static_cast<int>(latch_elements_.size());
      latch_elements_.push_back(k);
    }
    if (const auto* driver = dynamic_cast<const JointDriver*>(&e)) {
      drivers_.push_back(driver);
      driver_elements_.push_back(k);
    }
  }
  values_.resize(most_columns);
  if (dissipation_needs_poses) {
    dissipation_sweep_ = std::make_unique<Sweep>(scene_.model);
    dissipation_poses_.resize(scene_.model.size());
    dissipation_v_.resize(scene_.model.size());
  }
  dissipation_w_.resize(scene_.model.nv);
  if (!scene_.loops.empty()) {
    auto components = active_loop_components(scene_.model, scene_.loops, scene_.q0, scales_.length, sweep_);
    layout_.m = static_cast<int>(components.size());
    const double v_max = scene_.regulator.v_max.value_or(Regulator::automatic_bandwidth(scales_.rate));
    regulator_.emplace(scene_.model, scene_.loops, std::move(components), scene_.regulator, v_max, scales_.length);
    configure(scene_.q0.data());
    regulator_->calibrate(sweep_);
    Eigen::VectorXd S(layout_.m);
    for (int c = 0; c < layout_.m; ++c) S[c] = 1 / regulator_->component_scale(c);
    // The rigid loop forces at rest and in linearizations need W formed;
    // the loads' analysis follows the closure solver (sparse beyond
    // kMaxDenseComponents, or asked for).
    if (layout_.m <= kMaxDenseComponents) closure_rank_ = std::make_unique<ClosureRank>(S);
    if (scene_.regulator.solver == ClosureSolverKind::sparse || !closure_rank_)
      sparse_closure_rank_ = std::make_unique<SparseClosureRank>(scene_.model, scene_.loops, regulator_->components(), S);
    lambda_.resize(layout_.m);
    g_.resize(layout_.m);
    g_dot_.resize(layout_.m);
    d_.resize(layout_.m);
  }
  state_scale_ = state_scale_of(scene_.model, layout_, scales_, regulator());
  ydot_.resize(layout_.size());
  jv_y_.resize(layout_.size());
  jv_f_.resize(layout_.size());
  jv_y1_.resize(layout_.size());
}

Dynamics::~Dynamics() = default;

std::vector<double> state_scale_of(const Model& model, const StateLayout& layout, const MechanismScales& scales,
                                   const Regulator* regulator) {
  std::vector<double> scale(layout.size());
  // An elastic coordinate (unit modal mass): its body's size times the
  // square root of its mass.
  auto elastic = [&](int v) {
    return scales.length * std::sqrt(model.bodies[model.body_of_elastic_velocity[v]].mass);
  };
  for (int c = 0; c < layout.nq; ++c)
    scale[layout.q() + c] = model.joint_of_position[c] < 0 ? elastic(c - layout.nq + layout.nv)
                            : model.position_unit(c) == "m" ? scales.length
                                                            : 1.0;
  // The momentum that drifts its coordinate by one radian (one length) over
  // half a period of the mechanism's fastest own motion, pi / rate: as
  // long as an error of p drifts q one way before the motion turns.
  for (int c = 0; c < layout.nv; ++c)
    scale[layout.p() + c] = scales.inertia[c] * scales.rate / M_PI *
                            (model.joint_of_velocity[c] < 0     ? elastic(c)
                             : model.velocity_unit(c) == "m/s" ? scales.length
                                                                : 1.0);
  for (int c = 0; c < layout.m; ++c) scale[layout.u() + c] = regulator->component_scale(c);
  return scale;
}

NewtonPreconditioner& Dynamics::preconditioner() {
  if (!preconditioner_) preconditioner_ = std::make_unique<NewtonPreconditioner>(*this);
  return *preconditioner_;
}

void Dynamics::configure(const double* q) {
  if (configured_ && std::equal(configured_q_.begin(), configured_q_.end(), q)) return;
  sweep_.set_configuration(q);
  std::copy_n(q, layout_.nq, configured_q_.begin());
  configured_ = true;
  ++configuration_key_;
}

void Dynamics::place(const double* q) {
  if (configured_ && std::equal(configured_q_.begin(), configured_q_.end(), q)) return;
  sweep_.set_placements(q);
  configured_ = false;  // its articulated inertias are another configuration's
  ++configuration_key_;
}

std::vector<double> Dynamics::initial_state() {
  const Model& model = scene_.model;
  std::vector<double> y(size(), 0.0);
  std::copy(scene_.q0.begin(), scene_.q0.end(), y.begin() + layout_.q());
  if (!scene_.p0.empty()) {
    std::copy(scene_.p0.begin(), scene_.p0.end(), y.begin() + layout_.p());
  } else {
    // p = A^T mu with mu the subtree momenta of the given joint rates (a
    // driven joint's is 0: every profile starts at rest, and validation
    // refuses another).
    configure(scene_.q0.data());
    momenta_of_rates(scene_.dq0.data(), true, y.data() + layout_.p());
  }
  for (const JointDriver* d : drivers_) y[layout_.p() + model.velocity_of(d->joint).value] = 0;
  if (regulator_ && regulator_->uses_feedforward()) start_integral_at_rest(y.data());
  if (closure_rank_) closure_rank_->forget();
  if (sparse_closure_rank_) sparse_closure_rank_->forget();
  return y;
}

void Dynamics::start_integral_at_rest(double* y) {
  // evaluate() leaves the loops' acceleration d under every other force.
  if (!evaluate(0, y, ydot_.data(), Regulator::Gains::current)) return;
  std::vector<double> W_lambda(layout_.m);
  if (closure_rank_) {
    const LoopMatrix& W = regulator_->mobility(sweep_, configuration_key_);
    closure_rank_->compute(W);
    closure_rank_->settled_loop_forces(d_.data(), lambda_.data());
    const Eigen::Map<const Eigen::VectorXd> lambda(lambda_.data(), layout_.m);
    Eigen::Map<Eigen::VectorXd>(W_lambda.data(), layout_.m) = W * lambda;
  } else {
    // Beyond kMaxDenseComponents W is not formed: its products are passes of the sweep.
    if (!sparse_closure_rank_->compute(sweep_, false)) return;
    sparse_closure_rank_->settled_loop_forces(d_.data(), lambda_.data());
    regulator_->mobility_product(sweep_, lambda_.data(), W_lambda.data());
  }
  regulator_->integral_at_rest(W_lambda.data(), lambda_.data(), d_.data(), y + layout_.u());
}

void Dynamics::momenta_of_rates(const double* w, bool base_moves, double* p) {
  const Model& model = scene_.model;
  body_velocities(w, base_moves);
  for (int i = 0; i < model.size(); ++i) F_[i] = model.flexible(i) ? Vec6(sweep_.own_momentum(i, v_[i], w).head<6>())
                                                                  : Vec6(model.bodies[i].spatial_mass() * v_[i]);
  sweep_.generalized_forces(F_, p);
  for (int i = 0; i < model.size(); ++i)
    if (model.flexible(i)) {
      const int m = model.bodies[i].flexible->modes();
      Eigen::Map<Eigen::VectorXd>(p + model.first_elastic_velocity[i], m) +=
          sweep_.own_momentum(i, v_[i], w).tail(m);
    }
}

void Dynamics::body_velocities(const double* w, bool base_moves) {
  const Model& model = scene_.model;
  for (int i = 0; i < model.size(); ++i) {
    const int k = model.parent[i];
    if (model.node_of(i) >= 0)
      v_[i] = sweep_.placement(i).transform_velocity(sweep_.node_velocity(i, v_, w));
    else
      v_[i] = sweep_.placement(i).transform_velocity(k != kBase ? v_[k] : base_moves ? model.base_velocity : Vec6::Zero());
    for (int r = 0; r < model.joints[i].dof(); ++r)
      v_[i] += sweep_.motion_axes(i).col(r) * w[(model.first_velocity[i] + r).value];
  }
}

ElementState Dynamics::element_state(std::size_t k, const double* q, const double* w, const std::vector<Pose>& poses,
                                     const std::vector<Vec6>& v, const Vec6& v_base, const Sweep* sweep) const {
  const int l = latch_of_element_[k];
  return {scene_.model, Positions(q), Rates(w), poses, v, v_base, l >= 0 && latch_state_.engaged(l), sweep};
}

void Dynamics::add_element_forces(const double* q, const double* w) {
  for (Vec6& f : F_) f.setZero();
  std::fill(Q_joint_.begin(), Q_joint_.end(), 0.0);
  ElementForces out{RatesOut(Q_joint_.data()), F_};
  for (std::size_t k = 0; k < scene_.elements.size(); ++k)
    scene_.elements[k]->add_forces(element_state(k, q, w, poses_, v_, scene_.model.base_velocity, &sweep_), out);
}

double Dynamics::dissipation(const double* q, const double* q_dot) {
  const Model& model = scene_.model;
  rates_from_position_rates(model, q, q_dot, dissipation_w_.data());
  if (dissipation_sweep_) {
    // The rate of a length is the same seen from the base at rest.
    dissipation_sweep_->set_configuration(q);
    dissipation_sweep_->poses(dissipation_poses_);
    dissipation_sweep_->velocities_from_rates(dissipation_w_.data(), dissipation_v_);
  }
  double P = 0;
  for (std::size_t k = 0; k < scene_.elements.size(); ++k) {
    const ForceElement& e = *scene_.elements[k];
    if (!e.dissipative()) continue;
    P += e.dissipated_power(
        element_state(k, q, dissipation_w_.data(), dissipation_poses_, dissipation_v_, Vec6::Zero(),
                      dissipation_sweep_.get()));
  }
  return P;
}

bool Dynamics::rhs(double t, const double* y, double* ydot) {
  ++rhs_calls_;
  return evaluate(t, y, ydot, Regulator::Gains::current);
}

void Dynamics::drive(double t) {
  for (const JointDriver* d : drivers_) {
    const int c = scene_.model.velocity_of(d->joint).value;
    const JointDriver::Motion m = d->at(t);
    driven_rate_[c] = m.rate;
    driven_acceleration_[c] = m.acceleration;
  }
}

bool Dynamics::evaluate(double t, const double* y, double* ydot, Regulator::Gains gains) {
  const Model& model = scene_.model;
  const StateLayout& L = layout_;
  const double* q = y + L.q();
  const double* p = y + L.p();
  double* dq = ydot + L.q();
  double* dp = ydot + L.p();

  configure(q);
  const double* driven_rate = drivers_.empty() ? nullptr : driven_rate_.data();
  const double* driven_acceleration = drivers_.empty() ? nullptr : driven_acceleration_.data();
  if (driven_rate) drive(t);
  sweep_.bias(p, phi_, driven_rate);
  sweep_.velocities(p, phi_, model.base_velocity, w_.data(), v_, driven_rate);
  sweep_.momenta(v_, phi_, mu_);
  position_rates(model, q, w_.data(), dq);
  const double* w = w_.data();

  if (elements_need_poses_ || regulator_) sweep_.poses(poses_);
  add_element_forces(q, w);
  if (regulator_) {
    regulator_->gap(poses_, g_.data());
    regulator_->residual_rate(v_, g_dot_.data());
    if (regulator_->uses_feedforward()) {
      // d = eps a under every force but the loops'.
      sweep_.accelerations(v_, w, F_, Q_joint_.data(), bias_, a_, ddq_.data(), driven_acceleration);
      regulator_->residual_rate(a_, d_.data());
    }
    if (gains == Regulator::Gains::current && !regulator_->factorize(sweep_, configuration_key_)) return false;
    regulator_->control(g_.data(), y + L.u(), g_dot_.data(), d_.data(), gains, lambda_.data(), ydot + L.u());
    regulator_->apply(lambda_.data(), F_);
  }
  sweep_.generalized_forces(F_, Q_.data());
  sweep_.gyroscopic(v_, mu_, w, dp);
  for (int c = 0; c < L.nv; ++c) dp[c] += Q_[c] + Q_joint_[c];
  for (const JointDriver* d : drivers_) dp[model.velocity_of(d->joint).value] = 0;

  for (int k = 0; k < L.size(); ++k)
    if (!std::isfinite(ydot[k])) return false;
  return true;
}

bool Dynamics::jacobian_times(double t, const double* y, const double* v, double* Jv) {
  const int n = size();
  // The held gains are the last factorization's: a new base when anything
  // has been factored since, as when y, t (with drivers) or the latches
  // changed.
  const bool new_base = jv_engaged_ != latch_state_.engaged_count() || !std::equal(y, y + n, jv_y_.begin()) ||
                        (!drivers_.empty() && t != jv_t_) ||
                        (regulator_ && regulator_->factorized_configuration() != jv_gains_key_);
  bool ok = true;
  if (new_base) {
    std::copy_n(y, n, jv_y_.begin());
    jv_t_ = t;
    jv_engaged_ = latch_state_.engaged_count();
    if (regulator_) {
      configure(y + layout_.q());
      ok = regulator_->factorize(sweep_, configuration_key_);
      jv_gains_key_ = configuration_key_;
    }
    ok = ok && evaluate(t, y, jv_f_.data(), Regulator::Gains::held);
    ++jacobian_product_evals_;
  }
  // Half the digits for the step, half for the difference; sizes measured
  // in the state's own scales, so the step is the same for any units.
  Eigen::Map<const Eigen::VectorXd> y_(y, n), v_(v, n), s_(state_scale_.data(), n);
  const double v_norm = v_.cwiseQuotient(s_).norm();
  if (ok && v_norm > 0) {
    const double sigma =
        std::sqrt(std::numeric_limits<double>::epsilon()) * std::max(1.0, y_.cwiseQuotient(s_).norm()) / v_norm;
    Eigen::Map<Eigen::VectorXd>(jv_y1_.data(), n) = y_ + sigma * v_;
    ok = evaluate(t, jv_y1_.data(), Jv, Regulator::Gains::held);
    ++jacobian_product_evals_;
    for (int k = 0; k < n; ++k) Jv[k] = (Jv[k] - jv_f_[k]) / sigma;
  } else if (ok) {
    std::fill_n(Jv, n, 0.0);
  }
  if (!ok) jv_engaged_ = -1;
  return ok;
}

void Dynamics::switching_functions(const double* y, double* values) const {
  const Positions q(y + layout_.q());
  for (int l = 0; l < latch_count(); ++l)
    values[l] = latch_state_.switching_value(l, q[scene_.model.position_of(latches_[l]->joint)]);
}

bool Dynamics::loads(double t, const double* y, Loads& out, std::vector<ClosureError>* closure, At at) {
  const Model& model = scene_.model;
  const StateLayout& L = layout_;
  if (!evaluate(t, y, ydot_.data(), Regulator::Gains::current)) return false;
  const double* driven_acceleration = drivers_.empty() ? nullptr : driven_acceleration_.data();
  const double* q = y + L.q();
  const double* w = w_.data();
  out.element.assign(columns_.size(), 0.0);
  for (std::size_t k = 0; k < scene_.elements.size(); ++k) {
    if (element_columns_[k].empty()) continue;
    scene_.elements[k]->load_values(element_state(k, q, w, poses_, v_, model.base_velocity, &sweep_), values_.data());
    for (std::size_t c = 0; c < element_columns_[k].size(); ++c) out.element[element_columns_[k][c]] += values_[c];
  }
  // The applied forces again (the force pass consumed them); with loops,
  // the rigid model's loop forces at this state (closure_rank.hpp) from the
  // loops' acceleration under them. Then the accelerations and each
  // joint's wrench, moved from the child's origin to the hinge point.
  add_element_forces(q, w);
  out.determinacy = Determinacy::determinate;
  out.closure_rank = -1;
  if (regulator_) {
    if (!regulator_->uses_feedforward()) {  // else evaluate() left d in d_
      sweep_.accelerations(v_, w, F_, Q_joint_.data(), bias_, a_, ddq_.data(), driven_acceleration);
      regulator_->residual_rate(a_, d_.data());
      add_element_forces(q, w);
    }
    // lambda_ holds the regulator's loop forces, which moved the mechanism.
    const bool remember = at == At::step_end;
    if (!sparse_closure_rank_) {
      closure_rank_->compute(regulator_->mobility(sweep_, configuration_key_));
      if (!closure_rank_->loop_forces(d_.data(), lambda_.data(), remember))
        out.determinacy = Determinacy::indeterminate;
      out.closure_rank = closure_rank_->rank();
    } else if (!sparse_closure_rank_->compute(sweep_, remember)) {
      out.determinacy = Determinacy::not_assessed;  // the regulator's loop forces stand
    } else if (!sparse_closure_rank_->loop_forces(d_.data(), lambda_.data(), remember)) {
      out.determinacy = Determinacy::indeterminate;
    }
  }
  if (regulator_) regulator_->apply(lambda_.data(), F_);
  sweep_.accelerations(v_, w, F_, Q_joint_.data(), bias_, a_, ddq_.data(), driven_acceleration);
  out.reaction.resize(model.size());
  for (int i = 0; i < model.size(); ++i) {
    const Vec6 f = sweep_.joint_wrench(i, bias_, a_);
    Vec6& r = out.reaction[i];
    r.head<3>() = f.head<3>();
    r.tail<3>() = f.tail<3>() - model.joints[i].child_point.cross(f.head<3>());
  }
  // What the joint transmits along its axis beyond its other elements'
  // torques is the driver's.
  for (std::size_t d = 0; d < drivers_.size(); ++d) {
    const int i = drivers_[d]->joint, c = model.velocity_of(i).value;
    out.element[element_columns_[driver_elements_[d]][0]] =
        sweep_.motion_axes(i).col(0).dot(sweep_.joint_wrench(i, bias_, a_)) - Q_joint_[c];
  }
  out.loop_force.resize(L.m);
  for (int c = 0; c < L.m; ++c) out.loop_force[c] = -lambda_[c];
  out.sensor.resize(sensor_columns_.size());
  if (!scene_.sensors.empty()) {
    if (!elements_need_poses_ && !regulator_) sweep_.poses(poses_);
    double* reading = out.sensor.data();
    for (const Sensor& s : scene_.sensors) {
      if (s.node >= 0) {
        // On a flexible body: carried by its node's frame, a bracket's
        // offset r turning with it.
        const Placement& X = sweep_.node_placement(s.body, s.node);
        const Vec3 r = s.point - model.bodies[s.body].flexible->nodes[s.node].point;
        s.read_at(poses_[s.body].child(X), sweep_.node_frame_velocity(s.body, s.node, v_, w),
                  sweep_.node_frame_acceleration(s.body, s.node, v_, w), r, X.rho + X.G.transpose() * r, reading);
      } else {
        s.read(poses_[s.body], v_[s.body], a_[s.body], reading);
      }
      reading += 3 * s.measures.size();
    }
  }
  if (!closure) return true;
  // evaluate() placed the bodies wherever a loop needs them.
  closure->resize(scene_.loops.size());
  for (std::size_t l = 0; l < scene_.loops.size(); ++l)
    (*closure)[l] = closure_error(poses_[scene_.loops[l].body], poses_[scene_.loops[l].image]);
  return true;
}

double Dynamics::drive_power(double t, const double* y) {
  if (!loads(t, y, drive_loads_)) return std::numeric_limits<double>::quiet_NaN();
  double P = 0;
  for (std::size_t d = 0; d < drivers_.size(); ++d)
    P += drive_loads_.element[element_columns_[driver_elements_[d]][0]] *
         driven_rate_[scene_.model.velocity_of(drivers_[d]->joint).value];
  return P;
}

bool Dynamics::observe(double t, const double* y, Observation& out) {
  const Model& model = scene_.model;
  const StateLayout& L = layout_;
  if (!loads(t, y, out.loads)) return false;
  out.q_dot.assign(ydot_.begin() + L.q(), ydot_.begin() + L.q() + L.nq);
  out.w = w_;
  out.velocity = v_;
  body_poses(model, y + L.q(), out.poses);

  EnergyParts& E = out.energy;
  E = EnergyParts{};
  for (int i = 0; i < model.size(); ++i) {
    if (model.flexible(i)) {
      const flexible::ExtendedVector own = sweep_.own_momentum(i, v_[i], w_.data());
      const int m = model.bodies[i].flexible->modes();
      h_[i] = own.head<6>();
      E.kinetic += 0.5 * (v_[i].dot(h_[i]) +
                          Eigen::Map<const Eigen::VectorXd>(w_.data() + model.first_elastic_velocity[i], m).dot(own.tail(m)));
    } else {
      h_[i] = model.bodies[i].spatial_mass() * v_[i];
      E.kinetic += 0.5 * v_[i].dot(h_[i]);
    }
  }
  for (std::size_t k = 0; k < scene_.elements.size(); ++k) {
    const ForceElement& e = *scene_.elements[k];
    const double V = e.potential_energy(element_state(k, y + L.q(), w_.data(), out.poses, v_, model.base_velocity, &sweep_));
    switch (e.energy_store()) {
      case EnergyStore::springs:
        E.springs += V;
        break;
      case EnergyStore::latches:
        E.latches += V;
        break;
      case EnergyStore::gravity:
        E.gravity += V;
        break;
    }
  }
  for (int i = 0; i < model.size(); ++i) centres_[i] = sweep_.centre_of_mass(i);
  out.momentum = system_momentum(model, out.poses, h_, centres_);

  const int n_loops = static_cast<int>(scene_.loops.size());
  out.closure.resize(n_loops);
  for (int l = 0; l < n_loops; ++l)
    out.closure[l] = closure_error(out.poses[scene_.loops[l].body], out.poses[scene_.loops[l].image]);
  if (regulator_) {
    regulator_->gap(out.poses, g_.data());
    // loads() factored R at y's configuration.
    E.regulator = regulator_->energy(g_.data(), y + L.u());
  }
  return true;
}

}  // namespace unfurl::sim
