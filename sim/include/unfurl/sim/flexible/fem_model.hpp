// A reduced finite-element model as an FE tool exports it, in MBDyn's
// modal data file layout (the ".fem" file of its modal joint; written by
// MBDyn's femgen from NASTRAN's OUTPUT4 blocks, and by other pre-processors):
// plain text in numbered record groups, each headed by a line
// "** RECORD GROUP n, ...", other "**" lines comments:
//    1  header: revision, nodes, normal, attachment and constraint modes,
//       rejected modes (the modes are the sum of the three counts less
//       the rejected ones)
//    2  the nodes' labels
//    3, 4  initial modal displacements and velocities (read, not used:
//       a scene starts its bodies undeformed and at rest)
//    5, 6, 7  the nodes' x, y and z (the body frame)
//    8  the mode shapes: per mode (rejected ones first, skipped), per node,
//       its translation and rotation (6 numbers)
//    9, 10  the modal mass and stiffness matrices (modes square)
//    11  the diagonal of the lumped mass matrix: per node, 3 masses (equal)
//       and 3 moments of inertia, none negative
//    12  the rigid body's mass, centre of mass and inertia about it (its
//       mass and centre checked against the lumped masses')
//    13  the modal damping matrix
//    14 and up  MBDyn's precomputed inertia invariants (skipped: unfurl sums
//       its own from the lumped masses)
// docs/FLEXIBLE.md says how a body is made from one.
#pragma once

#include <Eigen/Core>
#include <stdexcept>
#include <string>
#include <vector>

namespace unfurl::sim::flexible {

struct FemModel {
  std::vector<std::string> labels;  // record group 2
  Eigen::Matrix3Xd points;          // 5-7: body frame
  // 8: node k's translation (rows 6k .. 6k+2) and rotation (6k+3 .. 6k+5)
  // per unit of each mode (columns).
  Eigen::MatrixXd shapes;
  Eigen::MatrixXd mass, stiffness;  // 9, 10
  Eigen::MatrixXd damping;          // 13, or empty
  // 11: per node (columns), its masses along x, y, z and its moments of
  // inertia about x, y, z.
  Eigen::Matrix<double, 6, Eigen::Dynamic> lumped;

  int nodes() const { return static_cast<int>(points.cols()); }
  int modes() const { return static_cast<int>(mass.rows()); }
  // The nodes' largest extent: the scale of the model's tolerances.
  double size() const;
  // The node at a body-frame point (within 1e-6 of the size), or -1.
  int node_at(const Eigen::Vector3d& point) const;
  // Whether something may attach at a body-frame point: at a node, or at
  // the frame's origin (the held attachment's own point).
  bool attaches(const Eigen::Vector3d& point) const;
};

// A line of the file that is not what its record group holds.
class FemFileError : public std::runtime_error {
 public:
  FemFileError(const std::string& path, int line, const std::string& what)
      : std::runtime_error(path + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + what) {}
};

// Reads a modal data file; throws FemFileError naming the file, the line
// and what was expected there. Record groups 1, 2, 5-11 are required.
FemModel read_fem(const std::string& path);
// The same from text (`path` names it in errors).
FemModel read_fem_text(const std::string& text, const std::string& path);

}  // namespace unfurl::sim::flexible
