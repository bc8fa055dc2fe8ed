// The integrators' state vector: (q, p) for a tree, (q, p, u) for a scene
// with loops (u: the regulator's state on the active loop components).
#pragma once

namespace unfurl::sim {

// Where each kind of state sits in the state vector.
// q has nq positions, p one momentum per velocity coordinate (nv); they
// differ only where a joint carries a quaternion.
struct StateLayout {
  int nq = 0;  // positions
  int nv = 0;  // velocity coordinates (momenta)
  int m = 0;   // active loop components
  int q() const { return 0; }
  int p() const { return nq; }
  int u() const { return nq + nv; }
  int size() const { return nq + nv + m; }
};

}  // namespace unfurl::sim
