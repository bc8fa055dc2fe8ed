// Scenes of any size, written as scene-file text (so they load, validate
// and save exactly like hand-written ones): the pantograph with N panel
// pairs, the z-fold with N panels, and a plain chain of N links.
#pragma once

#include <string>

namespace unfurl {

// Two chains of a frame and N panels cross-linked into a lazy-tongs with N
// loops; N = 3 is the reference `pantograph` (same bodies, joints, forces,
// numbering and initial state).
std::string generate_pantograph(int stages);

// Chain A of the pantograph with N panels: a tree; N = 3 is `zfold`.
std::string generate_zfold(int panels);

// N identical links hinged end to end about x, hanging under gravity with
// light damping, released from a bent shape: a tree for scaling runs.
std::string generate_chain(int links);

}  // namespace unfurl
