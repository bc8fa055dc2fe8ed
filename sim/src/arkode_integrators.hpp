// ARKODE: an explicit adaptive embedded Runge-Kutta method (ERKStep, the
// default 4th-order pair) or a diagonally implicit one (ARKStep with the
// whole right-hand side implicit, the default 4th-order SDIRK, Newton with a
// dense direct solver or GMRES). SUNDIALS 6 gives the two steppers parallel
// function families; the integrator picks one family once (arkode_api.hpp).
#pragma once

#include <optional>

#include "arkode_api.hpp"
#include "unfurl/sim/integrator.hpp"
#include "sundials_support.hpp"

namespace unfurl::sim {

class ArkodeIntegrator : public Integrator {
 public:
  ArkodeIntegrator(IntegratorKind kind, Dynamics& dynamics, const RunSettings& settings, double t0,
                   const std::vector<double>& y0);
  ~ArkodeIntegrator() override;

  StepOutcome step(double t_stop) override;
  double span_end() const override;
  void interpolate(double t, double* y) override;
  void interpolate_rate(double t, double* ydot) override;
  int interpolation_degree() const override;
  void restart(double t, const double* y) override;
  bool set_tolerances(double rtol, double atol) override;
  std::vector<int> roots() override;
  SolverStats stats() const override;
  double current_step() const override;
  double last_step() const override;

 private:
  // As CvodeIntegrator::choose_jacobian.
  void choose_jacobian();
  SolverStats segment_stats() const;
  void derivative(double t, int k, double* out);

  const ArkodeApi& api_;
  Dynamics& dynamics_;
  sundials::Context ctx_;
  sundials::Vector y_;
  double rtol_;
  sundials::Vector atol_;
  sundials::Vector scratch_;
  std::optional<sundials::DenseSolver> dense_;
  std::optional<sundials::KrylovSolver> krylov_;
  void* mem_ = nullptr;
  double t_stop_set_ = -1;
  SolverStats earlier_segments_;
  std::string last_error_;
};

}  // namespace unfurl::sim
