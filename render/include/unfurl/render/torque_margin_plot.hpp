// The torque margin plot: each driven joint's motorization factor over its
// travel, along the run (solid) and quasi-statically (dashed), against the
// required factor, on a log axis. From margins already computed
// (sim::torque_margins); the renderer never calls the solver.
#pragma once

#include <string>
#include <vector>

#include "unfurl/render/plot.hpp"
#include "unfurl/sim/torque_margin_result.hpp"

namespace unfurl::render {

PlotSpec torque_margin_plot(const std::string& scene_name, const std::vector<sim::JointTorqueMargin>& margins,
                            const sim::TorqueMarginFactors& factors);

}  // namespace unfurl::render
