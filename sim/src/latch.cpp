#include "unfurl/sim/latch.hpp"

namespace unfurl {

LatchState::LatchState(const std::vector<Latch>& latches, const std::vector<double>& q0_of_latch)
    : side_(latches.size()), position_(latches.size()), engaged_(latches.size(), 0) {
  for (std::size_t l = 0; l < latches.size(); ++l) {
    const double offset = q0_of_latch[l] - latches[l].position;
    side_[l] = offset >= 0 ? 1.0 : -1.0;
    position_[l] = latches[l].position;
    engaged_[l] = offset == 0 ? 1 : 0;
  }
}

double LatchState::switching_value(int l, double q) const {
  return engaged_[l] ? 1.0 : side_[l] * (q - position_[l]);
}

int LatchState::engaged_count() const {
  int n = 0;
  for (char e : engaged_) n += e;
  return n;
}

}  // namespace unfurl
