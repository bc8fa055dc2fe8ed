#include "latch_events.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace unfurl::sim {

namespace {
constexpr int kBisections = 60;
// How far above zero, relative to the latch coordinate's size, the bound
// on s must stay for the graze search to be passed over: a billion times
// the interpolant's round-off, so that the search, had it run, would have
// found s > 0 at its minimum and no graze.
constexpr double kClearOfZero = 1e-9;
}  // namespace

LatchEvents::LatchEvents(Dynamics& dynamics, double window)
    : dynamics_(dynamics),
      window_(window),
      y_(dynamics.size()),
      ydot_(dynamics.size()),
      rate_lo_(dynamics.size()),
      rate_hi_(dynamics.size()),
      y_lo_(dynamics.size()),
      y_hi_(dynamics.size()) {}

double LatchEvents::switching(int l, const double* y) const {
  const Positions q(y + dynamics_.layout().q());
  return dynamics_.latch_state().switching_value(l, q[dynamics_.model().position_of(dynamics_.latches()[l]->joint)]);
}

double LatchEvents::switching_rate(int l, const double* ydot) const {
  // q' of a one-coordinate joint is its rate.
  const Positions q_dot(ydot + dynamics_.layout().q());
  return dynamics_.latch_state().switching_rate(l, q_dot[dynamics_.model().position_of(dynamics_.latches()[l]->joint)]);
}

double LatchEvents::switching_at(Integrator& integrator, int l, double t) {
  integrator.interpolate(t, y_.data());
  return switching(l, y_.data());
}

double LatchEvents::bisect(Integrator& integrator, int l, double lo, double hi) {
  for (int k = 0; k < kBisections && hi - lo > 0; ++k) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (switching_at(integrator, l, mid) > 0 ? lo : hi) = mid;
  }
  return hi;
}

double LatchEvents::graze(Integrator& integrator, int l, double lo, double hi) {
  // The minimum of s: where its rate turns from falling to rising.
  double a = lo, b = hi;
  for (int k = 0; k < kBisections; ++k) {
    const double mid = 0.5 * (a + b);
    if (mid <= a || mid >= b) break;
    integrator.interpolate_rate(mid, ydot_.data());
    (switching_rate(l, ydot_.data()) < 0 ? a : b) = mid;
  }
  if (switching_at(integrator, l, b) > 0) return -1;
  ++grazes_;
  return bisect(integrator, l, lo, b);
}

bool LatchEvents::may_reach_zero(Integrator& integrator, int l, double lo, double hi) {
  const int d = integrator.interpolation_degree();
  if (!bound_ || bound_->degree() != d) {
    bound_.emplace(d);
    nodes_ready_ = false;
  }
  if (!nodes_ready_) {
    if (at_nodes_.size() != static_cast<std::size_t>(d + 1))
      at_nodes_.assign(d + 1, std::vector<double>(dynamics_.size()));
    at_nodes_[0] = y_lo_;
    at_nodes_[d] = y_hi_;
    for (int k = 1; k < d; ++k) integrator.interpolate(lo + bound_->node(k) * (hi - lo), at_nodes_[k].data());
    nodes_ready_ = true;
  }
  const Latch& latch = *dynamics_.latches()[l];
  const int c = dynamics_.layout().q() + dynamics_.model().position_of(latch.joint).value;
  Eigen::VectorXd s(d + 1);
  double size = std::abs(latch.position);
  for (int k = 0; k <= d; ++k) {
    s[k] = switching(l, at_nodes_[k].data());
    size = std::max(size, std::abs(at_nodes_[k][c]));
  }
  return bound_->lower_bound(s) <= kClearOfZero * size;
}

LatchGroup LatchEvents::find(Integrator& integrator, const StepOutcome& step) {
  LatchGroup group;
  const LatchState& state = dynamics_.latch_state();
  const int n = dynamics_.latch_count();
  auto in_group = [&](int l) {
    return std::any_of(group.roots.begin(), group.roots.end(), [l](const LatchRoot& r) { return r.latch == l; });
  };
  double first = std::numeric_limits<double>::infinity();
  if (step.status == StepStatus::root) {
    first = step.t;
    for (int l : integrator.roots())
      if (!state.engaged(l)) group.roots.push_back({l, step.t});
  } else {
    // Crossings the root finding cannot see: a graze, or one that ends
    // exactly at the step's end.
    const double lo = integrator.span_begin(), hi = step.t;
    if (!(hi > lo)) return group;
    integrator.interpolate(lo, y_lo_.data());
    integrator.interpolate(hi, y_hi_.data());
    integrator.interpolate_rate(lo, rate_lo_.data());
    integrator.interpolate_rate(hi, rate_hi_.data());
    nodes_ready_ = false;
    std::vector<LatchRoot> found;
    for (int l = 0; l < n; ++l) {
      if (state.engaged(l) || !(switching(l, y_lo_.data()) > 0)) continue;
      double t = -1;
      if (switching(l, y_hi_.data()) <= 0)
        t = bisect(integrator, l, lo, hi);
      else if (switching_rate(l, rate_lo_.data()) < 0 && switching_rate(l, rate_hi_.data()) > 0 &&
               may_reach_zero(integrator, l, lo, hi))
        t = graze(integrator, l, lo, hi);
      if (t >= 0) found.push_back({l, t});
    }
    if (found.empty()) return group;
    for (const LatchRoot& r : found) first = std::min(first, r.t);
    for (const LatchRoot& r : found)
      if (r.t <= first + window_) group.roots.push_back(r);
  }
  if (group.roots.empty()) return group;
  // Latches crossing within the window after the first, inside the step.
  const double limit = std::min(integrator.span_end(), first + window_);
  if (limit > first) {
    integrator.interpolate(limit, y_lo_.data());
    for (int l = 0; l < n; ++l) {
      if (state.engaged(l) || in_group(l) || switching(l, y_lo_.data()) > 0) continue;
      if (switching_at(integrator, l, first) <= 0) continue;
      group.roots.push_back({l, bisect(integrator, l, first, limit)});
    }
  }
  group.t_restart = first;
  for (const LatchRoot& r : group.roots) group.t_restart = std::max(group.t_restart, r.t);
  return group;
}

double LatchEvents::latch_torque(int l, double t, const double* y) {
  dynamics_.rhs(t, y, ydot_.data());
  const Latch& latch = *dynamics_.latches()[l];
  const PositionIndex c = dynamics_.model().position_of(latch.joint);
  const Positions q(y + dynamics_.layout().q()), q_dot(ydot_.data() + dynamics_.layout().q());
  return latch.torque(q[c], q_dot[c]);
}

void LatchEvents::engage(const LatchGroup& group, Integrator& integrator, double* y) {
  const StateLayout& L = dynamics_.layout();
  std::vector<double> impulse(group.roots.size(), 0.0);
  for (std::size_t k = 0; k < group.roots.size(); ++k) {
    const LatchRoot& r = group.roots[k];
    if (r.t >= group.t_restart) continue;
    integrator.interpolate(r.t, y_.data());
    const double at_root = latch_torque(r.latch, r.t, y_.data());
    const double at_restart = latch_torque(r.latch, group.t_restart, y);
    impulse[k] = 0.5 * (at_root + at_restart) * (group.t_restart - r.t);
  }
  for (std::size_t k = 0; k < group.roots.size(); ++k) {
    const int l = group.roots[k].latch;
    y[L.p() + dynamics_.model().velocity_of(dynamics_.latches()[l]->joint).value] += impulse[k];
    dynamics_.latch_state().engage(l);
  }
}

}  // namespace unfurl::sim
