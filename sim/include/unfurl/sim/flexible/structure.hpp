// A discretized elastic body: consistent mass and stiffness matrices over
// its nodal degrees of freedom, and where its nodes sit in the body frame.
// The plate and the beam (plate_structure.hpp, beam_structure.hpp) make
// one from section properties; modes and reductions read it.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace unfurl::sim::flexible {

struct Structure {
  Eigen::MatrixXd M, K;                // kg and N/m in a translation's units
  std::vector<Eigen::Vector3d> nodes;  // body frame, m
  int dofs_per_node = 0;
  // Each node's small translation and rotation (linear part first, as
  // spatial.hpp stacks them) from its degrees of freedom: 6 x
  // dofs_per_node, the same at every node.
  Eigen::MatrixXd node_motion;
  // The degrees of freedom of a small rigid motion of the whole structure
  // (linear part first, about the frame's origin): size() x 6. A
  // structure that does not model a motion (a plate's in-plane ones) has a
  // zero column for it.
  Eigen::MatrixXd rigid;

  int dof(int node, int component) const { return node * dofs_per_node + component; }
  // Every degree of freedom of the listed nodes (all of a clamp's).
  std::vector<int> dofs_of(const std::vector<int>& listed) const {
    std::vector<int> out;
    for (int node : listed)
      for (int k = 0; k < dofs_per_node; ++k) out.push_back(dof(node, k));
    return out;
  }
  int size() const { return static_cast<int>(M.rows()); }
};

}  // namespace unfurl::sim::flexible
