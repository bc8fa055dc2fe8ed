#include "unfurl/render/torque_margin_plot.hpp"

#include <algorithm>
#include <cmath>

namespace unfurl::render {

PlotSpec torque_margin_plot(const std::string& scene_name, const std::vector<sim::JointTorqueMargin>& margins,
                            const sim::TorqueMarginFactors& factors) {
  PlotSpec spec;
  spec.title = scene_name + ": motorization factor over each driven joint's travel";
  spec.x_label = "travel from the stowed angle to the latch, fraction";
  spec.y_label = "motorization factor (run solid, quasi-static dashed)";
  spec.log_y = true;
  // Over the travel's fraction, so joints of every range share the axis.
  double lo = factors.required, hi = factors.required;
  for (std::size_t k = 0; k < margins.size(); ++k) {
    const sim::JointTorqueMargin& m = margins[k];
    if (m.quasi_static.size() < 2) continue;
    const double start = m.quasi_static.front().q, end = m.quasi_static.back().q;
    for (const bool run : {true, false}) {
      Series s;
      s.label = m.joint + (run ? "" : " (quasi-static)");
      s.color = palette(static_cast<int>(k));
      s.dashed = !run;
      for (const sim::TorqueMarginPoint& p : run ? m.run : m.quasi_static) {
        if (!std::isfinite(p.factor) || p.factor <= 0) continue;
        s.x.push_back((p.q - start) / (end - start));
        s.y.push_back(p.factor);
        lo = std::min(lo, p.factor), hi = std::max(hi, p.factor);
      }
      if (!s.x.empty()) spec.series.push_back(std::move(s));
    }
  }
  Series required;
  required.label = "required";
  required.x = {0, 1};
  required.y = {factors.required, factors.required};
  required.color = IM_COL32(60, 60, 60, 255);
  spec.series.push_back(std::move(required));
  return spec;
}

}  // namespace unfurl::render
