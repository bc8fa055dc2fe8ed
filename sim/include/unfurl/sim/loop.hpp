// Closed loops (section 3): each loop is opened by splitting a body; its
// image hangs on another branch. eps has +1 at the body and -1 at the image,
// so eps v is the difference of their velocities (each in its own frame,
// frames that coincide while the loop is closed). This header holds what a
// loop is and its geometry; loop_components.hpp the passes over eps.
#pragma once

#include <string>

#include "unfurl/sim/kinematics.hpp"

namespace unfurl::sim {

struct Loop {
  std::string name;
  int body = 0;   // the split body (eps = +1)
  int image = 0;  // its image on another branch (eps = -1)
};

// One row of eps: a spatial component (0-2 linear, 3-5 angular) of a loop.
struct LoopComponent {
  int loop = 0;
  int axis = 0;
};

// The true geometric closure error of a loop: distance between the origins
// of the body and its image, and angle between their frames.
struct ClosureError {
  double distance = 0;
  double angle = 0;
};
ClosureError closure_error(const Pose& body, const Pose& image);

// The loop's true geometric gap g(q), what eps pi of (9) stands for: the
// body origin's offset from the image's (body frame) and the rotation
// vector (quaternion log) of the image frame relative to the body frame.
// Where the loop is closed its rate is eps v of (8); unlike eps pi it is a
// function of q, so an integration error in q cannot hide from it.
Vec6 closure_mismatch(const Pose& body, const Pose& image);

}  // namespace unfurl::sim
