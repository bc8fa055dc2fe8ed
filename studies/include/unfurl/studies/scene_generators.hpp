// Scenes of any size, built in code (SceneBuilder: validated as a file's
// are; write_scene_text makes their file): the pantograph with N panel
// pairs, the z-fold with N panels, and a plain chain of N links.
#pragma once

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

}  // namespace unfurl::studies
