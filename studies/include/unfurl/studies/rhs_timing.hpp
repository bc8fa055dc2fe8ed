// Where the right-hand side is timed, for the scaling report and the
// benchmarks alike: the initial state moved off itself (joints turning,
// loops slightly open), the general case the integrators see.
#pragma once

#include <vector>

#include "unfurl/sim/dynamics.hpp"

namespace unfurl::studies {

// Two timing states, their angles 1e-9 rad apart: timed calls alternate
// between them, because at a repeated q the sweep and the regulator keep
// what they computed (sweep.hpp), which a step of the integrator rarely
// sees. Throws std::runtime_error when the right-hand side is not finite
// there.
struct RhsTimingStates {
  std::vector<double> a, b;
  const std::vector<double>& operator[](long call) const { return call % 2 ? b : a; }
};
RhsTimingStates rhs_timing_states(sim::Dynamics& dynamics);

}  // namespace unfurl::studies
