#include "run_monitor.hpp"

#include <algorithm>
#include <cmath>

namespace unfurl::sim {

namespace {

// The load x at a step's end t into its peak, with its maximum between the
// steps.
void observe_step(Peak& peak, StepMaximum& between, double x, double t) {
  peak.update(x, t);
  if (const std::optional<Peak> vertex = between.observe(t, x)) peak.update(vertex->value, vertex->t);
}

}  // namespace

RunMonitor::RunMonitor(Dynamics& dynamics) : dynamics_(dynamics) {
  peaks_.latch_torque.resize(dynamics.latch_count());
  latch_torque_between_.resize(dynamics.latch_count());
  hinge_force_.resize(dynamics.model().size());
  hinge_moment_.resize(dynamics.model().size());
  peaks_.element.resize(dynamics.element_peaks().size());
  element_between_.resize(peaks_.element.size());
  sensor_peaks_ = dynamics.scene().sensor_peaks();
  peaks_.sensor.resize(sensor_peaks_.size());
  sensor_between_.resize(peaks_.sensor.size());
}

std::optional<double> RunMonitor::observe(double t, const double* y) {
  if (!dynamics_.loads(t, y, loads_, &closure_, Dynamics::At::step_end)) return std::nullopt;
  for (int l = 0; l < dynamics_.latch_count(); ++l)
    if (dynamics_.latch_state().engaged(l))
      observe_step(peaks_.latch_torque[l], latch_torque_between_[l],
                   std::abs(loads_.element[dynamics_.latch_column(l)]), t);
  for (std::size_t k = 0; k < peaks_.element.size(); ++k) {
    double squares = 0;
    for (const int c : dynamics_.element_peaks()[k].columns) squares += loads_.element[c] * loads_.element[c];
    observe_step(peaks_.element[k], element_between_[k], std::sqrt(squares), t);
  }
  for (std::size_t k = 0; k < peaks_.sensor.size(); ++k) {
    double squares = 0;
    for (const int c : sensor_peaks_[k].columns) squares += loads_.sensor[c] * loads_.sensor[c];
    observe_step(peaks_.sensor[k], sensor_between_[k], std::sqrt(squares), t);
  }
  const bool determinate = loads_.determinacy != Determinacy::indeterminate;
  if (loads_.determinacy == Determinacy::not_assessed) peaks_.loads_assessed = false;
  for (std::size_t j = 0; j < loads_.reaction.size(); ++j) {
    const Vec6& r = loads_.reaction[j];
    hinge_force_[j].observe(r.head<3>().norm(), t, determinate);
    hinge_moment_[j].observe(r.tail<3>().norm(), t, determinate);
  }
  if (!determinate) {
    if (!in_indeterminate_span_) peaks_.indeterminate_spans.push_back({t, t});
    peaks_.indeterminate_spans.back()[1] = t;
  }
  in_indeterminate_span_ = !determinate;
  if (loads_.closure_rank >= 0) {
    if (peaks_.closure_rank_at_start < 0) peaks_.closure_rank_at_start = loads_.closure_rank;
    if (peaks_.lowest_closure_rank < 0 || loads_.closure_rank < peaks_.lowest_closure_rank)
      peaks_.lowest_closure_rank = loads_.closure_rank, peaks_.lowest_closure_rank_t = t;
  }
  const bool before_latch = dynamics_.latch_state().engaged_count() == 0;
  double largest = 0;
  for (const ClosureError& c : closure_) {
    peaks_.gap_m.update(c.distance, t);
    peaks_.gap_rad.update(c.angle, t);
    if (before_latch) {
      peaks_.gap_m_before_latch.update(c.distance, t);
      peaks_.gap_rad_before_latch.update(c.angle, t);
    }
    largest = std::max({largest, dynamics_.scales().relative_length(c.distance), c.angle});
  }
  return largest;
}

void RunMonitor::latched() {
  // The model changed: the loads' steps before and after are not one
  // smooth function.
  for (auto* between : {&latch_torque_between_, &element_between_, &sensor_between_})
    for (StepMaximum& m : *between) m.restart();
  for (DeterminatePeak& p : hinge_force_) p.latched();
  for (DeterminatePeak& p : hinge_moment_) p.latched();
}

RunPeaks RunMonitor::peaks(bool completed) const {
  RunPeaks peaks = peaks_;
  for (const DeterminatePeak& p : hinge_force_) {
    peaks.hinge_force.push_back(p.settled(completed));
    peaks.hinge_force_indeterminate.push_back(p.over_indeterminate_steps(completed));
  }
  for (const DeterminatePeak& p : hinge_moment_) {
    peaks.hinge_moment.push_back(p.settled(completed));
    peaks.hinge_moment_indeterminate.push_back(p.over_indeterminate_steps(completed));
  }
  return peaks;
}

void RunMonitor::step_taken(double h) {
  if (ramping_ && h > last_h_) {
    last_h_ = h;
    min_step_after_restart_ = std::min(min_step_after_restart_, h);
    return;
  }
  ramping_ = false;
  min_step_ = std::min(min_step_, h);
}

}  // namespace unfurl::sim
