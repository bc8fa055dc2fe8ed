// Where a run raised its tolerances to the right-hand side's round-off
// (roundoff_guard.hpp in the sources).
#pragma once

namespace unfurl::sim {

struct ToleranceRaise {
  double t = 0;      // s
  double floor = 0;  // roundoff_floor.hpp's measure at t
  double rtol = 0;   // the tolerances from t on
  double atol = 0;
};

}  // namespace unfurl::sim
