#include "unfurl/studies/study_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace unfurl::studies {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Ranks 1..n, ties sharing their average rank.
std::vector<double> ranks(const std::vector<double>& x) {
  std::vector<std::size_t> order(x.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return x[a] < x[b]; });
  std::vector<double> r(x.size());
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j + 1 < order.size() && x[order[j + 1]] == x[order[i]]) ++j;
    const double average = 0.5 * static_cast<double>(i + j) + 1;
    for (std::size_t k = i; k <= j; ++k) r[order[k]] = average;
    i = j + 1;
  }
  return r;
}

double pearson(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  const double mx = std::accumulate(x.begin(), x.end(), 0.0) / n, my = std::accumulate(y.begin(), y.end(), 0.0) / n;
  double sxy = 0, sxx = 0, syy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
    syy += (y[i] - my) * (y[i] - my);
  }
  if (sxx == 0 || syy == 0) return kNaN;
  return sxy / std::sqrt(sxx * syy);
}

// A tail percentile only where the sample reaches beyond it: the p-th (and
// the (100 - p)-th) needs at least 100 / p cases (p1 and p99: 100; p5 and
// p95: 20); else NaN, printed as "-".
double supported_percentile(const std::vector<double>& sorted, double p) {
  const double tail = std::min(p, 100 - p);
  if (static_cast<double>(sorted.size()) * tail < 100) return kNaN;
  return percentile(sorted, p);
}

OutputStatistics describe_output(const std::string& name, std::vector<double> x) {
  OutputStatistics s;
  s.output = name;
  s.n = static_cast<long>(x.size());
  if (x.empty()) {
    s.min = s.max = s.mean = s.sd = s.p1 = s.p5 = s.p50 = s.p95 = s.p99 = kNaN;
    return s;
  }
  std::sort(x.begin(), x.end());
  s.min = x.front();
  s.max = x.back();
  s.mean = std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(x.size());
  double ss = 0;
  for (double v : x) ss += (v - s.mean) * (v - s.mean);
  s.sd = x.size() > 1 ? std::sqrt(ss / static_cast<double>(x.size() - 1)) : 0.0;
  s.p1 = supported_percentile(x, 1);
  s.p5 = supported_percentile(x, 5);
  s.p50 = percentile(x, 50);
  s.p95 = supported_percentile(x, 95);
  s.p99 = supported_percentile(x, 99);
  return s;
}

}  // namespace

double percentile(const std::vector<double>& sorted, double p) {
  if (sorted.empty()) return kNaN;
  const double at = p / 100 * static_cast<double>(sorted.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(at));
  const std::size_t hi = std::min(lo + 1, sorted.size() - 1);
  return sorted[lo] + (at - static_cast<double>(lo)) * (sorted[hi] - sorted[lo]);
}

double spearman(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.size() < 3 || x.size() != y.size()) return kNaN;
  return pearson(ranks(x), ranks(y));
}

bool inputs_moved_together(const Study& study) { return study.zip && study.runs == 0 && study.variables.size() > 1; }

StudyStatistics study_statistics(const CaseColumns& columns, const std::vector<CaseResult>& results, bool together) {
  StudyStatistics st;
  std::vector<const CaseResult*> deployed;
  for (const CaseResult& r : results) {
    ++st.cases;
    if (r.status == CaseStatus::deployed) ++st.deployed;
    if (r.status == CaseStatus::deployed && r.failure.empty()) deployed.push_back(&r);
    if (r.status == CaseStatus::not_deployed) ++st.not_deployed;
    if (r.status == CaseStatus::failed) ++st.failed;
  }
  for (std::size_t o = 0; o < columns.outputs.size(); ++o) {
    std::vector<double> x;
    for (const CaseResult* r : deployed)
      if (std::isfinite(r->outputs[o])) x.push_back(r->outputs[o]);
    st.outputs.push_back(describe_output(columns.outputs[o], std::move(x)));
  }
  const auto moved_with = [&](std::size_t i) {
    std::vector<std::string> others;
    if (together)
      for (std::size_t j = 0; j < columns.inputs.size(); ++j)
        if (j != i) others.push_back(columns.inputs[j]);
    return others;
  };
  for (const std::string& output : CaseColumns::headline()) {
    Driver strongest{output, "", kNaN, {}};
    for (std::size_t i = 0; i < columns.inputs.size(); ++i) {
      std::vector<double> x, y;
      for (const CaseResult* r : deployed) {
        const double v = output_value(columns, *r, output);
        if (std::isfinite(v) && std::isfinite(r->inputs[i])) x.push_back(r->inputs[i]), y.push_back(v);
      }
      const Driver d{output, columns.inputs[i], spearman(x, y), {}};
      st.correlations.push_back(d);
      if (!std::isnan(d.rho) && (std::isnan(strongest.rho) || std::abs(d.rho) > std::abs(strongest.rho))) strongest = d;
    }
    if (std::isnan(strongest.rho)) continue;
    const auto at = std::find(columns.inputs.begin(), columns.inputs.end(), strongest.input);
    strongest.together = moved_with(static_cast<std::size_t>(at - columns.inputs.begin()));
    st.drivers.push_back(strongest);
  }
  return st;
}

}  // namespace unfurl::studies
