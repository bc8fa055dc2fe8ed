// Where the right-hand side is timed, for the scaling report and the
// benchmarks alike: the initial state moved off itself (joints turning,
// loops slightly open), the general case the integrators see.
#pragma once

#include <vector>

#include "unfurl/sim/dynamics.hpp"

namespace unfurl {

// The timing state; throws std::runtime_error when the right-hand side is
// not finite there.
std::vector<double> rhs_timing_state(Dynamics& dynamics);

}  // namespace unfurl
