// The clearance of a run of a scene file (studies/clearance.hpp), its
// bodies' solids from their collision shapes or their meshes, which the
// renderer's mesh reader reads where it is built.
#pragma once

#include <atomic>

#include "unfurl/sim/clearance_result.hpp"
#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/trajectory.hpp"
#include "unfurl/studies/body_solids.hpp"

namespace unfurl::app {

// The bodies' solids; meshes that cannot be had are named in `unread`.
studies::BodySolids scene_solids(const sim::Scene& scene, const sim::SceneVisuals& visuals,
                                 std::vector<std::string>* unread);

// Between the scene_solids, the meshes that could not be had named in
// `unread`. Stops where *cancel becomes true, incomplete
// (studies::check_clearance).
sim::Clearance run_clearance(const sim::Scene& scene, const studies::BodySolids& solids,
                             std::vector<std::string> unread, const sim::Trajectory& trajectory,
                             const std::atomic<bool>* cancel = nullptr);
// The same, the solids read first.
sim::Clearance run_clearance(const sim::Scene& scene, const sim::SceneVisuals& visuals,
                             const sim::Trajectory& trajectory, const std::atomic<bool>* cancel = nullptr);

}  // namespace unfurl::app
