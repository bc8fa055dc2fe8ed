// Natural frequencies, damping ratios and mode shapes of a scene linearized
// about a state, by default the static equilibrium nearest it (the deployed,
// latched array at rest).
//
// The linearization is in independent coordinates: on a mechanism with
// loops, the velocity coordinates w = T z with T a basis of the loops'
// admissible motions (the null space of their Jacobian G, every direction
// with a first-order gap constrained), orthonormal in the mass metric
// (T^T M T = I); without loops T = L^-T (M = L L^T). The loops are closed by
// the rigid model's loop forces, not the regulator, and a perturbed state is
// put back on the loops' manifold (minimum-norm correction in the mass
// metric), so the reduced stiffness carries the loop forces' geometric
// part. With z'' = f(z, z'):
//   K = -df/dz,  C = -df/dz'  (central differences, steps of 1e-6 rad or
//   1e-6 of the mechanism's length, and 1e-6 of its rate: unit-invariant)
// and the modes are those of z'' + C z' + K z = 0 with K symmetrized: the
// undamped frequencies and shapes from K phi = omega^2 phi, each mode's
// damping ratio from its modal damping phi^T C phi / (2 omega), exact where
// the damping is proportional (the usual modal damping; the coupling that
// non-proportional damping adds between modes is left out, and with a
// spinning base the gyroscopic coupling is). K's asymmetry (forces that are
// not conservative: a follower load) is reported. Coulomb friction, which
// sticks at rest, enters as its smoothed law's slope, a stiff damper.
//
// Drivers (joint_driver.hpp) hold their joints: the modes are those of the
// other coordinates, about a state where no driver is moving.
//
// A free-floating base has six rigid-body modes (frequency 0); a rigid
// mechanism at a branch point, or a joint nothing holds, has mechanism
// modes, whose frequency is 0 to first order: their stiffness, if any, is
// of higher order, and compliance determines it.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/simulation.hpp"

namespace unfurl::sim {

// unstable: a state the stiffness drives away from (negative omega^2): its
// frequency_hz is the negative growth rate over 2 pi.
enum class ModeKind { elastic, rigid_body, mechanism, unstable };
const char* mode_kind_name(ModeKind kind);

struct Mode {
  ModeKind kind = ModeKind::elastic;
  double frequency_hz = 0;         // undamped natural frequency
  double damping_ratio = 0;        // modal, phi^T C phi / (2 omega)
  double damped_frequency_hz = 0;  // frequency_hz sqrt(1 - zeta^2); 0 when zeta >= 1
  // Per velocity coordinate (Model::velocity_name), the largest entry +1 in
  // the coordinates' own sizes (an angle in rad, a length over the
  // mechanism's length).
  Eigen::VectorXd shape;
};

struct ModesSettings {
  bool settle = true;  // first solve for the static equilibrium near the given state
};

struct ModesResult {
  std::vector<double> q;        // the positions linearized about
  std::vector<bool> engaged;    // each latch's state there
  int coordinates = 0;          // velocity coordinates that move (not those drivers hold)
  int loop_rank = 0;            // independent loop constraints there
  // Of those, how many hold only weakly: the state is near a branch point
  // of the loops (where the loads are indeterminate), and the rigid
  // model's modes depend on how near; compliance determines them.
  int weak_loop_directions = 0;
  int settle_iterations = 0;
  // How far the state is from its static equilibrium: the largest
  // coordinate of K^-1 f(0), in rad (a length over the mechanism's length).
  double equilibrium_offset = 0;
  double stiffness_asymmetry = 0;  // ||K - K^T|| / ||K + K^T||
  double length = 1;               // the mechanism's length, m (shapes' lengths are over it)
  std::vector<Mode> modes;         // rigid-body and mechanism modes first, then by frequency
};

// The modes at positions q with the latches `engaged` (one per latch).
// Throws std::runtime_error where no linearization can be made (loops
// beyond the dense analysis, an evaluation that fails, a state off its
// loops).
ModesResult linear_modes(const Scene& scene, const std::vector<double>& q, const std::vector<bool>& engaged,
                         const ModesSettings& settings = {});

// A state to linearize about: positions and each latch's state.
struct LinearizationState {
  std::vector<double> q;
  std::vector<bool> engaged;
  double t = 0;  // where a run's state was taken
};
// A run's state at time t (its last sample where t is beyond it), with the
// latches that had engaged by then.
LinearizationState state_of_run(const Scene& scene, const Trajectory& run, double t);
// Given positions, with the latches engaged whose joints are at or past
// their positions (on the side away from where they start).
LinearizationState given_state(const Scene& scene, const std::vector<double>& q);

// Mode k (0-based) drawn as a motion, for pictures: q(t) = q (+) a sin(2 pi
// t / period) shape, put back on the loops, at samples + 1 instants over
// one period; a in rad (the shape's largest entry; a length over the
// mechanism's length). The linear mode at a visible amplitude, not a run.
Trajectory mode_animation(const Scene& scene, const ModesResult& modes, int k, double amplitude, double period,
                          int samples);

// Positions q displaced along velocity coordinates x (q (+) x: a joint's
// rates integrated for unit time to first order, quaternions normalized).
std::vector<double> displaced_positions(const Model& model, const std::vector<double>& q, const Eigen::VectorXd& x);

}  // namespace unfurl::sim
