// The rows of eps that carry a loop regulator: components of eps v that no
// motion can excite (a zero row of eps T A, such as the out-of-plane
// components of a planar loop) are left out. Products with eps on body
// velocities and forces, and the gap on the components kept.
#pragma once

#include <vector>

#include "unfurl/sim/loop.hpp"
#include "unfurl/sim/model.hpp"
#include "unfurl/sim/sweep.hpp"

namespace unfurl::sim {

// eps v on the active components, from body velocities (8).
void residual_rate(const std::vector<Loop>& loops, const std::vector<LoopComponent>& components,
                   const std::vector<Vec6>& v, double* g_dot);

// Adds eps^T lambda to the body forces, scaled: +scale lambda_c on the body's
// component, -scale lambda_c on the image's.
void add_loop_forces(const std::vector<Loop>& loops, const std::vector<LoopComponent>& components,
                     const double* lambda, double scale, std::vector<Vec6>& F);

// The rows of eps T A that are not identically zero, found from the rows at
// the initial coordinates and at random ones (sweep: scratch, any state);
// a linear component's row counts over the mechanism's `length`, so the
// cut-off does not depend on units.
std::vector<LoopComponent> active_loop_components(const Model& model, const std::vector<Loop>& loops,
                                                  const std::vector<double>& q0, double length, Sweep& sweep);

// g(q) of closure_mismatch() on the active components.
void geometric_gap(const std::vector<Loop>& loops, const std::vector<LoopComponent>& components,
                   const std::vector<Pose>& poses, double* g);

}  // namespace unfurl::sim
