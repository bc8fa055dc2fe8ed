// The reports' plots, drawn by the renderer: error against run time
// (work-precision, one curve per integrator on log-log axes), markered
// measurements, and PNG files of plot specs.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "unfurl/render/plot.hpp"
#include "unfurl/studies/work_precision.hpp"

namespace unfurl::app {

enum class PrecisionMeasure { angle_error, final_error, latch_time_error };

// `measure` against the median wall time, one curve per integrator (the
// settings that finished and measured something).
render::PlotSpec work_precision_plot(const studies::WorkPrecision& report, PrecisionMeasure measure);

// Measured points as markered curves, one per label, in the palette's order.
std::vector<render::Series> marked_series(std::map<std::string, render::Series> curves);

// Draws each plot at 1280x720 (taller for a chart of more than 24 named
// rows) in an offscreen context and writes it as a PNG in dir; returns the
// file names.
std::vector<std::string> write_plot_pngs(const std::vector<std::pair<render::PlotSpec, std::string>>& plots,
                                         const std::string& dir);

}  // namespace unfurl::app
