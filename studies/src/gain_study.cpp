#include "unfurl/studies/gain_study.hpp"

#include <Eigen/Eigenvalues>

#include "unfurl/sim/dynamics.hpp"
#include "unfurl/sim/number_text.hpp"
#include "unfurl/sim/scene_file.hpp"
#include "unfurl/studies/stability_verdicts.hpp"

namespace unfurl::studies {

GainComparison compare_gain_tunings(double budget_s) {
  GainComparison g;
  const sim::Scene full = sim::load_builtin_scene("pantograph", {{"run.max_wall_time", sim::format_number(budget_s)}});
  // The paper's run is let go past the closure check, up to loops open by
  // metres, to show where it goes.
  const sim::Scene paper = sim::load_builtin_scene(
      "pantograph",
      {{"regulator.gains", "paper"}, {"run.max_closure", "1e3"}, {"run.max_wall_time", sim::format_number(budget_s)}});
  const sim::RunResult run_full = sim::simulate(full, full.run), run_paper = sim::simulate(paper, paper.run);
  for (const sim::Sample& s : run_full.trajectory.samples) {
    g.t_full.push_back(s.t);
    g.residual_full.push_back(largest_gap(s));
  }
  for (const sim::Sample& s : run_paper.trajectory.samples) {
    g.t_paper.push_back(s.t);
    g.residual_paper.push_back(largest_gap(s));
  }
  g.paper_status = run_paper.status;
  if (run_paper.status == sim::RunStatus::failed) g.paper_failure = sim::describe(run_paper.failure);
  g.paper_latches = static_cast<int>(run_paper.trajectory.events.size());
  g.full_latches = static_cast<int>(run_full.trajectory.events.size());

  // a = eigenvalues of K = W diag(W(0))^-1 (the paper's gains come from W
  // at t = 0), similar to the symmetric diag(W(0))^-1/2 W diag(W(0))^-1/2.
  sim::Dynamics dynamics(full);
  sim::Regulator& regulator = *dynamics.regulator();
  sim::Sweep sweep(full.model);
  const sim::RegulatorSettings& r = full.regulator;
  g.routh_bound = r.p0 / ((r.p0 + 2 * r.p1) * (1 + 2 * r.p0 * r.p1));
  sweep.set_configuration(full.q0.data());
  const Eigen::VectorXd scale = regulator.mobility(sweep).diagonal().cwiseSqrt().cwiseInverse();
  for (std::size_t k = 0; k < run_full.trajectory.samples.size(); k += 5) {
    const sim::Sample& s = run_full.trajectory.samples[k];
    sweep.set_configuration(s.y.data());
    const Eigen::MatrixXd W = regulator.mobility(sweep);
    const Eigen::MatrixXd K = scale.asDiagonal() * W * scale.asDiagonal();
    g.t_eigen.push_back(s.t);
    g.smallest_eigen.push_back(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(K, Eigen::EigenvaluesOnly).eigenvalues()(0));
  }
  return g;
}

}  // namespace unfurl::studies
