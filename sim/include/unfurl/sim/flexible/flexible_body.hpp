// A flexible body as the solver carries it (docs/FLEXIBLE.md): its
// floating frame's inertia invariants, the modal stiffness and damping of
// its m elastic coordinates eta (unit modal masses), and the nodes its
// children hang on, each with its small translation and rotation per unit
// eta. Made once from a mesh and a reduction (beam_body, plate_body);
// shared, immutable, by every copy of a scene.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "unfurl/sim/flexible/beam_structure.hpp"
#include "unfurl/sim/flexible/inertia_invariants.hpp"

namespace unfurl::sim::flexible {

// The largest number of elastic coordinates a body may keep: the sweep's
// extended blocks are fixed-size (6 + kMaxModes square) so that it
// allocates nothing.
inline constexpr int kMaxModes = 24;
inline constexpr int kMaxExtended = 6 + kMaxModes;
// A flexible body's extended vectors and matrices (its frame's 6 and its
// elastic coordinates): dynamic sizes up to kMaxExtended, stored in place.
using ExtendedVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxExtended, 1>;
using ExtendedMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxExtended, kMaxExtended>;
using NodeMatrix = Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, kMaxExtended>;

// The modal damping ratio when a scene gives none: 0.5 %, the second and
// third modes' on-orbit values measured on a solar array paddle (MOS-1,
// NASDA, 1985: 1.1 %, 0.4 %, 0.45 % for its first three modes). Low, so
// that the latch-up shock is not understated.
inline constexpr double kDefaultDampingRatio = 0.005;

// What a beam body was made from (a scene file's `flexible: {beam: ...}`),
// kept so that the scene writes back and its parameters edit and re-run
// like any other.
struct BeamBodySpec {
  BeamSection section;
  int normal_modes = 4;
  double damping_ratio = kDefaultDampingRatio;
  std::vector<Eigen::Vector3d> attachments;
  // The foreshortening that stiffens a spinning beam; off only to show the
  // plain linear floating-frame model's spurious softening.
  bool geometric_stiffening = true;
};

struct FlexibleNode {
  Eigen::Vector3d point;                         // body frame, undeformed
  Eigen::Matrix<double, 6, Eigen::Dynamic> shape;  // translation, then rotation, per unit eta
};

struct FlexibleBody {
  InertiaInvariants inertia;
  Eigen::VectorXd frequency_hz;  // of each coordinate, the frame held
  Eigen::VectorXd stiffness;     // omega_k^2, 1/s^2 (the coordinates have unit modal masses)
  Eigen::VectorXd damping;       // 2 zeta_k omega_k
  std::vector<FlexibleNode> nodes;
  // Every node of the structure's mesh, for the drawing and the deflection.
  std::vector<FlexibleNode> mesh_nodes;
  BeamBodySpec beam;

  // The largest translation of a mesh node at deformation eta.
  double largest_deflection(const double* eta) const;

  int modes() const { return static_cast<int>(stiffness.size()); }
};

// A beam along x from the frame's origin, held there (the frame's
// attachment), with `attachments` (body-frame points on the beam's axis)
// as interface nodes, `normal_modes` fixed-interface modes and the
// attachments' constraint modes, each with damping ratio `zeta`; the
// foreshortening carried. Each attachment becomes a node at the mesh node
// nearest it. Throws std::invalid_argument when more coordinates result
// than kMaxModes or a point lies off the beam.
FlexibleBody beam_body(const BeamBodySpec& spec);
inline FlexibleBody beam_body(const BeamSection& section, int normal_modes, double zeta,
                              const std::vector<Eigen::Vector3d>& attachments) {
  return beam_body(BeamBodySpec{section, normal_modes, zeta, attachments});
}

}  // namespace unfurl::sim::flexible
