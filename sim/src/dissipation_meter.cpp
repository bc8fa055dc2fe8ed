#include "dissipation_meter.hpp"

#include <cmath>

namespace unfurl::sim {

namespace {

bool has_dissipation(const Scene& scene) {
  for (const auto& e : scene.elements)
    if (e->dissipative()) return true;
  return false;
}

}  // namespace

DissipationMeter::DissipationMeter(Dynamics& dynamics, double t0)
    : dynamics_(dynamics),
      dissipative_(has_dissipation(dynamics.scene())),
      driven_(dynamics.has_drivers()),
      t_(t0),
      y_(dynamics.layout().size()),
      ydot_(dynamics.layout().size()) {}

void DissipationMeter::advance(Integrator& integrator, double t) {
  if (!(dissipative_ || driven_) || !(t > t_)) {
    t_ = std::max(t_, t);
    return;
  }
  const double half = 0.5 * (t - t_), mid = 0.5 * (t + t_);
  const double node = std::sqrt(0.6);
  const double nodes[3] = {-node, 0.0, node};
  const double weights[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  double sum = 0, drive_sum = 0;
  for (int k = 0; k < 3; ++k) {
    const double t_k = mid + half * nodes[k];
    integrator.interpolate(t_k, y_.data());
    integrator.interpolate_rate(t_k, ydot_.data());
    if (dissipative_)
      sum +=
          weights[k] * dynamics_.dissipation(y_.data() + dynamics_.layout().q(), ydot_.data() + dynamics_.layout().q());
    if (driven_) drive_sum += weights[k] * dynamics_.drive_power(t_k, y_.data());
  }
  work_ += half * sum;
  drive_work_ += half * drive_sum;
  t_ = t;
}

}  // namespace unfurl::sim
