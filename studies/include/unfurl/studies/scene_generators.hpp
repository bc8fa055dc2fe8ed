// Scenes of any size, built in code (SceneBuilder: validated as a file's
// are; write_scene_text makes their file): the pantograph with N panel
// pairs, the z-fold with N panels, and a plain chain of N links.
#pragma once

#include <string>
#include <vector>

#include "unfurl/sim/scene_file.hpp"

namespace unfurl::studies {

// How the pantograph's cross-links pivot: on rigid pins, each closing a loop
// through an image body and the regulator, or on compliant pins, bushings
// between full-mass panels that leave the mechanism a tree.
enum class CrossPivots { rigid, compliant };

// Whether a compliant or flexible array's stowed stack rests on snubbers:
// each hinge stopped at its stowed angle (a JointLimit as stiff as its
// latch), so it opens but never folds back into the stack. Without them the
// pins let the inner panels of a 10-stage array fold through the stowed
// lazy-tongs' branch point and hang up there, folded: compliant, within
// 2 s, 14 of 22 latches engaged; flexible, where the loops close through
// the plates' bending and compliant pivots, 10 of 22 in 20 s, hinges
// ending up to 0.13 rad past their stowed angle (with them 18 of 22: one
// pair per chain stays held 0.011 rad past its snubbers). The rigid loops
// hold every hinge on the lazy-tongs' path, which never folds back, so
// rigid arrays have none.
enum class Snubbers { stowed, none };

// Two chains of a frame and N panels cross-linked into a lazy-tongs with N
// loops; N = 3 is the reference `pantograph` (same bodies, joints, forces,
// numbering and initial state), or with compliant pivots and no snubbers
// `pantograph_compliant`.
sim::SceneFile generate_pantograph(int stages, CrossPivots pivots = CrossPivots::rigid,
                                   Snubbers snubbers = Snubbers::stowed);

// The pantograph with N pairs of flexible plate panels, its N loops closing
// through their bending at compliant cross pivots; N = 3 without snubbers
// is the built-in `pantograph_flexible`. Its springs, latches and pins are
// scaled with the size as the rigid and compliant arrays' are; its plates
// are the same panels at every size.
sim::SceneFile generate_flexible_pantograph(int stages, Snubbers snubbers = Snubbers::stowed);

// A generated scene by kind and size, as `unfurl generate` and Python's
// unfurl.generate name them: "pantograph" (stages; `compliant` or
// `flexible`, and a compliant or flexible one's `snubbers`), "zfold" (panels), "chain"
// (links), "rods" or "beam" (segments). Throws std::invalid_argument
// naming a bad kind, size or combination of options.
struct ArrayOptions {
  bool compliant = false, flexible = false, snubbers = true;
};
sim::SceneFile generate_scene(const std::string& kind, int size, const ArrayOptions& options = {});

// Chain A of the pantograph with N panels: a tree; N = 3 is `zfold`.
sim::SceneFile generate_zfold(int panels);

// A uniform beam in bending as N rigid segments hinged end to end with
// bending springs (the finite-segment, or lumped, model: segments of
// length l = L / N, each hinge's spring EI / l, the clamp's 2 EI / l as
// though the beam went on mirrored beyond it), cantilevered to a hub that
// turns about z; no gravity. By default Simo and Vu-Quoc's spin-up beam:
// L = 10 m, EI = 1.4e4 N m^2, rho A = 1.2 kg/m, the hub driven by a
// spin-up to 6 rad/s over 15 s. Being a chain of rigid bodies at large
// rotations, it carries the centrifugal stiffening a linear floating-frame
// model leaves out: the reference a flexible body's modes are checked
// against.
struct BeamSpec {
  double length = 10;                // m
  double bending_stiffness = 1.4e4;  // EI, N m^2
  double mass_per_length = 1.2;      // rho A, kg/m
  double spin_rate = 6;              // rad/s, the hub's final rate
  double spin_up_time = 15;          // s
};
sim::SceneFile generate_beam(int segments, const BeamSpec& spec = {});

// N identical links hinged end to end about x, hanging under gravity with
// light damping, released from a bent shape: a tree for scaling runs.
sim::SceneFile generate_chain(int links);

// Two equal cranks on the ground, joined by N parallel rods (a multiple
// parallelogram), swung by a torsion spring on the first crank through
// their flat position, where the mobility jumps to N + 1, twice a period:
// one degree of freedom, N - 1 redundant loop components everywhere. The
// rods translate, so the inertia is constant and the cranks' angle is a
// cosine; no gravity, no damping.
sim::SceneFile generate_parallel_rods(int rods);
// The closed form: each joint's angle at time t (the cranks at theta(t),
// the rods and their images turned back by as much).
std::vector<double> parallel_rods_angles(const sim::Scene& scene, double t);

}  // namespace unfurl::studies
