#include "cvode_integrator.hpp"

#include <cvode/cvode.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <cstdlib>

namespace unfurl::sim {

using sundials::check;

CvodeIntegrator::CvodeIntegrator(IntegratorKind kind, Dynamics& dynamics, const RunSettings& settings,
                                 double t0, const std::vector<double>& y0)
    : dynamics_(dynamics),
      bdf_(kind == IntegratorKind::cvode_bdf),
      max_order_(bdf_ ? 5 : 12),
      y_(y0, ctx_),
      rtol_(settings.rtol),
      atol_(absolute_tolerances(dynamics, settings.atol), ctx_),
      scratch_(y0, ctx_) {
  mem_ = CVodeCreate(bdf_ ? CV_BDF : CV_ADAMS, ctx_);
  sundials::check_ptr(mem_, "CVodeCreate");
  check(CVodeInit(mem_, sundials::rhs, t0, y_), "CVodeInit");
  check(CVodeSetUserData(mem_, &dynamics_), "CVodeSetUserData");
  check(CVodeSetErrHandlerFn(mem_, sundials::capture_error, &last_error_), "CVodeSetErrHandlerFn");
  check(CVodeSVtolerances(mem_, rtol_, atol_), "CVodeSVtolerances");
  check(CVodeSetMaxNumSteps(mem_, -1), "CVodeSetMaxNumSteps");
  check(CVodeSetMaxOrd(mem_, max_order_), "CVodeSetMaxOrd");
  if (settings.stability_limit_detection == StabilityLimitDetection::on) watch_stability_limit();
  if (bdf_ && uses_krylov(settings, dynamics.size())) {
    krylov_.emplace(y_, dynamics_, ctx_);
    check(CVodeSetLinearSolver(mem_, krylov_->LS, nullptr), "CVodeSetLinearSolver");
    check(CVodeSetPreconditioner(mem_, sundials::precondition_setup, sundials::precondition_solve),
          "CVodeSetPreconditioner");
    check(CVodeSetJacTimes(mem_, nullptr, sundials::jacobian_times), "CVodeSetJacTimes");
  } else if (bdf_) {
    dense_.emplace(dynamics.size(), y_, ctx_);
    check(CVodeSetLinearSolver(mem_, dense_->LS, dense_->A), "CVodeSetLinearSolver");
    choose_jacobian();
  } else {
    fixed_point_ = SUNNonlinSol_FixedPoint(y_, 0, ctx_);
    sundials::check_ptr(fixed_point_, "SUNNonlinSol_FixedPoint");
    check(CVodeSetNonlinearSolver(mem_, fixed_point_), "CVodeSetNonlinearSolver");
  }
  if (dynamics.latch_count() > 0) {
    check(CVodeRootInit(mem_, dynamics.latch_count(), sundials::switching), "CVodeRootInit");
    std::vector<int> falling(dynamics.latch_count(), -1);
    check(CVodeSetRootDirection(mem_, falling.data()), "CVodeSetRootDirection");
    check(CVodeSetNoInactiveRootWarn(mem_), "CVodeSetNoInactiveRootWarn");
  }
}

CvodeIntegrator::~CvodeIntegrator() {
  CVodeFree(&mem_);
  if (fixed_point_) SUNNonlinSolFree(fixed_point_);
}

StepOutcome CvodeIntegrator::step(double t_stop) {
  if (t_stop != t_stop_set_) {
    check(CVodeSetStopTime(mem_, t_stop), "CVodeSetStopTime");
    t_stop_set_ = t_stop;
  }
  if (krylov_ && dynamics_.regulator() && dynamics_.regulator()->settings().gains == GainTuning::paper) {
    double h = 0;
    CVodeGetCurrentStep(mem_, &h);
    check(CVodeSetEpsLin(mem_, sundials::krylov_tolerance_factor(h, dynamics_.regulator()->v_max())), "CVodeSetEpsLin");
  }
  double t = 0;
  const int flag = CVode(mem_, t_stop, y_, &t, CV_ONE_STEP);
  StepOutcome out;
  out.t = t;
  if (flag < 0) {
    char* name = CVodeGetReturnFlagName(flag);
    out.status = StepStatus::failed;
    out.reason = std::string(name) + (last_error_.empty() ? "" : " (" + last_error_ + ")");
    std::free(name);
    CVodeGetCurrentTime(mem_, &out.t);
    return out;
  }
  if (flag == CV_ROOT_RETURN) {
    out.status = StepStatus::root;
  } else if (flag == CV_TSTOP_RETURN) {
    out.status = StepStatus::reached_stop;
    t_stop_set_ = -1;  // CVODE clears the stop time once reached
  } else {
    out.status = StepStatus::advanced;
  }
  return out;
}

double CvodeIntegrator::span_end() const {
  double t = 0;
  CVodeGetCurrentTime(mem_, &t);
  return t;
}

void CvodeIntegrator::derivative(double t, int k, double* out) {
  check(CVodeGetDky(mem_, t, k, scratch_), "CVodeGetDky");
  std::copy(scratch_.data(), scratch_.data() + dynamics_.size(), out);
}

void CvodeIntegrator::interpolate(double t, double* y) { derivative(t, 0, y); }
void CvodeIntegrator::interpolate_rate(double t, double* ydot) { derivative(t, 1, ydot); }

void CvodeIntegrator::restart(double t, const double* y) {
  earlier_segments_ += segment_stats();
  std::copy(y, y + dynamics_.size(), y_.data());
  check(CVodeReInit(mem_, t, y_), "CVodeReInit");
  t_stop_set_ = -1;
  choose_jacobian();
}

void CvodeIntegrator::watch_stability_limit() {
  // Only BDF has the limit; the setting persists through CVodeReInit.
  if (bdf_) check(CVodeSetStabLimDet(mem_, SUNTRUE), "CVodeSetStabLimDet");
}

void CvodeIntegrator::limit_order(int order) {
  // Lowering the cap is allowed after CVodeInit and persists through
  // CVodeReInit; the interpolation's degree stays max_order_, an upper bound.
  if (bdf_ && order < max_order_) check(CVodeSetMaxOrd(mem_, order), "CVodeSetMaxOrd");
}

bool CvodeIntegrator::set_tolerances(double rtol, double atol) {
  rtol_ = rtol;
  const std::vector<double> scaled = absolute_tolerances(dynamics_, atol);
  std::copy(scaled.begin(), scaled.end(), atol_.data());
  check(CVodeSVtolerances(mem_, rtol_, atol_), "CVodeSVtolerances");
  return true;
}

void CvodeIntegrator::choose_jacobian() {
  if (!dense_) return;
  check(CVodeSetJacFn(mem_, sundials::dense_jacobian_for(dynamics_)), "CVodeSetJacFn");
}

std::vector<int> CvodeIntegrator::roots() {
  std::vector<int> found(dynamics_.latch_count());
  check(CVodeGetRootInfo(mem_, found.data()), "CVodeGetRootInfo");
  std::vector<int> hit;
  for (int l = 0; l < static_cast<int>(found.size()); ++l)
    if (found[l] != 0) hit.push_back(l);
  return hit;
}

SolverStats CvodeIntegrator::stats() const {
  SolverStats s = earlier_segments_;
  s += segment_stats();
  return s;
}

SolverStats CvodeIntegrator::segment_stats() const {
  SolverStats s;
  long jac = 0, setups = 0, iters = 0, fails = 0, etf = 0, steps = 0;
  CVodeGetNumSteps(mem_, &steps);
  CVodeGetNumLinSolvSetups(mem_, &setups);
  CVodeGetNumNonlinSolvIters(mem_, &iters);
  CVodeGetNumNonlinSolvConvFails(mem_, &fails);
  CVodeGetNumErrTestFails(mem_, &etf);
  if (dense_) CVodeGetNumJacEvals(mem_, &jac);
  if (krylov_) CVodeGetNumLinIters(mem_, &s.linear_iterations);
  s.steps = steps;
  s.jacobian_evals = jac;
  s.linear_setups = setups;
  s.nonlinear_iterations = iters;
  s.nonlinear_failures = fails;
  s.error_test_failures = etf;
  s.last_step = last_step();
  return s;
}

double CvodeIntegrator::last_step() const {
  double h = 0;
  CVodeGetLastStep(mem_, &h);
  return h;
}

double CvodeIntegrator::current_step() const {
  double h = 0;
  CVodeGetCurrentStep(mem_, &h);
  return h;
}

}  // namespace unfurl::sim
