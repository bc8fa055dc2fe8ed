// Where a body-frame point lies on a flexible plate: what it may attach
// to (the held root edge, the hinge line, a mesh node) or why it may not.
// One rule for the plate's reduction (plate_body), its frame (on_frame)
// and the scene reader's messages; defined with plate_body
// (flexible_body.cpp).
#pragma once

#include <Eigen/Core>

#include "unfurl/sim/flexible/flexible_body.hpp"

namespace unfurl::sim::flexible {

struct PlatePoint {
  enum class On { outside, root_edge, hinge_line, node, between_nodes };
  On on = On::outside;
  Eigen::Vector3d at = Eigen::Vector3d::Zero();  // plate coordinates, in its plane (a node's own position)
  int node = -1;                                  // the mesh node under it (On::node)

  bool attaches() const { return on == On::root_edge || on == On::hinge_line || on == On::node; }
};

// Within a billionth of the plate's size: over an edge's line, over a node.
PlatePoint locate(const PlateBodySpec& spec, const Eigen::Vector3d& point);

}  // namespace unfurl::sim::flexible
