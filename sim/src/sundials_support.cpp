#include "sundials_support.hpp"

#include <sunlinsol/sunlinsol_dense.h>
#include <sunlinsol/sunlinsol_spgmr.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <stdexcept>

#include "newton_preconditioner.hpp"

namespace unfurl::sim::sundials {

void check(int flag, const char* call) {
  if (flag < 0) throw std::runtime_error(std::string(call) + " failed (flag " + std::to_string(flag) + ")");
}

void check_ptr(const void* ptr, const char* call) {
  if (!ptr) throw std::runtime_error(std::string(call) + " failed (out of memory)");
}

Context::Context() { check(SUNContext_Create(nullptr, &ctx_), "SUNContext_Create"); }
Context::~Context() { SUNContext_Free(&ctx_); }

Vector::Vector(const std::vector<double>& values, SUNContext ctx)
    : v_(N_VNew_Serial(static_cast<sunindextype>(values.size()), ctx)) {
  check_ptr(v_, "N_VNew_Serial");
  std::copy(values.begin(), values.end(), data());
}
Vector::~Vector() { N_VDestroy(v_); }

DenseSolver::DenseSolver(int n, N_Vector y, SUNContext ctx)
    : A(SUNDenseMatrix(n, n, ctx)), LS(SUNLinSol_Dense(y, A, ctx)) {
  check_ptr(A, "SUNDenseMatrix");
  check_ptr(LS, "SUNLinSol_Dense");
}
DenseSolver::~DenseSolver() {
  SUNLinSolFree(LS);
  SUNMatDestroy(A);
}

int krylov_dimension(int loop_components) { return std::min(2 * loop_components + 5, kMaxKrylovDimension); }

double krylov_tolerance_factor(double step, double v_max) {
  return kSundialsKrylovToleranceFactor / std::max(1.0, step * v_max);
}

KrylovSolver::KrylovSolver(N_Vector y, const Dynamics& dynamics, SUNContext ctx)
    : LS(SUNLinSol_SPGMR(y, SUN_PREC_LEFT,
                         krylov_dimension(dynamics.regulator() ? dynamics.regulator()->size() : 0), ctx)) {
  check_ptr(LS, "SUNLinSol_SPGMR");
}
KrylovSolver::~KrylovSolver() { SUNLinSolFree(LS); }

int precondition_setup(double, N_Vector y, N_Vector fy, int, int* jcur, double gamma, void* dynamics) {
  // The preconditioner is rebuilt from the current state each time: it
  // costs one pass of the sweep.
  static_cast<Dynamics*>(dynamics)->preconditioner().setup(N_VGetArrayPointer(y), N_VGetArrayPointer(fy), gamma);
  *jcur = 1;
  return 0;
}

int precondition_solve(double, N_Vector, N_Vector, N_Vector r, N_Vector z, double, double, int, void* dynamics) {
  static_cast<Dynamics*>(dynamics)->preconditioner().solve(N_VGetArrayPointer(r), N_VGetArrayPointer(z));
  return 0;
}

int jacobian_times(N_Vector v, N_Vector Jv, double t, N_Vector y, N_Vector, void* dynamics, N_Vector) {
  // Not finite: a positive return, which CVODE treats as recoverable.
  return static_cast<Dynamics*>(dynamics)->jacobian_times(t, N_VGetArrayPointer(y), N_VGetArrayPointer(v),
                                                          N_VGetArrayPointer(Jv))
             ? 0
             : 1;
}

int dense_jacobian(double t, N_Vector y, N_Vector, SUNMatrix J, void* dynamics, N_Vector unit, N_Vector, N_Vector) {
  Dynamics& d = *static_cast<Dynamics*>(dynamics);
  const sunindextype n = N_VGetLength(y);
  double* e = N_VGetArrayPointer(unit);
  std::fill_n(e, n, 0.0);
  for (sunindextype j = 0; j < n; ++j) {
    e[j] = 1;
    if (!d.jacobian_times(t, N_VGetArrayPointer(y), e, SM_COLUMN_D(J, j))) return 1;
    e[j] = 0;
  }
  return 0;
}

DenseJacobianFn dense_jacobian_for(const Dynamics& dynamics) {
  return dynamics.latch_state().engaged_count() > 0 ? dense_jacobian : nullptr;
}

int rhs(double t, N_Vector y, N_Vector ydot, void* dynamics) {
  // A positive return asks the integrator to retry with a smaller step.
  return static_cast<Dynamics*>(dynamics)->rhs(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot)) ? 0 : 1;
}

int switching(double, N_Vector y, double* values, void* dynamics) {
  static_cast<Dynamics*>(dynamics)->switching_functions(N_VGetArrayPointer(y), values);
  return 0;
}

void capture_error(int, const char* module, const char* function, char* message, void* sink) {
  *static_cast<std::string*>(sink) = std::string(module) + " " + function + ": " + message;
}

}  // namespace unfurl::sim::sundials
