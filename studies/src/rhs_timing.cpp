#include "unfurl/studies/rhs_timing.hpp"

#include <stdexcept>

namespace unfurl::studies {

RhsTimingStates rhs_timing_states(sim::Dynamics& dynamics) {
  RhsTimingStates states;
  std::vector<double>& y = states.a;
  y = dynamics.initial_state();
  std::vector<double> ydot(y.size());
  for (double& x : y) x += 1e-3;
  states.b = y;
  const sim::StateLayout& L = dynamics.layout();
  for (int c = 0; c < L.nq; ++c) states.b[L.q() + c] += 1e-9;
  for (const std::vector<double>* state : {&states.a, &states.b})
    if (!dynamics.rhs(0, state->data(), ydot.data()))
      throw std::runtime_error(dynamics.scene().name + ": the right-hand side is not finite at the timing state");
  return states;
}

}  // namespace unfurl::studies
