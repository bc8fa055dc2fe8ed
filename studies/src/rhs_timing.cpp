#include "unfurl/studies/rhs_timing.hpp"

#include <stdexcept>

namespace unfurl {

std::vector<double> rhs_timing_state(Dynamics& dynamics) {
  std::vector<double> y = dynamics.initial_state(), ydot(y.size());
  for (double& x : y) x += 1e-3;
  if (!dynamics.rhs(0, y.data(), ydot.data()))
    throw std::runtime_error(dynamics.scene().name + ": the right-hand side is not finite at the timing state");
  return y;
}

}  // namespace unfurl
