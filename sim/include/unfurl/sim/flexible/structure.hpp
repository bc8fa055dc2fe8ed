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

  int dof(int node, int component) const { return node * dofs_per_node + component; }
  int size() const { return static_cast<int>(M.rows()); }
};

}  // namespace unfurl::sim::flexible
