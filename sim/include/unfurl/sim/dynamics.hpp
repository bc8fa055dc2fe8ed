// The equations of motion of a scene as a first-order system for the
// integrators: the state is (q, p) for a tree and (q, p, u) for a scene with
// loops, u the regulator's state on the active loop components:
//   q' = N(q) w, w the sweep's rates (6)            (N = I but for quaternions)
//   p' = -A^T Omega mu + A^T T^T (F - eps^T lambda) + Q_joint   (12)
//   u' = k_pi g(q) + k_v eps v                     (13)
// with g(q) the loops' true geometric gap (regulator.hpp). rhs() allocates
// nothing.
#pragma once

#include <memory>
#include <vector>

#include "unfurl/sim/energy.hpp"
#include "unfurl/sim/latch.hpp"
#include "unfurl/sim/loads.hpp"
#include "unfurl/sim/momentum.hpp"
#include "unfurl/sim/regulator.hpp"
#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/state_layout.hpp"
#include "unfurl/sim/sweep.hpp"

namespace unfurl {

class NewtonPreconditioner;

// Everything derived from a state at one instant.
struct Observation {
  std::vector<double> dq;              // q'
  std::vector<double> rates;           // the velocity coordinates (q' of one-coordinate joints)
  std::vector<Vec6> velocity;          // v_i, body frames
  std::vector<Pose> poses;
  std::vector<ClosureError> closure;   // per loop
  EnergyParts energy;
  SystemMomentum momentum;
  Loads loads;
};

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

  // The initial state: q0, p0 (from dq0 when no p0 is given), u0 = 0.
  std::vector<double> initial_state();

  // y' = f(t, y). Returns false when the result is not finite.
  bool rhs(double t, const double* y, double* ydot);
  long rhs_calls() const { return rhs_calls_; }

  // Latches: engagement state and the integrators' root functions.
  LatchState& latch_state() { return latch_state_; }
  const LatchState& latch_state() const { return latch_state_; }
  int latch_count() const { return static_cast<int>(scene_.latches.size()); }
  void switching_functions(const double* y, double* values) const;

  // Jv ~ (f(y + sigma v) - f(y)) / sigma for the implicit integrators'
  // Krylov solvers and latched dense Newton matrices, with the regulator's gains held at y's configuration
  // and solved without refinement on both sides. J then leaves out how the
  // gains turn with q, which only the Newton iteration sees (its residual
  // is f itself, exact), and a product costs the sweeps and one triangular
  // solve instead of a factorization and a refined solve. f(y) is kept
  // while y repeats: GMRES asks for several products at one iterate.
  // False where f is not finite.
  bool jacobian_times(const double* y, const double* v, double* Jv);
  long jacobian_product_evals() const { return jacobian_product_evals_; }

  // The implicit integrators' Krylov preconditioner, made on first use.
  NewtonPreconditioner& preconditioner();

  // Derived quantities at a state.
  void observe(double t, const double* y, Observation& out);

  // The loads at a state (loads.hpp): the element forces from the joints'
  // laws, the reactions from the sweep's accelerations (exact, O(N)); and
  // the loops' geometric gaps if asked.
  void loads(double t, const double* y, Loads& out, std::vector<ClosureError>* closure = nullptr);

  // The power the dampers, friction, point springs' damping and engaged
  // latches take out of the mechanism at coordinates q and joint rates dq
  // (>= 0); its integral is EnergyParts::dissipated. Uses the scratch of
  // rhs() (call it between right-hand sides).
  double dissipation(const double* q, const double* dq);

 private:
  bool evaluate(double t, const double* y, double* ydot);
  void joint_torques(const double* q, const double* dq, double* Q) const;
  // Adds the point springs' pulls to F_ (needs poses_ and v_).
  void add_point_springs();

  const Scene scene_;
  StateLayout layout_;
  Sweep sweep_;
  std::optional<Regulator> regulator_;
  LatchState latch_state_;
  std::unique_ptr<NewtonPreconditioner> preconditioner_;
  bool loads_need_poses_ = false;
  long rhs_calls_ = 0;
  long jacobian_product_evals_ = 0;

  // Scratch for rhs(), sized once.
  std::vector<Vec6> phi_, v_, mu_, F_;
  std::vector<Pose> poses_;
  std::vector<Vec6> bias_, a_;   // the accelerations pass
  std::vector<double> Q_, Q_joint_, ddq_, w_, lambda_, g_, g_dot_, d_, ydot_;
  // jacobian_times(): its base y and f(y) with held gains (for the latches
  // engaged then), and y + sigma v.
  std::vector<double> jv_y_, jv_f_, jv_y1_;
  int jv_engaged_ = -1;
  long jv_factorizations_ = -1;  // the regulator's count at the base
};

}  // namespace unfurl
