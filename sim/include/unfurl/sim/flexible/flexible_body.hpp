// A flexible body as the solver carries it (docs/FLEXIBLE.md): its
// floating frame's inertia invariants, the modal stiffness and damping of
// its m elastic coordinates eta (unit modal masses), and the nodes its
// children hang on, each with its small translation and rotation per unit
// eta. Made once from a mesh and a reduction (beam_body, plate_body);
// shared, immutable, by every copy of a scene.
#pragma once

#include <Eigen/Core>
#include <array>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "unfurl/sim/flexible/beam_structure.hpp"
#include "unfurl/sim/flexible/fem_model.hpp"
#include "unfurl/sim/flexible/inertia_invariants.hpp"
#include "unfurl/sim/flexible/plate_structure.hpp"

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
  // Ascending. (Filled, not listed: GCC 12 misreads a copied initializer
  // list here as maybe uninitialized.)
  std::vector<DampingBand> bands =
      std::vector<DampingBand>(1, DampingBand{std::numeric_limits<double>::infinity(), kDefaultDampingRatio});
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
  // Where positive, instead of normal_modes: every fixed-interface mode up
  // to this frequency (Hz), the scene's `modes: {up_to: F}`.
  double modes_up_to_hz = 0;
};

// A plate's edges: x = 0, x = length_x, y = 0, y = length_y (its own
// axes, plate_structure.hpp).
enum class PlateEdge { x0, x1, y0, y1 };

// What a plate body was made from (a scene file's `flexible: {plate:
// ...}`): a Kirchhoff plate (plate_structure.hpp says why) held along one
// edge, its inboard hinge line, to its frame, with its other hinge lines
// tied rigid in themselves.
struct PlateBodySpec {
  PlateSpec plate;
  // Young's modulus and the thickness that gave the bending stiffness (D =
  // E t^3 / (12 (1 - nu^2))) where the file gave them, else 0: kept so that
  // the scene writes back as written and edits the parameter it has.
  double youngs_modulus = 0, thickness = 0;
  int normal_modes = 4;
  ModalDamping damping;
  // Body-frame points where children, sensors and elements attach: on a
  // hinge line (anywhere along it, or on a rigid bracket beside it) or at
  // a mesh node (or a bracket beside one), which becomes an interface node.
  std::vector<Eigen::Vector3d> attachments;
  // The plate's corner x = y = 0 in the body frame, and the body axis its
  // normal runs along (0 x, 1 y, 2 z): its own x and y are the next two
  // body axes in cyclic order.
  Eigen::Vector3d corner = Eigen::Vector3d::Zero();
  int normal = 2;
  // The edge tied rigid to the frame (the frame's attachment: the inboard
  // hinge line, as the rigid model's joint holds it), and edges tied rigid
  // in themselves (outboard hinge lines: three constraint modes each,
  // where a single node's own degrees of freedom would take four and a
  // line of them dozens).
  PlateEdge root_edge = PlateEdge::y0;
  std::vector<PlateEdge> hinge_lines;
  // Where the plate is fastened to its hinge pins, at the root edge and
  // the hinge line alike (one list for both edges, a tied tip edge
  // included): spans [from, to] along them (m, from the edge's end at the
  // plate's corner), each holding at least one mesh node.
  // Empty: the whole edge. The pins themselves stay rigid along the whole
  // line; between brackets the plate's edge is free.
  std::vector<std::array<double, 2>> brackets;
  double modes_up_to_hz = 0;  // as a beam's
};

// What a body read from a reduced finite-element model was made from (a
// scene file's `flexible: {fem: file}`, fem_model.hpp): its modes must
// hold the body where its frame attaches (Craig-Bampton's fixed-interface
// and constraint modes with the inboard hinge's nodes held), as the
// plate's and the beam's do, and its node coordinates are the body
// frame's.
struct FemBodySpec {
  std::string file;  // as the scene resolved it
  std::shared_ptr<const FemModel> model;
  // The lowest this many of the file's coordinates (orthonormalized),
  // or where modes_up_to_hz is positive every one up to it; neither: all.
  int normal_modes = 0;
  double modes_up_to_hz = 0;
  ModalDamping damping;
  // Where the scene gives no damping and the file has a modal damping
  // matrix: its diagonal in the orthonormalized coordinates.
  bool damping_from_file = false;
  // Body-frame points where children, sensors and elements attach: each at
  // a node of the model, or at the frame's origin.
  std::vector<Eigen::Vector3d> attachments;
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
  // (a plate's, along its x first: (elements_x + 1) (elements_y + 1)).
  std::vector<FlexibleNode> mesh_nodes;
  // What the body was made from: a beam, or where `plate` or `fem` is
  // set a plate or an FE model (the beam's spec then unused).
  BeamBodySpec beam;
  std::optional<PlateBodySpec> plate;
  std::optional<FemBodySpec> fem;  // where set, the beam's and the plate's unused

  // The body-frame direction of the beam's axis, and the distance along it
  // from the root of a body-frame point.
  Eigen::Vector3d axis() const { return Eigen::Vector3d::Unit(beam.axis); }
  double station(const Eigen::Vector3d& p) const { return axis().dot(p - beam.root); }
  // The node attachment `point` hangs on, or -1.
  int node_of(const Eigen::Vector3d& point) const;
  // Whether `point` moves rigidly with the frame: the beam's root, a point
  // over the plate's held edge.
  bool on_frame(const Eigen::Vector3d& point) const;
  // The largest dimension: the scale of the body's points' tolerances.
  double size() const;

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
// A plate held along spec.root_edge (the frame's attachment), its hinge
// lines tied, every other attachment an interface node at the mesh node
// under it; `normal_modes` fixed-interface modes and the ties' and nodes'
// constraint modes, damped as spec.damping says. No foreshortening: a
// plate's stiffening by in-plane inertia loads is a membrane effect,
// negligible at deployment rates (mass_points.hpp). Throws
// std::invalid_argument as beam_body does, and for a point neither on a
// hinge line nor over a mesh node.
FlexibleBody plate_body(const PlateBodySpec& spec);
PlateBodySpec scaled(const PlateBodySpec& spec, double L, double M);
// A body from a reduced FE model: its inertia, the modal mass included,
// summed from the lumped masses at its nodes moved by the file's mode
// shapes, its stiffness the file's modal stiffness, its coordinates
// orthonormalized with them; `attachments` at its nodes. Throws
// std::invalid_argument for a model that is not one (a rigid motion among
// its modes, modal matrices that are not symmetric and positive definite),
// and as beam_body does.
FlexibleBody fem_body(const FemBodySpec& spec);
// (The scaled spec keeps the file's path: written back, a scaled scene
// reads the unscaled model; scale_scene is the studies' unit check.)
FemBodySpec scaled(const FemBodySpec& spec, double L, double M);

// Where a body-frame point lies in a plate's own axes (x, y in its plane,
// z off it).
Eigen::Vector3d plate_coordinates(const PlateBodySpec& spec, const Eigen::Vector3d& point);

inline FlexibleBody beam_body(const BeamSection& section, int normal_modes, double zeta,
                              const std::vector<Eigen::Vector3d>& attachments) {
  return beam_body(BeamBodySpec{section, normal_modes, ModalDamping::uniform(zeta), attachments});
}

}  // namespace unfurl::sim::flexible
