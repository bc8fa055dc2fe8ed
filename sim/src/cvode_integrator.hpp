// CVODE: variable-order BDF (stiff, Newton with a dense direct solver or
// GMRES) or Adams-Moulton (non-stiff, fixed-point iteration).
#pragma once

#include <sundials/sundials_nonlinearsolver.h>

#include <optional>

#include "unfurl/sim/integrator.hpp"
#include "sundials_support.hpp"

namespace unfurl::sim {

class CvodeIntegrator : public Integrator {
 public:
  CvodeIntegrator(IntegratorKind kind, Dynamics& dynamics, const RunSettings& settings, double t0,
                  const std::vector<double>& y0);
  ~CvodeIntegrator() override;

  StepOutcome step(double t_stop) override;
  double span_end() const override;
  void interpolate(double t, double* y) override;
  void interpolate_rate(double t, double* ydot) override;
  int interpolation_degree() const override { return max_order_; }  // CVODE's Nordsieck history's
  void restart(double t, const double* y) override;
  bool set_tolerances(double rtol, double atol) override;
  void watch_stability_limit() override;
  void limit_order(int order) override;
  std::vector<int> roots() override;
  SolverStats stats() const override;
  double current_step() const override;
  double last_step() const override;

 private:
  // The dense Newton matrix for the latch state (sundials::dense_jacobian_for).
  void choose_jacobian();
  SolverStats segment_stats() const;  // since the last (re)start
  void derivative(double t, int k, double* out);

  Dynamics& dynamics_;
  bool bdf_;
  int max_order_;  // CVODE's defaults: 5 for BDF, 12 for Adams
  sundials::Context ctx_;
  sundials::Vector y_;
  double rtol_;
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

}  // namespace unfurl::sim
