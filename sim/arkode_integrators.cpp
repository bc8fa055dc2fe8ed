#include "arkode_integrators.hpp"

#include <arkode/arkode_arkstep.h>
#include <arkode/arkode_erkstep.h>

#include <cstdlib>
#include <limits>

namespace unfurl {

using sundials::check;

ArkodeIntegrator::ArkodeIntegrator(IntegratorKind kind, Dynamics& dynamics, const RunSettings& settings,
                                   double t0, const std::vector<double>& y0)
    : explicit_(kind == IntegratorKind::arkode_erk),
      dynamics_(dynamics),
      y_(y0, ctx_),
      atol_(absolute_tolerances(dynamics.layout(), settings.atol), ctx_),
      scratch_(y0, ctx_),
      min_step_(std::numeric_limits<double>::infinity()) {
  const int n_roots = dynamics.latch_count();
  std::vector<int> falling(n_roots, -1);
  if (explicit_) {
    mem_ = ERKStepCreate(sundials::rhs, t0, y_, ctx_);
    sundials::check_ptr(mem_, "ERKStepCreate");
    check(ERKStepSetUserData(mem_, &dynamics_), "ERKStepSetUserData");
    check(ERKStepSetErrHandlerFn(mem_, sundials::capture_error, &last_error_), "ERKStepSetErrHandlerFn");
    check(ERKStepSVtolerances(mem_, settings.rtol, atol_), "ERKStepSVtolerances");
    check(ERKStepSetMaxNumSteps(mem_, -1), "ERKStepSetMaxNumSteps");
    if (n_roots > 0) {
      check(ERKStepRootInit(mem_, n_roots, sundials::switching), "ERKStepRootInit");
      check(ERKStepSetRootDirection(mem_, falling.data()), "ERKStepSetRootDirection");
      check(ERKStepSetNoInactiveRootWarn(mem_), "ERKStepSetNoInactiveRootWarn");
    }
  } else {
    mem_ = ARKStepCreate(nullptr, sundials::rhs, t0, y_, ctx_);
    sundials::check_ptr(mem_, "ARKStepCreate");
    check(ARKStepSetUserData(mem_, &dynamics_), "ARKStepSetUserData");
    check(ARKStepSetErrHandlerFn(mem_, sundials::capture_error, &last_error_), "ARKStepSetErrHandlerFn");
    check(ARKStepSVtolerances(mem_, settings.rtol, atol_), "ARKStepSVtolerances");
    check(ARKStepSetMaxNumSteps(mem_, -1), "ARKStepSetMaxNumSteps");
    if (uses_krylov(settings, dynamics.size())) {
      krylov_.emplace(y_, ctx_);
      check(ARKStepSetLinearSolver(mem_, krylov_->LS, nullptr), "ARKStepSetLinearSolver");
      check(ARKStepSetPreconditioner(mem_, sundials::precondition_setup, sundials::precondition_solve),
            "ARKStepSetPreconditioner");
    } else {
      dense_.emplace(dynamics.size(), y_, ctx_);
      check(ARKStepSetLinearSolver(mem_, dense_->LS, dense_->A), "ARKStepSetLinearSolver");
    }
    if (n_roots > 0) {
      check(ARKStepRootInit(mem_, n_roots, sundials::switching), "ARKStepRootInit");
      check(ARKStepSetRootDirection(mem_, falling.data()), "ARKStepSetRootDirection");
      check(ARKStepSetNoInactiveRootWarn(mem_), "ARKStepSetNoInactiveRootWarn");
    }
  }
}

ArkodeIntegrator::~ArkodeIntegrator() {
  if (explicit_)
    ERKStepFree(&mem_);
  else
    ARKStepFree(&mem_);
}

StepOutcome ArkodeIntegrator::step(double t_stop) {
  if (t_stop != t_stop_set_) {
    check(explicit_ ? ERKStepSetStopTime(mem_, t_stop) : ARKStepSetStopTime(mem_, t_stop), "SetStopTime");
    t_stop_set_ = t_stop;
  }
  double t = 0;
  const int flag = explicit_ ? ERKStepEvolve(mem_, t_stop, y_, &t, ARK_ONE_STEP)
                             : ARKStepEvolve(mem_, t_stop, y_, &t, ARK_ONE_STEP);
  StepOutcome out;
  out.t = t;
  double h = 0;
  if (explicit_)
    ERKStepGetLastStep(mem_, &h);
  else
    ARKStepGetLastStep(mem_, &h);
  if (h > 0) min_step_ = std::min(min_step_, h);
  if (flag < 0) {
    char* name = explicit_ ? ERKStepGetReturnFlagName(flag) : ARKStepGetReturnFlagName(flag);
    out.status = StepStatus::failed;
    out.reason = std::string(name) + (last_error_.empty() ? "" : " (" + last_error_ + ")");
    std::free(name);
    if (explicit_)
      ERKStepGetCurrentTime(mem_, &out.t);
    else
      ARKStepGetCurrentTime(mem_, &out.t);
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

void ArkodeIntegrator::interpolate(double t, double* y) {
  check(explicit_ ? ERKStepGetDky(mem_, t, 0, scratch_) : ARKStepGetDky(mem_, t, 0, scratch_), "GetDky");
  std::copy(scratch_.data(), scratch_.data() + dynamics_.size(), y);
}

void ArkodeIntegrator::restart(double t, const double* y) {
  earlier_segments_ += segment_stats();
  min_step_ = std::numeric_limits<double>::infinity();
  std::copy(y, y + dynamics_.size(), y_.data());
  if (explicit_)
    check(ERKStepReInit(mem_, sundials::rhs, t, y_), "ERKStepReInit");
  else
    check(ARKStepReInit(mem_, nullptr, sundials::rhs, t, y_), "ARKStepReInit");
  t_stop_set_ = -1;
}

std::vector<int> ArkodeIntegrator::roots() {
  std::vector<int> found(dynamics_.latch_count());
  check(explicit_ ? ERKStepGetRootInfo(mem_, found.data()) : ARKStepGetRootInfo(mem_, found.data()),
        "GetRootInfo");
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
  long steps = 0, etf = 0;
  if (explicit_) {
    ERKStepGetNumSteps(mem_, &steps);
    ERKStepGetNumErrTestFails(mem_, &etf);
    ERKStepGetLastStep(mem_, &s.last_step);
  } else {
    long jac = 0, setups = 0, iters = 0, fails = 0;
    ARKStepGetNumSteps(mem_, &steps);
    ARKStepGetNumErrTestFails(mem_, &etf);
    if (dense_) ARKStepGetNumJacEvals(mem_, &jac);
    if (krylov_) ARKStepGetNumLinIters(mem_, &s.linear_iterations);
    ARKStepGetNumLinSolvSetups(mem_, &setups);
    ARKStepGetNumNonlinSolvIters(mem_, &iters);
    ARKStepGetNumNonlinSolvConvFails(mem_, &fails);
    ARKStepGetLastStep(mem_, &s.last_step);
    s.jacobian_evals = jac;
    s.linear_setups = setups;
    s.nonlinear_iterations = iters;
    s.nonlinear_failures = fails;
  }
  s.steps = steps;
  s.error_test_failures = etf;
  s.min_step = min_step_;
  return s;
}

double ArkodeIntegrator::current_step() const {
  double h = 0;
  if (explicit_)
    ERKStepGetCurrentStep(mem_, &h);
  else
    ARKStepGetCurrentStep(mem_, &h);
  return h;
}

}  // namespace unfurl
