#include "arkode_integrators.hpp"

#include <arkode/arkode_arkstep.h>

#include <cstdlib>

namespace unfurl::sim {

using sundials::check;

ArkodeIntegrator::ArkodeIntegrator(IntegratorKind kind, Dynamics& dynamics, const RunSettings& settings,
                                   double t0, const std::vector<double>& y0)
    : api_(kind == IntegratorKind::arkode_erk ? erk_api() : dirk_api()),
      dynamics_(dynamics),
      y_(y0, ctx_),
      rtol_(settings.rtol),
      atol_(absolute_tolerances(dynamics, settings.atol), ctx_),
      scratch_(y0, ctx_) {
  mem_ = api_.create(sundials::rhs, t0, y_, ctx_);
  sundials::check_ptr(mem_, "ARKODE create");
  check(api_.set_user_data(mem_, &dynamics_), "SetUserData");
  check(api_.set_err_handler(mem_, sundials::capture_error, &last_error_), "SetErrHandlerFn");
  check(api_.sv_tolerances(mem_, rtol_, atol_), "SVtolerances");
  check(api_.set_max_num_steps(mem_, -1), "SetMaxNumSteps");
  if (api_.implicit) {
    if (uses_krylov(settings, dynamics.size())) {
      krylov_.emplace(y_, dynamics_, ctx_);
      check(ARKStepSetLinearSolver(mem_, krylov_->LS, nullptr), "ARKStepSetLinearSolver");
      check(ARKStepSetPreconditioner(mem_, sundials::precondition_setup, sundials::precondition_solve),
            "ARKStepSetPreconditioner");
      check(ARKStepSetJacTimes(mem_, nullptr, sundials::jacobian_times), "ARKStepSetJacTimes");
    } else {
      dense_.emplace(dynamics.size(), y_, ctx_);
      check(ARKStepSetLinearSolver(mem_, dense_->LS, dense_->A), "ARKStepSetLinearSolver");
      choose_jacobian();
    }
  }
  if (const int n_roots = dynamics.latch_count(); n_roots > 0) {
    std::vector<int> falling(n_roots, -1);
    check(api_.root_init(mem_, n_roots, sundials::switching), "RootInit");
    check(api_.set_root_direction(mem_, falling.data()), "SetRootDirection");
    check(api_.set_no_inactive_root_warn(mem_), "SetNoInactiveRootWarn");
  }
}

ArkodeIntegrator::~ArkodeIntegrator() { api_.free(&mem_); }

StepOutcome ArkodeIntegrator::step(double t_stop) {
  if (t_stop != t_stop_set_) {
    check(api_.set_stop_time(mem_, t_stop), "SetStopTime");
    t_stop_set_ = t_stop;
  }
  double t = 0;
  const int flag = api_.evolve(mem_, t_stop, y_, &t, ARK_ONE_STEP);
  StepOutcome out;
  out.t = t;
  if (flag < 0) {
    char* name = api_.get_return_flag_name(flag);
    out.status = StepStatus::failed;
    out.reason = std::string(name) + (last_error_.empty() ? "" : " (" + last_error_ + ")");
    std::free(name);
    api_.get_current_time(mem_, &out.t);
    return out;
  }
  if (flag == ARK_ROOT_RETURN) {
    out.status = StepStatus::root;
  } else if (flag == ARK_TSTOP_RETURN) {
    out.status = StepStatus::reached_stop;
    t_stop_set_ = -1;
  } else {
    out.status = StepStatus::advanced;
  }
  return out;
}

double ArkodeIntegrator::span_end() const {
  double t = 0;
  api_.get_current_time(mem_, &t);
  return t;
}

// ARKODE's default interpolant (Hermite) is of degree at most
// ARK_INTERP_MAX_DEGREE, whichever method it serves.
int ArkodeIntegrator::interpolation_degree() const { return ARK_INTERP_MAX_DEGREE; }

void ArkodeIntegrator::derivative(double t, int k, double* out) {
  check(api_.get_dky(mem_, t, k, scratch_), "GetDky");
  std::copy(scratch_.data(), scratch_.data() + dynamics_.size(), out);
}

void ArkodeIntegrator::interpolate(double t, double* y) { derivative(t, 0, y); }
void ArkodeIntegrator::interpolate_rate(double t, double* ydot) { derivative(t, 1, ydot); }

void ArkodeIntegrator::restart(double t, const double* y) {
  earlier_segments_ += segment_stats();
  std::copy(y, y + dynamics_.size(), y_.data());
  check(api_.reinit(mem_, sundials::rhs, t, y_), "ReInit");
  t_stop_set_ = -1;
  choose_jacobian();
}

bool ArkodeIntegrator::set_tolerances(double rtol, double atol) {
  rtol_ = rtol;
  const std::vector<double> scaled = absolute_tolerances(dynamics_, atol);
  std::copy(scaled.begin(), scaled.end(), atol_.data());
  check(api_.sv_tolerances(mem_, rtol_, atol_), "SVtolerances");
  return true;
}

void ArkodeIntegrator::choose_jacobian() {
  if (!dense_) return;
  check(ARKStepSetJacFn(mem_, sundials::dense_jacobian_for(dynamics_)), "ARKStepSetJacFn");
}

std::vector<int> ArkodeIntegrator::roots() {
  std::vector<int> found(dynamics_.latch_count());
  check(api_.get_root_info(mem_, found.data()), "GetRootInfo");
  std::vector<int> hit;
  for (int l = 0; l < static_cast<int>(found.size()); ++l)
    if (found[l] != 0) hit.push_back(l);
  return hit;
}

SolverStats ArkodeIntegrator::stats() const {
  SolverStats s = earlier_segments_;
  s += segment_stats();
  return s;
}

SolverStats ArkodeIntegrator::segment_stats() const {
  SolverStats s;
  api_.get_num_steps(mem_, &s.steps);
  api_.get_num_err_test_fails(mem_, &s.error_test_failures);
  s.last_step = last_step();
  if (!api_.implicit) return s;
  if (dense_) ARKStepGetNumJacEvals(mem_, &s.jacobian_evals);
  if (krylov_) ARKStepGetNumLinIters(mem_, &s.linear_iterations);
  ARKStepGetNumLinSolvSetups(mem_, &s.linear_setups);
  ARKStepGetNumNonlinSolvIters(mem_, &s.nonlinear_iterations);
  ARKStepGetNumNonlinSolvConvFails(mem_, &s.nonlinear_failures);
  return s;
}

double ArkodeIntegrator::current_step() const {
  double h = 0;
  api_.get_current_step(mem_, &h);
  return h;
}

double ArkodeIntegrator::last_step() const {
  double h = 0;
  api_.get_last_step(mem_, &h);
  return h;
}

}  // namespace unfurl::sim
