// ARKODE: an explicit adaptive embedded Runge-Kutta method (ERKStep, the
// default 4th-order pair) or a diagonally implicit one (ARKStep with the
// whole right-hand side implicit, the default 4th-order SDIRK, Newton with a
// dense direct solver).
#pragma once

#include <optional>

#include "integrator.hpp"
#include "sundials_support.hpp"

namespace unfurl {

class ArkodeIntegrator : public Integrator {
 public:
  ArkodeIntegrator(IntegratorKind kind, Dynamics& dynamics, const RunSettings& settings, double t0,
                   const std::vector<double>& y0);
  ~ArkodeIntegrator() override;

  StepOutcome step(double t_stop) override;
  void interpolate(double t, double* y) override;
  void restart(double t, const double* y) override;
  std::vector<int> roots() override;
  SolverStats stats() const override;
  double current_step() const override;

 private:
  SolverStats segment_stats() const;

  bool explicit_;
  Dynamics& dynamics_;
  sundials::Context ctx_;
  sundials::Vector y_;
  sundials::Vector atol_;
  sundials::Vector scratch_;
  std::optional<sundials::DenseSolver> dense_;
  std::optional<sundials::KrylovSolver> krylov_;
  void* mem_ = nullptr;
  double t_stop_set_ = -1;
  double min_step_;
  SolverStats earlier_segments_;
  std::string last_error_;
};

}  // namespace unfurl
