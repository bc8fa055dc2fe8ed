#include "trajectory.hpp"

#include <algorithm>

namespace unfurl {

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
  const double h = b.t - a.t, s = (t - a.t) / h;
  const double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s);
  const double h01 = s * s * (3 - 2 * s), h11 = s * s * (s - 1);
  for (int c = 0; c < layout.nq; ++c)
    q[c] = h00 * a.y[layout.q() + c] + h10 * h * a.dq[c] + h01 * b.y[layout.q() + c] + h11 * h * b.dq[c];
}

}  // namespace unfurl
