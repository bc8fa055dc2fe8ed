// A scene: the mechanism (tree, forces, latches, loops, regulator), its
// initial state, how to run it, and what the renderer draws for each body.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "forces.hpp"
#include "latch.hpp"
#include "loops.hpp"
#include "model.hpp"
#include "regulator.hpp"

namespace unfurl {

enum class IntegratorKind { cvode_bdf, cvode_adams, arkode_erk, arkode_dirk, rk4 };

// How the implicit integrators solve their Newton systems: a dense
// finite-difference Jacobian and LU (O(n^3) per setup), or GMRES with an
// O(N) preconditioner (newton_preconditioner.hpp). automatic: dense up to
// kDenseStatesUpTo states.
enum class LinearSolverKind { automatic, dense, krylov };
inline constexpr int kDenseStatesUpTo = 100;

const char* integrator_name(IntegratorKind kind);
// Parses "cvode-bdf" etc.; nullopt for an unknown name.
std::optional<IntegratorKind> parse_integrator(const std::string& name);
const std::vector<IntegratorKind>& all_integrators();

struct RunSettings {
  double t_end = 10;
  IntegratorKind integrator = IntegratorKind::cvode_bdf;
  double rtol = 1e-8;
  double atol = 1e-10;  // for q; see tolerances.hpp for the other states
  LinearSolverKind linear_solver = LinearSolverKind::automatic;
  double dt = 1e-4;     // step of the fixed-step RK4
  double sample = 0.01; // output interval
  long max_steps = 50'000'000;
  // The run fails ("time budget") when it has taken longer than this, in
  // seconds of wall time; 0: no limit.
  double max_wall_time = 0;
  // The run fails when a loop's geometric gap exceeds this (m or rad), at
  // the end of any step: the regulator has lost the loop.
  double max_closure = 0.1;
  // Latches whose roots follow the first within this many seconds engage in
  // one restart, each at its own root (latch_events.hpp).
  double event_window = 1e-6;
};

// What the renderer draws for a body: a mesh from assets/meshes, scaled,
// then turned about an axis, then offset, in the body frame.
struct Visual {
  std::string mesh;
  Vec3 scale = Vec3::Ones();
  Vec3 rotation_axis = Vec3::UnitZ();
  double rotation_deg = 0;
  Vec3 offset = Vec3::Zero();
};

struct Scene {
  std::string name;
  std::string description;
  std::string source;  // the file it came from, or "built-in"
  Model model;
  std::vector<JointSpring> springs;  // the file's springs, then its dampers
  std::size_t dampers_from = 0;      // springs[dampers_from..] came from `dampers:`
  std::vector<BodyLoad> loads;
  std::vector<Latch> latches;
  std::vector<Loop> loops;
  RegulatorSettings regulator;
  std::vector<double> q0;     // per coordinate
  std::vector<double> dq0;    // per coordinate (used when p0 is empty)
  std::vector<double> p0;     // per coordinate, optional
  double closure_tolerance = 1e-6;  // how far the initial loops may be open
  RunSettings run;
  Visual base_visual;
  std::vector<Visual> visuals;  // per body
};

}  // namespace unfurl
