// The equations of motion of a scene as a first-order system for the
// integrators: the state is (q, p) for a tree and (q, p, u) for a scene with
// loops, u the regulator's state on the active loop components:
//   q' = N(q) w, w the sweep's rates (6)            (N = I but for quaternions)
//   p' = -A^T Omega mu + A^T T^T (F - eps^T lambda) + Q_joint   (12)
//   u' = k_pi g(q) + k_v eps v                     (13)
// with g(q) the loops' true geometric gap (regulator.hpp), F and Q_joint the
// force elements' (force_element.hpp). rhs() allocates nothing.
//
// Time enters only through the drivers (joint_driver.hpp): a driven joint's
// rate in w and its acceleration are the driver's at t, its q' is that
// rate, and its entry of p is not a state (held at zero): a scene without
// drivers is autonomous.
//
// What evaluations share, in one place:
// - the configuration (the sweep's placements and articulated inertias,
//   the bodies' poses) depends on q alone. It is kept with the q it was
//   computed for, and a key that changes whenever it is computed anew; an
//   evaluation at the same q reuses it (the finite-difference Jacobian's
//   momentum columns, the loads after a step).
// - the regulator's factorization of R = W + delta I depends on the
//   configuration: it is factored for a configuration key and reused at
//   that key. rhs(), loads() and observe() use the gains of their own
//   state; jacobian_times() holds those of its base state (see there).
// - loads() and observe() evaluate the right-hand side at their state first
//   and read what it derived; dissipation() has a configuration of its own.
// A failed evaluation (a result that is not finite, a closure system that
// cannot be factored) returns false; nothing derived from it is used.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "unfurl/sim/elements/joint_driver.hpp"
#include "unfurl/sim/energy.hpp"
#include "unfurl/sim/loads.hpp"
#include "unfurl/sim/mechanism_scales.hpp"
#include "unfurl/sim/momentum.hpp"
#include "unfurl/sim/regulator.hpp"
#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/state_layout.hpp"
#include "unfurl/sim/sweep.hpp"

namespace unfurl::sim {

class ClosureRank;
class NewtonPreconditioner;
class SparseClosureRank;
class SubtreeSpans;

// Everything derived from a state at one instant.
struct Observation {
  std::vector<double> q_dot;           // q' (nq)
  std::vector<double> w;               // the velocity coordinates (nv)
  std::vector<Vec6> velocity;          // v_i, body frames
  std::vector<Pose> poses;
  std::vector<ClosureError> closure;   // per loop
  EnergyParts energy;
  SystemMomentum momentum;
  Loads loads;
};

// Per state entry of `layout`, the size that counts as one radian of an
// angle: 1 for an angle, the length for a length, for a momentum what
// drifts its coordinate by one radian over half a period of the
// mechanism's fastest motion (inertia x rate / pi), for the regulator's
// state its gap's scale.
std::vector<double> state_scale_of(const Model& model, const StateLayout& layout, const MechanismScales& scales,
                                   const Regulator* regulator);

class Dynamics {
 public:
  explicit Dynamics(const Scene& scene);
  ~Dynamics();
  Dynamics(const Dynamics&) = delete;
  Dynamics& operator=(const Dynamics&) = delete;

  const Scene& scene() const { return scene_; }
  const Model& model() const { return scene_.model; }
  const StateLayout& layout() const { return layout_; }
  int size() const { return layout_.size(); }
  Regulator* regulator() { return regulator_ ? &*regulator_ : nullptr; }
  const Regulator* regulator() const { return regulator_ ? &*regulator_ : nullptr; }
  // The mechanism's own sizes (at q0): what tolerances and the closure's
  // metric are measured against.
  const MechanismScales& scales() const { return scales_; }
  // Per state entry, the size that counts as one radian of an angle
  // (state_scale_of): what tolerances and difference steps are measured in.
  const std::vector<double>& state_scale() const { return state_scale_; }

  // The initial state: q0, p0 (from dq0 when no p0 is given) and the
  // regulator state where its integral settles at q0 (Regulator::
  // integral_at_rest; 0 without the full tuning's feedforward).
  std::vector<double> initial_state();

  // y' = f(t, y). False where the result is not finite or the closure
  // system cannot be factored.
  bool rhs(double t, const double* y, double* ydot);
  long rhs_calls() const { return rhs_calls_; }

  // Latches: engagement state and the integrators' root functions.
  LatchState& latch_state() { return latch_state_; }
  const LatchState& latch_state() const { return latch_state_; }
  const std::vector<const Latch*>& latches() const { return latches_; }
  int latch_count() const { return static_cast<int>(latches_.size()); }
  void switching_functions(const double* y, double* values) const;

  // Jv ~ (f(y + sigma v) - f(y)) / sigma for the implicit integrators'
  // Krylov solvers and latched dense Newton matrices, with the regulator's
  // gains held at y's configuration and solved without refinement on both
  // sides. J then leaves out how the gains turn with q, which only the
  // Newton iteration sees (its residual is f itself, exact), and a product
  // costs the sweeps and one triangular solve instead of a factorization
  // and a refined solve. y, f(y), the gains' configuration key (and t, with
  // drivers) make the product's base: while they stand (GMRES asks for several products at
  // one iterate) the base is reused. False where f is not finite.
  bool jacobian_times(double t, const double* y, const double* v, double* Jv);
  long jacobian_product_evals() const { return jacobian_product_evals_; }

  // The implicit integrators' Krylov preconditioner, made on first use.
  NewtonPreconditioner& preconditioner();

  // Derived quantities at a state (the right-hand side at y first). False
  // where that evaluation failed.
  bool observe(double t, const double* y, Observation& out);

  // The loads at a state (loads.hpp): the elements' load columns, the
  // reactions from the sweep's accelerations (exact, O(N)), whether the
  // motion determines them (minimum-norm where it does not), the sensors'
  // readings from the same accelerations; and the loops' geometric gaps if
  // asked. False where the evaluation at y failed. At a step's end (the
  // run's monitor) the loads also update what the run remembers of how its
  // motion passed a branch point (closure_rank.hpp); elsewhere (samples, a
  // single state) they only read it.
  enum class At { state, step_end };
  bool loads(double t, const double* y, Loads& out, std::vector<ClosureError>* closure = nullptr,
             At at = At::state);
  // What Loads::element holds, and which of its columns each element writes.
  const std::vector<LoadColumn>& load_columns() const { return columns_; }
  const std::vector<int>& element_columns(std::size_t element) const { return element_columns_[element]; }
  // The column of latch l's torque.
  int latch_column(int l) const { return element_columns_[latch_elements_[l]][0]; }
  // What Loads::sensor holds.
  const std::vector<LoadColumn>& sensor_columns() const { return sensor_columns_; }
  // The peaks the elements ask a run to keep (Scene::element_peaks).
  const std::vector<TrackedPeak>& element_peaks() const { return element_peaks_; }

  // For linearizations (modes.hpp), at positions q and velocity
  // coordinates w, without the regulator (rigid_evaluation.cpp):
  // - the accelerations w' with the loops closed by the rigid model's loop
  //   forces, W lambda = d (minimum-norm where redundant, closure_rank.hpp
  //   and, beyond kMaxDenseComponents, sparse_closure_rank.hpp); false
  //   where the evaluation failed;
  bool rigid_accelerations(const double* q, const double* w, double* w_dot);
  // - the generalized force each of `elements` alone puts on each of the
  //   joint velocity coordinates `coordinates` (no elastic ones), at
  //   rates w: entry (e, j). The poses and velocities are formed once and
  //   each element's wrenches are carried straight to the joints above
  //   their bodies, so the cost is O(N + elements x coordinates), where a
  //   force pass per element would be O(N x elements);
  Eigen::MatrixXd element_joint_forces(const std::vector<std::size_t>& elements, const std::vector<int>& coordinates,
                                       const double* q, const double* w);
  // - the mass matrix, T = w^T M(q) w / 2 (p = M w but on a driven joint,
  //   whose p is not a state);
  Eigen::MatrixXd mass_matrix(const double* q);
  // - the loops' gap on the active components in the closure's metric (a
  //   distance over the mechanism's length, an angle), and its rate per
  //   unit of each velocity coordinate (m x nv).
  Eigen::VectorXd loop_gap(const double* q);
  Eigen::MatrixXd loop_jacobian(const double* q);

  // The power the elements take out of the mechanism at positions q and
  // position rates q' (>= 0 for passive elements); its integral is
  // EnergyParts::dissipated.
  double dissipation(const double* q, const double* q_dot);
  // The power the drivers put in at state y and time t (their torques from
  // the loads, times their rates); its integral is EnergyParts::driven.
  bool has_drivers() const { return !drivers_.empty(); }
  double drive_power(double t, const double* y);

  // The element state at positions q and rates w, for element k (its
  // discrete state). poses, v and the sweep's configuration must be
  // current where elements need them.
  ElementState element_state(std::size_t k, const double* q, const double* w, const std::vector<Pose>& poses,
                             const std::vector<Vec6>& v, const Vec6& v_base, const Sweep* sweep) const;

 private:
  // Computes the configuration at q unless it holds q's already; its key
  // changes when it computes.
  void configure(const double* q);
  // Only the sweep's placements at q (Sweep::set_placements), for analyses
  // that read poses and element forces but no accelerations.
  void place(const double* q);
  bool evaluate(double t, const double* y, double* ydot, Regulator::Gains gains);
  // The drivers' rates and accelerations at t into driven_rate_ and
  // driven_acceleration_.
  void drive(double t);
  void add_element_forces(const double* q, const double* w);
  // v_i of the configured sweep for velocity coordinates w, the base moving
  // with its steady velocity when `base_moves`.
  void body_velocities(const double* w, bool base_moves);
  // p = M(q) w at the configured q: the subtree momenta of the rates w
  // projected on each coordinate (the base at rest unless `base_moves`).
  void momenta_of_rates(const double* w, bool base_moves, double* p);
  // Sets y's regulator state to where its integral settles
  // (ClosureRank::settled_loop_forces, Regulator::integral_at_rest).
  void start_integral_at_rest(double* y);

  const Scene scene_;
  StateLayout layout_;
  Sweep sweep_;
  MechanismScales scales_;
  std::vector<double> state_scale_;
  std::optional<Regulator> regulator_;
  std::unique_ptr<ClosureRank> closure_rank_;  // up to kMaxDenseComponents components
  std::unique_ptr<SparseClosureRank> sparse_closure_rank_;  // beyond
  std::vector<const Latch*> latches_;
  std::vector<std::size_t> latch_elements_;  // element index of latch l
  std::vector<const JointDriver*> drivers_;
  std::vector<std::size_t> driver_elements_;  // element index of driver d
  // Per velocity coordinate: the driven joints' rates and accelerations at
  // the time of the last drive() (zero elsewhere).
  std::vector<double> driven_rate_ = std::vector<double>(scene_.model.nv, 0.0);
  std::vector<double> driven_acceleration_ = std::vector<double>(scene_.model.nv, 0.0);
  std::vector<int> latch_of_element_;        // -1 for elements that are not latches
  LatchState latch_state_;
  std::vector<LoadColumn> columns_;
  std::vector<std::vector<int>> element_columns_;
  std::vector<TrackedPeak> element_peaks_;
  std::vector<LoadColumn> sensor_columns_;
  std::unique_ptr<NewtonPreconditioner> preconditioner_;
  bool elements_need_poses_ = false;
  long rhs_calls_ = 0;
  long jacobian_product_evals_ = 0;

  // The configuration the sweep holds, and its key.
  std::vector<double> configured_q_;
  bool configured_ = false;
  long configuration_key_ = 0;

  // element_joint_forces(): the tree's subtrees and every body, made on
  // its first call.
  std::unique_ptr<SubtreeSpans> subtree_spans_;
  std::vector<int> every_body_;

  // Scratch for the evaluations, sized once.
  std::vector<Vec6> phi_, v_, mu_, F_;
  std::vector<Pose> poses_;
  std::vector<Vec6> bias_, a_;   // the accelerations pass
  std::vector<double> Q_, Q_joint_, ddq_, w_, lambda_, g_, g_dot_, d_, ydot_, values_;
  // jacobian_times(): its base (y, f(y) with held gains, the latches engaged
  // then, the gains' configuration key) and y + sigma v.
  std::vector<double> jv_y_, jv_f_, jv_y1_;
  int jv_engaged_ = -1;
  double jv_t_ = 0;
  long jv_gains_key_ = -1;
  // dissipation(): a configuration of its own.
  std::unique_ptr<Sweep> dissipation_sweep_;
  std::vector<Pose> dissipation_poses_;
  std::vector<Vec6> dissipation_v_;
  std::vector<double> dissipation_w_;
  Loads drive_loads_;  // drive_power()'s
  // observe()'s, sized once: each body's momentum and centre of mass.
  std::vector<Vec6> h_;
  std::vector<Vec3> centres_;
};

}  // namespace unfurl::sim
