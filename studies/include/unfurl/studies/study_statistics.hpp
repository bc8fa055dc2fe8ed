// Statistics of a study's outputs over its deployed cases, and which input
// drives each output (Spearman's rank correlation). Cases with an injected
// failure are counted by status but left out of the statistics: they sit at
// the nominal values and would distort both the spread and the ranking.
#pragma once

#include <string>
#include <vector>

#include "unfurl/studies/case_result.hpp"

namespace unfurl::studies {

// The tail percentiles are NaN where the sample does not reach beyond them:
// p1 and p99 need 100 cases, p5 and p95 20.
struct OutputStatistics {
  std::string output;
  long n = 0;  // deployed cases (no injected failure) with a finite value
  double min = 0, max = 0, mean = 0, sd = 0;
  double p1 = 0, p5 = 0, p50 = 0, p95 = 0, p99 = 0;
};

struct Driver {
  std::string output, input;
  double rho = 0;  // Spearman's rank correlation over the deployed cases
  // The other inputs that moved with `input` (a zip): then no one of them
  // is the driver.
  std::vector<std::string> together;
};

struct StudyStatistics {
  long cases = 0, deployed = 0, not_deployed = 0, failed = 0;
  std::vector<OutputStatistics> outputs;  // every output column
  std::vector<Driver> drivers;            // per headline output, the input with the largest |rho|
  std::vector<Driver> correlations;       // every headline output against every input
};

// `together`: the inputs moved together (a zip of lists: one case per
// index), so that no one of them can be named a driver; else each varied
// on its own (a product of lists, random draws).
StudyStatistics study_statistics(const CaseColumns& columns, const std::vector<CaseResult>& results,
                                 bool together = false);
// Whether a study's inputs moved together: a zip of lists.
bool inputs_moved_together(const Study& study);

// The p-th percentile (0..100) of sorted values, linear between ranks.
double percentile(const std::vector<double>& sorted, double p);
// Spearman's rho of paired samples (average ranks for ties); NaN when
// either side is constant or there are fewer than three pairs.
double spearman(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace unfurl::studies
