#include "summary.hpp"

#include <algorithm>
#include <limits>

namespace unfurl {

RunSummary summarize(const Scene& scene, const RunResult& result) {
  RunSummary s;
  const Model& model = scene.model;
  const Trajectory& tr = result.trajectory;
  double first_latch = std::numeric_limits<double>::infinity();
  for (const LatchEvent& e : tr.events) {
    s.latch_times.emplace_back(model.joints[e.joint].name, e.t);
    first_latch = std::min(first_latch, e.t);
  }
  for (int l = 0; l < static_cast<int>(scene.latches.size()); ++l) {
    const bool engaged = std::any_of(tr.events.begin(), tr.events.end(),
                                     [&](const LatchEvent& e) { return e.latch == l; });
    if (!engaged) s.unlatched.push_back(model.joints[scene.latches[l].joint].name);
  }
  for (const Sample& sample : tr.samples) {
    for (const ClosureError& c : sample.closure) {
      s.max_closure_m = std::max(s.max_closure_m, c.distance);
      s.max_closure_rad = std::max(s.max_closure_rad, c.angle);
      if (sample.t > first_latch) continue;
      s.max_closure_m_before_latch = std::max(s.max_closure_m_before_latch, c.distance);
      s.max_closure_rad_before_latch = std::max(s.max_closure_rad_before_latch, c.angle);
    }
  }
  if (!tr.empty()) {
    s.energy_initial = tr.samples.front().energy.total();
    s.energy_final = tr.samples.back().energy.total();
    s.t_reached = tr.samples.back().t;
    for (int c = 0; c < model.nq; ++c)
      s.final_q.emplace_back(model.joints[model.joint_of_coordinate[c]].name, tr.samples.back().y[tr.layout.q() + c]);
  }
  return s;
}

}  // namespace unfurl
