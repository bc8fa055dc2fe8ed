// A rectangular plate in bending, meshed with Bogner-Fox-Schmit elements:
// the Kirchhoff (thin-plate) model, bicubic Hermite in x and y with w,
// w_x, w_y and w_xy at each node. Kirchhoff rather than Mindlin because a
// deployable panel is thin for its bending waves: a honeycomb sandwich of
// 20 mm over a 1 m span has its first modes' transverse-shear correction
// below 1 % (D pi^2 / (S a^2) with the core's shear stiffness S), and the
// conforming element converges from above, monotonically, at fourth order
// in the frequencies. In-plane stretching is left out: it is stiffer than
// bending by (a / h)^2.
//
// The plate lies in the body frame's xy-plane, x in [0, length_x], y in
// [0, length_y]; w is along z. Nodes are numbered along x first.
#pragma once

#include <vector>

#include "unfurl/sim/flexible/structure.hpp"

namespace unfurl::sim::flexible {

struct PlateSpec {
  double length_x = 1, length_y = 1;  // m
  double bending_stiffness = 1;       // D, N m
  double poisson = 0.3;
  double mass_per_area = 1;  // kg/m^2
  int elements_x = 8, elements_y = 8;
};

// The degrees of freedom at each node, in order.
enum PlateDof { plate_w = 0, plate_w_x, plate_w_y, plate_w_xy };

Structure plate_structure(const PlateSpec& spec);

enum class EdgeSupport { free, simply_supported, clamped };

struct PlateEdges {
  EdgeSupport x0 = EdgeSupport::free, x1 = EdgeSupport::free;  // the edges x = 0 and x = length_x
  EdgeSupport y0 = EdgeSupport::free, y1 = EdgeSupport::free;
};

// The degrees of freedom the supports hold at zero: along a simply
// supported edge w and its slope along the edge, along a clamped one all
// four.
std::vector<int> held_dofs(const PlateSpec& spec, const PlateEdges& edges);

}  // namespace unfurl::sim::flexible
