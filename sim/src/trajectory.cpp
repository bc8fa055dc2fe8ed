#include "unfurl/sim/trajectory.hpp"

#include <algorithm>

#include "hermite.hpp"

namespace unfurl::sim {

void Trajectory::coordinates_at(double t, std::vector<double>& q) const {
  q.resize(layout.nq);
  if (samples.empty()) return;
  if (t <= samples.front().t || samples.size() == 1) {
    std::copy_n(samples.front().y.begin() + layout.q(), layout.nq, q.begin());
    return;
  }
  if (t >= samples.back().t) {
    std::copy_n(samples.back().y.begin() + layout.q(), layout.nq, q.begin());
    return;
  }
  const auto after = std::upper_bound(samples.begin(), samples.end(), t,
                                      [](double x, const Sample& s) { return x < s.t; });
  const Sample& b = *after;
  const Sample& a = *(after - 1);
  const Hermite span{a.t, b.t};
  for (int c = 0; c < layout.nq; ++c)
    q[c] = span.value(a.y[layout.q() + c], a.q_dot[c], b.y[layout.q() + c], b.q_dot[c], t);
}

const Sample& Trajectory::sample_at(double t) const {
  const auto after = std::upper_bound(samples.begin(), samples.end(), t,
                                      [](double x, const Sample& s) { return x < s.t; });
  return after == samples.begin() ? samples.front() : *(after - 1);
}

}  // namespace unfurl::sim
