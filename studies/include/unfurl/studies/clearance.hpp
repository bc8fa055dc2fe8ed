// The clearance between a run's bodies not jointed together (a joint, a
// loop's split body or a bushing holds them at a pivot where they meet by
// design): the smallest distance between their solids over the run and
// when, for every pair that comes near (the others certified farther
// apart), and every span in which two touched or interpenetrated.
//
// The distances are the Flexible Collision Library's (FCL, Debian's
// libfcl-dev): exact between boxes, spheres, cylinders and triangle meshes,
// with bounding-volume hierarchies that make a mesh's query cost grow with
// the log of its triangles. Only pairs whose swept bounding boxes come
// within a margin are measured at all (clearance_broad_phase.hpp): a tenth
// of the largest body's reach, doubled until it holds the closest pair.
// Most of their queries are never made either: a pair whose last
// measured distance exceeds how far its bodies can have moved since (the
// chord of each body's origin plus its reach times the angle turned,
// sample to sample) is certified clear. Where two measured samples do not
// certify the path between them, it is bisected on the trajectory's
// interpolation, and each pair's closest sample is refined there
// (golden-section search on the interpolated motion).
//
// A mesh is a surface: a solid wholly inside another without their surfaces
// crossing is not seen. A primitive pair's interpenetration depth is not
// reported; contact is.
#pragma once

#include <atomic>

#include "unfurl/sim/clearance_result.hpp"
#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/trajectory.hpp"
#include "unfurl/studies/body_solids.hpp"

namespace unfurl::studies {

// Throws std::invalid_argument when `solids` are not the scene's bodies'.
// Where *cancel becomes true it stops between pairs, its result incomplete
// (for a caller that discards it).
sim::Clearance check_clearance(const sim::Scene& scene, const BodySolids& solids, const sim::Trajectory& trajectory,
                               const std::atomic<bool>* cancel = nullptr);

}  // namespace unfurl::studies
