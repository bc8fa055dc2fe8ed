// The integrators' state vector: (q, p) for a tree, (q, p, u) for a scene
// with loops (u: the regulator's state on the active loop components).
#pragma once

namespace unfurl {

// Where each kind of state sits in the state vector.
struct StateLayout {
  int nq = 0;  // coordinates
  int m = 0;   // active loop components
  int q() const { return 0; }
  int p() const { return nq; }
  int u() const { return 2 * nq; }
  int size() const { return 2 * nq + m; }
};

}  // namespace unfurl
