// The reports' plots: error against run time (work-precision), one curve
// per integrator on log-log axes.
#pragma once

#include "plot.hpp"
#include "work_precision.hpp"

namespace unfurl::render {

enum class PrecisionMeasure { angle_error, final_error, latch_time_error };

// `measure` against the median wall time, one curve per integrator (the
// settings that finished and measured something).
PlotSpec work_precision_plot(const WorkPrecision& report, PrecisionMeasure measure);

}  // namespace unfurl::render
