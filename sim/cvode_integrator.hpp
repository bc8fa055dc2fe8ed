// CVODE: variable-order BDF (stiff, Newton with a dense direct solver) or
// Adams-Moulton (non-stiff, fixed-point iteration).
#pragma once

#include "integrator.hpp"
#include "sundials_support.hpp"

#include <sundials/sundials_nonlinearsolver.h>

#include <optional>

namespace unfurl {

class CvodeIntegrator : public Integrator {
 public:
  CvodeIntegrator(IntegratorKind kind, Dynamics& dynamics, const RunSettings& settings, double t0,
                  const std::vector<double>& y0);
  ~CvodeIntegrator() override;

  StepOutcome step(double t_stop) override;
  void interpolate(double t, double* y) override;
  void restart(double t, const double* y) override;
  std::vector<int> roots() override;
  SolverStats stats() const override;
  double current_step() const override;

 private:
  SolverStats segment_stats() const;  // since the last (re)start

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
  double min_step_;
  SolverStats earlier_segments_;
  std::string last_error_;
};

}  // namespace unfurl
