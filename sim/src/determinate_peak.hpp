// A reaction's peak over the steps where the rigid model determines it. A
// determinate peak must be a maximum the rigid model reaches: a load still
// rising when its steps turn indeterminate (a toggle closing on its branch
// point, where the rigid load grows as 1/distance) is not bounded by the
// rigid model. Where that run-up stops is where the regulator departs from
// the rigid loads, which its regularization and gains set: 326 .. 1640 N on
// the broken-spring pantograph over regularization 2e-5 .. 2e-8. So the
// values since the load last fell are held until it falls again (then they
// are a maximum) or the steps turn indeterminate (then they count with the
// indeterminate peak, as the approach to it). Likewise a load falling out of
// an indeterminate span counts there until it first rises. A latch's
// engagement ends a run-up: it changes the model, so the loads up to it are
// the rigid model's maximum of the motion before it, wherever the
// regulator departs after (an asymmetric latch-up next to the deployed
// branch point: 117.80 / 117.72 / 117.59 N at regularization 2e-7 / 2e-6 /
// 2e-5 on a Monte Carlo draw, against 56.10 / 56.10 / 51.22 N left if it
// counted as a run-up); it also ends a fall out of a span, the latch's
// impact being the rigid model's. A run that ends still rising keeps that
// run-up as determinate; one that failed there (the regulator lost a loop
// closing on a toggle) does not. A maximum between three determinate steps
// counts at its interpolated value (StepMaximum).
#pragma once

#include <cmath>
#include <limits>
#include <optional>

#include "step_maximum.hpp"
#include "unfurl/sim/loads.hpp"

namespace unfurl::sim {

class DeterminatePeak {
 public:
  // A step's load x at t, and whether the rigid model determined it there.
  void observe(double x, double t, bool determinate) {
    const std::optional<Peak> between = determinate ? between_.observe(t, x) : std::nullopt;
    if (!determinate) {
      between_.restart();
      merge(indeterminate_, run_up_);
      merge(indeterminate_, {x, t});
      run_up_ = {}, leaving_ = true, previous_ = std::numeric_limits<double>::infinity();
    } else if (leaving_ && x < previous_) {
      merge(indeterminate_, {x, t});
    } else if (x > previous_) {
      leaving_ = false;
      merge(run_up_, {x, t});
    } else {  // flat or falling: what rose before it is a maximum, and so is x
      leaving_ = false;
      settle();
      merge(settled_, {x, t});
      if (between) merge(settled_, *between);  // a rise, then x: not leaving a span
    }
    if (determinate) previous_ = x;
  }
  // A latch engaged: the loads since the last fall are a maximum.
  void latched() {
    between_.restart();
    settle();
    leaving_ = false, previous_ = 0;
  }
  // Over the whole run; `completed`: whether it went on to its end, so that
  // a run-up it ends on is the rigid model's.
  Peak settled(bool completed) const {
    Peak peak = settled_;
    if (completed) merge(peak, run_up_);
    return peak;
  }
  Peak over_indeterminate_steps(bool completed) const {
    Peak peak = indeterminate_;
    if (!completed) merge(peak, run_up_);
    return peak;
  }

 private:
  static void merge(Peak& into, const Peak& peak) {
    if (!std::isnan(peak.t)) into.update(peak.value, peak.t);
  }
  void settle() {
    merge(settled_, run_up_);
    run_up_ = {};
  }
  Peak settled_, run_up_, indeterminate_;
  StepMaximum between_;
  double previous_ = 0;
  bool leaving_ = false;  // falling out of an indeterminate span
};

}  // namespace unfurl::sim
