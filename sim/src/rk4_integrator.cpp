#include "rk4_integrator.hpp"

#include <cmath>

#include "hermite.hpp"

namespace unfurl::sim {

Rk4Integrator::Rk4Integrator(Dynamics& dynamics, const RunSettings& settings, double t0,
                             const std::vector<double>& y0)
    : dynamics_(dynamics),
      dt_(settings.dt),
      t_grid0_(t0),
      y0_(y0),
      f0_(y0.size()),
      y1_(y0),
      f1_(y0.size()),
      k2_(y0.size()),
      k3_(y0.size()),
      k4_(y0.size()),
      tmp_(y0.size()),
      s0_(dynamics.latch_count()),
      s1_(dynamics.latch_count()) {
  restart(t0, y0.data());
}

void Rk4Integrator::restart(double t, const double* y) {
  t0_ = t1_ = t;
  std::copy(y, y + y0_.size(), y0_.begin());
  y1_ = y0_;
  dynamics_.rhs(t, y0_.data(), f0_.data());
  f1_ = f0_;
  dynamics_.switching_functions(y0_.data(), s0_.data());
  s1_ = s0_;
}

bool Rk4Integrator::take_step(double h) {
  const std::size_t n = y0_.size();
  auto stage = [&](const std::vector<double>& k, double c, std::vector<double>& out) {
    for (std::size_t j = 0; j < n; ++j) tmp_[j] = y0_[j] + c * h * k[j];
    return dynamics_.rhs(t0_ + c * h, tmp_.data(), out.data());
  };
  bool ok = stage(f0_, 0.5, k2_) && stage(k2_, 0.5, k3_) && stage(k3_, 1.0, k4_);
  for (std::size_t j = 0; j < n; ++j) y1_[j] = y0_[j] + h / 6 * (f0_[j] + 2 * k2_[j] + 2 * k3_[j] + k4_[j]);
  t1_ = t0_ + h;
  ok = ok && dynamics_.rhs(t1_, y1_.data(), f1_.data());
  dynamics_.switching_functions(y1_.data(), s1_.data());
  ++stats_.steps;
  stats_.last_step = h;
  return ok;
}

double Rk4Integrator::earliest_crossing(std::vector<int>& which) {
  // Bisection on each crossing switching function's interpolant.
  double t_root = t1_;
  const int nq_offset = dynamics_.layout().q();
  for (int l = 0; l < dynamics_.latch_count(); ++l) {
    if (!(s0_[l] > 0 && s1_[l] <= 0)) continue;
    const int c = nq_offset + dynamics_.model().position_of(dynamics_.latches()[l]->joint).value;
    const Hermite step{t0_, t1_};
    auto value = [&](double t) {
      return dynamics_.latch_state().switching_value(l, step.value(y0_[c], f0_[c], y1_[c], f1_[c], t));
    };
    double lo = t0_, hi = t1_;
    for (int it = 0; it < 60 && hi - lo > 1e-15 * std::max(1.0, std::abs(hi)); ++it) {
      const double mid = 0.5 * (lo + hi);
      (value(mid) > 0 ? lo : hi) = mid;
    }
    const double tol = 1e-15 * std::max(1.0, std::abs(t_root));
    if (hi < t_root - tol) {
      which.clear();
      t_root = hi;
    }
    if (std::abs(hi - t_root) <= tol) which.push_back(l);
  }
  return t_root;
}

StepOutcome Rk4Integrator::step(double t_stop) {
  StepOutcome out;
  // Restart from the end of the last step.
  if (t1_ != t0_) {
    t0_ = t1_;
    y0_.swap(y1_);
    f0_.swap(f1_);
    s0_.swap(s1_);
  }
  const double k = std::floor((t0_ - t_grid0_) / dt_ + 1e-9) + 1;
  const double t_next = std::min(t_grid0_ + k * dt_, t_stop);
  if (!take_step(t_next - t0_)) {
    out.status = StepStatus::failed;
    out.t = t0_;
    out.reason = "the right-hand side is not finite (step too large for this scene?)";
    t1_ = t0_;
    return out;
  }
  roots_.clear();
  bool crossed = false;
  for (int l = 0; l < dynamics_.latch_count(); ++l) crossed = crossed || (s0_[l] > 0 && s1_[l] <= 0);
  if (crossed) {
    out.status = StepStatus::root;
    out.t = earliest_crossing(roots_);
    return out;
  }
  out.t = t1_;
  out.status = t1_ >= t_stop ? StepStatus::reached_stop : StepStatus::advanced;
  return out;
}

void Rk4Integrator::interpolate(double t, double* y) {
  if (t1_ == t0_) {
    std::copy(y1_.begin(), y1_.end(), y);
    return;
  }
  const Hermite step{t0_, t1_};
  for (std::size_t j = 0; j < y0_.size(); ++j) y[j] = step.value(y0_[j], f0_[j], y1_[j], f1_[j], t);
}

void Rk4Integrator::interpolate_rate(double t, double* ydot) {
  if (t1_ == t0_) {
    std::copy(f1_.begin(), f1_.end(), ydot);
    return;
  }
  const Hermite step{t0_, t1_};
  for (std::size_t j = 0; j < y0_.size(); ++j) ydot[j] = step.rate(y0_[j], f0_[j], y1_[j], f1_[j], t);
}

}  // namespace unfurl::sim
