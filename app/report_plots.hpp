// The reports' plots: error against run time (work-precision), one curve
// per integrator on log-log axes.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "plot.hpp"
#include "work_precision.hpp"

namespace unfurl::render {

enum class PrecisionMeasure { angle_error, final_error, latch_time_error };

// `measure` against the median wall time, one curve per integrator (the
// settings that finished and measured something).
PlotSpec work_precision_plot(const WorkPrecision& report, PrecisionMeasure measure);

// Measured points as markered curves, one per label, in the palette's order.
std::vector<Series> marked_series(std::map<std::string, Series> curves);

}  // namespace unfurl::render
