#include "report_plots.hpp"

#include "unfurl/io/png_file.hpp"
#include "unfurl/render/gl_context.hpp"
#include "unfurl/render/plot_renderer.hpp"

#include <cmath>

namespace unfurl::app {

namespace {

double measured(const studies::PrecisionPoint& p, PrecisionMeasure measure) {
  switch (measure) {
    case PrecisionMeasure::angle_error:
      return p.angle_error;
    case PrecisionMeasure::final_error:
      return p.final_error;
    case PrecisionMeasure::latch_time_error:
      return p.latch_time_error;
  }
  return studies::kNotMeasured;
}

}  // namespace

render::PlotSpec work_precision_plot(const studies::WorkPrecision& report, PrecisionMeasure measure) {
  render::PlotSpec spec;
  spec.log_x = spec.log_y = true;
  spec.x_label = "wall time, s (median)";
  switch (measure) {
    case PrecisionMeasure::angle_error:
      spec.title = report.scene + ": joint-angle error against run time";
      spec.y_label = "max |q - q_ref|, rad";
      break;
    case PrecisionMeasure::final_error:
      spec.title = report.scene + ": final-state error against run time";
      spec.y_label = "max |q(t_end) - q_ref(t_end)|, rad";
      break;
    case PrecisionMeasure::latch_time_error:
      spec.title = report.scene + ": latch-time error against run time";
      spec.y_label = "max |t_latch - t_ref|, s";
      break;
  }
  const auto& kinds = sim::all_integrators();
  for (std::size_t k = 0; k < kinds.size(); ++k) {
    render::Series s;
    s.label = sim::integrator_name(kinds[k]);
    s.color = render::palette(static_cast<int>(k));
    s.markers = true;
    for (const studies::PrecisionPoint& p : report.points) {
      const double y = measured(p, measure);
      if (p.integrator != kinds[k] || !std::isfinite(y)) continue;
      // An exact match (0) sits at the bottom of a log axis, not off it.
      s.x.push_back(p.wall_time_s);
      s.y.push_back(std::max(y, 1e-16));
    }
    if (!s.x.empty()) spec.series.push_back(std::move(s));
  }
  return spec;
}

std::vector<render::Series> marked_series(std::map<std::string, render::Series> curves) {
  std::vector<render::Series> out;
  int color = 0;
  for (auto& [label, s] : curves) {
    s.label = label;
    s.color = render::palette(color++);
    s.markers = true;
    out.push_back(std::move(s));
  }
  return out;
}

std::vector<std::string> write_plot_pngs(const std::vector<std::pair<render::PlotSpec, std::string>>& plots,
                                         const std::string& dir) {
  auto context = render::make_offscreen_context();
  render::PlotRenderer plotter(1280, 720);
  render::Image image;
  std::vector<std::string> files;
  for (const auto& [spec, name] : plots) {
    // A chart of named rows grows to give each its line.
    const int rows = static_cast<int>(spec.y_categories.size());
    if (rows > 24) {
      render::PlotRenderer tall(1280, 160 + 24 * rows);
      tall.draw(spec, image);
    } else {
      plotter.draw(spec, image);
    }
    io::write_png(image, dir + "/" + name, 6);
    files.push_back(name);
  }
  return files;
}

}  // namespace unfurl::app
