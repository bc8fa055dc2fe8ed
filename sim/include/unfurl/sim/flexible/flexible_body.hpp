// A flexible body as the solver carries it (docs/FLEXIBLE.md): its
// floating frame's inertia invariants, the modal stiffness and damping of
// its m elastic coordinates eta (unit modal masses), and the nodes its
// children hang on, each with its small translation and rotation per unit
// eta. Made once from a mesh and a reduction (beam_body, plate_body);
// shared, immutable, by every copy of a scene.
#pragma once

#include <Eigen/Core>
#include <limits>
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

// Each elastic coordinate's modal damping ratio: one for all, by bands of
// the coordinate's frequency (the frame held), or one per coordinate. Bands
// are how Adams damps a flexible body by default (1 % below 100 Hz, 10 %
// below 1 kHz, critical above: FLEX_BODY's CRATIO), so that the stiff
// constraint modes kept for their compliance do not ring at kHz and set
// the step size; the structural modes keep a measured, low ratio.
struct DampingBand {
  double up_to_hz = std::numeric_limits<double>::infinity();
  double ratio = 0;
};

struct ModalDamping {
  std::vector<DampingBand> bands{{std::numeric_limits<double>::infinity(), kDefaultDampingRatio}};  // ascending
  std::vector<double> per_coordinate;  // instead of the bands, when given

  static ModalDamping uniform(double zeta) { return {{{std::numeric_limits<double>::infinity(), zeta}}, {}}; }
  bool is_uniform() const { return per_coordinate.empty() && bands.size() == 1; }
  // Coordinate k's ratio, its frequency f_hz.
  double ratio(int k, double f_hz) const;
};

// What a beam body was made from (a scene file's `flexible: {beam: ...}`),
// kept so that the scene writes back and its parameters edit and re-run
// like any other.
struct BeamBodySpec {
  BeamSection section;
  int normal_modes = 4;
  ModalDamping damping;
  // Body-frame points where children and sensors attach. Each becomes an
  // interface node at the mesh node its projection on the axis falls on;
  // its distance from the axis is a rigid bracket (a hinge's pivot line
  // off a panel's mid-plane).
  std::vector<Eigen::Vector3d> attachments;
  // The foreshortening that stiffens a spinning beam; off only to show the
  // plain linear floating-frame model's spurious softening.
  bool geometric_stiffening = true;
  // Where the beam starts (held to the frame: the frame's attachment) and
  // which body axis it runs along (0 x, 1 y, 2 z). Its section's first and
  // second transverse axes are the next two body axes in cyclic order, so
  // bending_stiffness_y is about axis + 1 and bending_stiffness_z about
  // axis + 2: a panel along y in the xy-plane bends out of its plane about
  // x, with bending_stiffness_z.
  Eigen::Vector3d root = Eigen::Vector3d::Zero();
  int axis = 0;
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

  // The body-frame direction of the beam's axis, and the distance along it
  // from the root of a body-frame point.
  Eigen::Vector3d axis() const { return Eigen::Vector3d::Unit(beam.axis); }
  double station(const Eigen::Vector3d& p) const { return axis().dot(p - beam.root); }
  // The node attachment `point` hangs on, or -1.
  int node_of(const Eigen::Vector3d& point) const;

  // The largest translation of a mesh node at deformation eta.
  double largest_deflection(const double* eta) const;

  int modes() const { return static_cast<int>(stiffness.size()); }
};

// A beam from spec.root along body axis spec.axis, held at the root (the
// frame's attachment), with `attachments` as interface nodes,
// `normal_modes` fixed-interface modes and the attachments' constraint
// modes, damped as spec.damping says; the foreshortening carried. Each
// attachment becomes a node at the mesh node nearest its projection.
// Throws std::invalid_argument when more coordinates result than
// kMaxModes, a point lies beyond the beam's ends, or the damping ratios
// given one per coordinate are not one per coordinate.
FlexibleBody beam_body(const BeamBodySpec& spec);

// The same beam in units whose lengths are L times and masses M times
// larger, time unchanged (studies::scale_scene): the frequencies and mode
// shapes' forms stay, the elastic coordinates (m kg^0.5) grow by L sqrt(M).
BeamBodySpec scaled(const BeamBodySpec& spec, double L, double M);
inline FlexibleBody beam_body(const BeamSection& section, int normal_modes, double zeta,
                              const std::vector<Eigen::Vector3d>& attachments) {
  return beam_body(BeamBodySpec{section, normal_modes, ModalDamping::uniform(zeta), attachments});
}

}  // namespace unfurl::sim::flexible
