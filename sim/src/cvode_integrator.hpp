// CVODE: variable-order BDF (stiff, Newton with a dense direct solver or
// GMRES) or Adams-Moulton (non-stiff, fixed-point iteration).
#pragma once

#include <sundials/sundials_nonlinearsolver.h>

#include <optional>

#include "unfurl/sim/integrator.hpp"
#include "sundials_support.hpp"

namespace unfurl {

class CvodeIntegrator : public Integrator {
 public:
  CvodeIntegrator(IntegratorKind kind, Dynamics& dynamics, const RunSettings& settings, double t0,
                  const std::vector<double>& y0);
  ~CvodeIntegrator() override;

  StepOutcome step(double t_stop) override;
  double span_end() const override;
  void interpolate(double t, double* y) override;
  void interpolate_rate(double t, double* ydot) override;
  void restart(double t, const double* y) override;
  std::vector<int> roots() override;
  SolverStats stats() const override;
  double current_step() const override;
  double last_step() const override;

 private:
  // The dense Newton matrix: before any latch engages, CVODE's difference
  // quotients of f itself, with the gains' turn with q; once latches hold
  // the mechanism, the held gains' (sundials::dense_jacobian). At the
  // pantograph's deployed branch point R^-1 amplifies by up to 1/delta and
  // f's curvature in q defeats difference quotients of f: with one spring
  // 20 % stiffer the latched array took 5451 Newton failures and 53,324
  // steps with them, 7 and 18,663 with the held gains.
  void choose_jacobian();
  SolverStats segment_stats() const;  // since the last (re)start
  void derivative(double t, int k, double* out);

  Dynamics& dynamics_;
  sundials::Context ctx_;
  sundials::Vector y_;
  sundials::Vector atol_;
  sundials::Vector scratch_;
  std::optional<sundials::DenseSolver> dense_;
  std::optional<sundials::KrylovSolver> krylov_;
  SUNNonlinearSolver fixed_point_ = nullptr;
  void* mem_ = nullptr;
  double t_stop_set_ = -1;
  SolverStats earlier_segments_;
  std::string last_error_;
};

}  // namespace unfurl
