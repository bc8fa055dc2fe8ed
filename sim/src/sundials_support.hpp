// What the SUNDIALS-based integrators share: the context and vectors as
// owned objects, the callbacks into Dynamics, and checked calls.
#pragma once

#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>

#include <string>
#include <vector>

#include "unfurl/sim/dynamics.hpp"

namespace unfurl::sim::sundials {

// Throws std::runtime_error naming the call when a SUNDIALS call fails.
void check(int flag, const char* call);
void check_ptr(const void* ptr, const char* call);

class Context {
 public:
  Context();
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;
  operator SUNContext() const { return ctx_; }

 private:
  SUNContext ctx_ = nullptr;
};

class Vector {
 public:
  Vector(const std::vector<double>& values, SUNContext ctx);
  ~Vector();
  Vector(const Vector&) = delete;
  Vector& operator=(const Vector&) = delete;
  operator N_Vector() const { return v_; }
  double* data() const { return N_VGetArrayPointer(v_); }

 private:
  N_Vector v_ = nullptr;
};

// A dense matrix and its direct solver, for the implicit methods' Newton
// iterations.
struct DenseSolver {
  DenseSolver(int n, N_Vector y, SUNContext ctx);
  ~DenseSolver();
  DenseSolver(const DenseSolver&) = delete;
  DenseSolver& operator=(const DenseSolver&) = delete;
  SUNMatrix A = nullptr;
  SUNLinearSolver LS = nullptr;
};

// GMRES with left preconditioning by the Dynamics' NewtonPreconditioner.
struct KrylovSolver {
  KrylovSolver(N_Vector y, const Dynamics& dynamics, SUNContext ctx);
  ~KrylovSolver();
  KrylovSolver(const KrylovSolver&) = delete;
  KrylovSolver& operator=(const KrylovSolver&) = delete;
  SUNLinearSolver LS = nullptr;
};

// GMRES's Krylov dimension for a mechanism of m loop components. Where the
// preconditioner leaves the loop forces out (the paper's gains,
// newton_preconditioner.hpp) they change the Newton matrix by at most rank
// 2m (the momenta's rows in the range of the loops' m directions, the
// integral states' m rows), which a space of 2m + 5 holds, 5 being
// SUNDIALS' default for the rest. Where a
// loop closes through compliant pins or plates that part is no longer a
// tight cluster: with the default alone, Newton failed on 36 % of the
// flexible 10-stage array's steps. Capped, as the solver keeps that many
// vectors of the state.
int krylov_dimension(int loop_components);
inline constexpr int kMaxKrylovDimension = 300;

// The factor on Newton's tolerance that GMRES's residual must reach
// (CVodeSetEpsLin) for a step h on a mechanism whose loop regulator has the
// bandwidth v_max and the paper's gains: SUNDIALS' 0.05 divided by h v_max
// where that exceeds 1. (The full gains' loop forces are in the
// preconditioner, which leaves SUNDIALS' 0.05 as it is.) Without them the preconditioned
// Newton matrix departs from a normal one in proportion to gamma (the
// pantograph at its start: |P^-1 N - I| = 8.7e3 at gamma = 1e-5 s, 8.7e6 at
// 1e-2 s), so a small preconditioned residual bounds the Newton correction's
// error less and less as the steps lengthen. On the generated 30-stage array
// at rtol 1e-7 the corrections' error then set the step: the default took
// 9,112 steps over its first 8 s, this 2,811 (and 90 for 1,391 over 2 s at
// rtol 1e-8). It does not free the latched ring-down, which BDF's order 4
// holds at h v_max = 2.9 (README, "Where the rigid arrays' steps go"); where h v_max stays
// below 1 (pantograph_flexible, a 100-stage array's first 0.2 s) little
// changes.
double krylov_tolerance_factor(double step, double v_max);
inline constexpr double kSundialsKrylovToleranceFactor = 0.05;

// Callbacks, with the Dynamics as user data.
int rhs(double t, N_Vector y, N_Vector ydot, void* dynamics);
int switching(double t, N_Vector y, double* values, void* dynamics);
int precondition_setup(double t, N_Vector y, N_Vector fy, int jok, int* jcur, double gamma, void* dynamics);
int precondition_solve(double t, N_Vector y, N_Vector fy, N_Vector r, N_Vector z, double gamma, double delta, int lr,
                       void* dynamics);
// J v with the regulator's gains held (Dynamics::jacobian_times).
int jacobian_times(N_Vector v, N_Vector Jv, double t, N_Vector y, N_Vector fy, void* dynamics, N_Vector tmp);
// The dense J, column by column as J e_j with the gains held.
int dense_jacobian(double t, N_Vector y, N_Vector fy, SUNMatrix J, void* dynamics, N_Vector unit, N_Vector,
                   N_Vector);
// The dense Newton matrix for the latch state: before any latch engages,
// nullptr (the integrator's own difference quotients of f, with the gains'
// turn with q); once latches hold the mechanism, dense_jacobian. At the
// pantograph's deployed branch point R^-1 amplifies by up to 1/delta and
// f's curvature in q defeats difference quotients of f: with one spring
// 20 % stiffer the latched array took 5451 Newton failures and 53,324
// steps with them, 7 and 20,869 with the held gains.
using DenseJacobianFn = int (*)(double, N_Vector, N_Vector, SUNMatrix, void*, N_Vector, N_Vector, N_Vector);
DenseJacobianFn dense_jacobian_for(const Dynamics& dynamics);

// Keeps the library's last error message for the failure report instead of
// letting it print.
void capture_error(int code, const char* module, const char* function, char* message, void* sink);

}  // namespace unfurl::sim::sundials
