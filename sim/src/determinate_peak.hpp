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
// counted as a run-up). A run that ends still rising ends on determinate
// loads, and keeps them.
#pragma once

#include <limits>

#include "unfurl/sim/loads.hpp"

namespace unfurl::sim {

class DeterminatePeak {
 public:
  void determinate(double x, double t) {
    if (leaving_ && x < previous_) {
      indeterminate_.update(x, t);
      previous_ = x;
      return;
    }
    leaving_ = false;
    if (x < previous_) settled_.update(run_up_.value, run_up_.t), run_up_ = {};
    run_up_.update(x, t);
    previous_ = x;
  }
  void indeterminate(double x, double t) {
    indeterminate_.update(run_up_.value, run_up_.t);
    indeterminate_.update(x, t);
    run_up_ = {}, leaving_ = true, previous_ = std::numeric_limits<double>::infinity();
  }
  // A latch engaged: the loads since the last fall are a maximum.
  void latched() {
    settled_.update(run_up_.value, run_up_.t);
    run_up_ = {}, leaving_ = false, previous_ = 0;
  }
  // Over the whole run, the run-up it ends on counted as determinate.
  Peak settled() const {
    Peak peak = settled_;
    peak.update(run_up_.value, run_up_.t);
    return peak;
  }
  const Peak& over_indeterminate_steps() const { return indeterminate_; }

 private:
  Peak settled_, run_up_, indeterminate_;
  double previous_ = 0;
  bool leaving_ = false;  // falling out of an indeterminate span
};

}  // namespace unfurl::sim
