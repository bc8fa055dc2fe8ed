// Scenes of any size, built in code (SceneBuilder: validated as a file's
// are; write_scene_text makes their file): the pantograph with N panel
// pairs, the z-fold with N panels, and a plain chain of N links.
#pragma once

#include <vector>

#include "unfurl/sim/scene_file.hpp"

namespace unfurl::studies {

// Two chains of a frame and N panels cross-linked into a lazy-tongs with N
// loops; N = 3 is the reference `pantograph` (same bodies, joints, forces,
// numbering and initial state).
sim::SceneFile generate_pantograph(int stages);

// Chain A of the pantograph with N panels: a tree; N = 3 is `zfold`.
sim::SceneFile generate_zfold(int panels);

// N identical links hinged end to end about x, hanging under gravity with
// light damping, released from a bent shape: a tree for scaling runs.
sim::SceneFile generate_chain(int links);

// Two equal cranks on the ground, joined by N parallel rods (a multiple
// parallelogram), swung by a torsion spring on the first crank through
// their flat position, where the mobility jumps to N + 1, twice a period:
// one degree of freedom, N - 1 redundant loop components everywhere. The
// rods translate, so the inertia is constant and the cranks' angle is a
// cosine; no gravity, no damping.
sim::SceneFile generate_parallel_rods(int rods);
// The closed form: each joint's angle at time t (the cranks at theta(t),
// the rods and their images turned back by as much).
std::vector<double> parallel_rods_angles(const sim::Scene& scene, double t);

}  // namespace unfurl::studies
