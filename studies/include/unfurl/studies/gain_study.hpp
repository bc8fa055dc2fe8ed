// The regulator's tunings compared on the pantograph.
#pragma once

#include <string>
#include <vector>

#include "unfurl/sim/simulation.hpp"

namespace unfurl::studies {

// The paper's diagonal tuning (16) against the full-matrix gains on the
// pantograph: the largest geometric loop gap of each along the run (the paper's run is
// let go on past the closure check to show where it goes), and the smallest
// eigenvalue a of K = W diag(W)^-1 along the full-gain run (a mode of the
// paper's tuning is stable only for a > p0 / ((p0 + 2 p1)(1 + 2 p0 p1))).
struct GainComparison {
  std::vector<double> t_full, residual_full, t_paper, residual_paper;
  std::vector<double> t_eigen, smallest_eigen;
  double routh_bound = 0;
  sim::RunStatus paper_status = sim::RunStatus::finished;
  std::string paper_failure;
  int paper_latches = 0, full_latches = 0;
};
GainComparison compare_gain_tunings(double budget_s);

}  // namespace unfurl::studies
