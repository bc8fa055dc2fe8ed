// The right-hand side allocates nothing: malloc is counted around rhs()
// calls of the pantograph (loops, full-matrix regulator, latches engaged),
// the z-fold and a gravity scene, and around the Krylov solvers' Jacobian
// products and preconditioner solves. glibc lets a program interpose malloc.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>

#include "newton_preconditioner.hpp"
#include "support.hpp"
#include "unfurl/sim/dynamics.hpp"

extern "C" {
void* __libc_malloc(size_t);
void* __libc_calloc(size_t, size_t);
void* __libc_realloc(void*, size_t);
void* __libc_memalign(size_t, size_t);

static std::atomic<long> allocations{0};

void* malloc(size_t n) {
  allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_malloc(n);
}
void* calloc(size_t n, size_t size) {
  allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_calloc(n, size);
}
void* realloc(void* p, size_t n) {
  allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_realloc(p, n);
}
void* aligned_alloc(size_t alignment, size_t n) {
  allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_memalign(alignment, n);
}
int posix_memalign(void** out, size_t alignment, size_t n) {
  allocations.fetch_add(1, std::memory_order_relaxed);
  *out = __libc_memalign(alignment, n);
  return *out ? 0 : 12;
}
}

namespace unfurl {
namespace {

// A generic state: moving, loops slightly open.
std::vector<double> generic_state(sim::Dynamics& dynamics) {
  std::vector<double> y = dynamics.initial_state();
  for (double& x : y) x += 1e-3;
  return y;
}

long allocations_in_rhs(const sim::Scene& scene, bool engage_latches) {
  sim::Dynamics dynamics(scene);
  std::vector<double> y = generic_state(dynamics), ydot(y.size());
  if (engage_latches)
    for (int l = 0; l < dynamics.latch_count(); ++l) dynamics.latch_state().engage(l);
  dynamics.rhs(0, y.data(), ydot.data());  // warm-up
  const long before = allocations.load();
  for (int k = 0; k < 10; ++k) dynamics.rhs(0, y.data(), ydot.data());
  return allocations.load() - before;
}

// The Krylov solvers' J v at one base (as GMRES asks): with the gains
// held, the sparse solver does not factor (the one step that allocates).
long allocations_in_jacobian_times(const sim::Scene& scene) {
  sim::Dynamics dynamics(scene);
  std::vector<double> y = generic_state(dynamics), v(y.size(), 1.0), Jv(y.size());
  dynamics.rhs(0, y.data(), Jv.data());
  dynamics.jacobian_times(0, y.data(), v.data(), Jv.data());  // warm-up
  const long before = allocations.load();
  for (int k = 0; k < 10; ++k) {
    dynamics.jacobian_times(0, y.data(), v.data(), Jv.data());
    v[k % v.size()] += 1;
  }
  return allocations.load() - before;
}

// GMRES applies the preconditioner once per iteration, several times per
// Newton matrix; only its setup (the loops' sparse factorizations) may
// allocate. gamma as at a mid-length step, where the regulator's two
// poles are apart (both factorizations in use).
long allocations_in_preconditioner_solves(const sim::Scene& scene) {
  sim::Dynamics dynamics(scene);
  std::vector<double> y = generic_state(dynamics), f(y.size()), r(y.size(), 1.0), z(y.size());
  dynamics.rhs(0, y.data(), f.data());
  sim::NewtonPreconditioner& preconditioner = dynamics.preconditioner();
  preconditioner.setup(y.data(), f.data(), 1e-3);
  preconditioner.solve(r.data(), z.data());  // warm-up
  const long before = allocations.load();
  for (int k = 0; k < 10; ++k) {
    preconditioner.solve(r.data(), z.data());
    r[k % r.size()] += 1;
  }
  return allocations.load() - before;
}

TEST(RightHandSide, CountsAllocationsAtAll) {
  // The counter works: a vector allocates.
  const long before = allocations.load();
  std::vector<double>* v = new std::vector<double>(100);
  delete v;
  EXPECT_GE(allocations.load() - before, 1);
}

TEST(RightHandSide, PantographAllocatesNothing) {
  EXPECT_EQ(allocations_in_rhs(test::scene_file("pantograph"), true), 0);
}

TEST(RightHandSide, PaperTuningAllocatesNothing) {
  EXPECT_EQ(allocations_in_rhs(test::scene_file("pantograph", {{"regulator.gains", "paper"}}), false), 0);
}

TEST(RightHandSide, ZfoldAllocatesNothing) {
  EXPECT_EQ(allocations_in_rhs(test::scene_file("zfold"), true), 0);
}

// A free joint at the root (6 x 6 D_0) and the regulator's load-case passes
// through it; a ball and a planar joint.
TEST(RightHandSide, FreeFloatingPantographAllocatesNothing) {
  EXPECT_EQ(allocations_in_rhs(test::scene_file("pantograph_free"), true), 0);
}

TEST(RightHandSide, BallAndPlanarJointsAllocateNothing) {
  EXPECT_EQ(allocations_in_rhs(test::scene_file("ball_pendulum"), false), 0);
}

TEST(RightHandSide, JacobianProductsAllocateNothing) {
  EXPECT_EQ(allocations_in_jacobian_times(test::scene_file("pantograph")), 0);
  EXPECT_EQ(allocations_in_jacobian_times(test::scene_file("pantograph", {{"regulator.solver", "sparse"}})), 0);
}

// The drivers' rates and accelerations, in the right-hand side and its
// Jacobian products.
TEST(RightHandSide, ADrivenCrankAllocatesNothing) {
  const sim::Scene fourbar =
      test::scene_file("fourbar", {{"drivers", "[{joint: crank_pivot, profile: spin_up, amount: 3, duration: 1}]"}});
  EXPECT_EQ(allocations_in_rhs(fourbar, true), 0);
  EXPECT_EQ(allocations_in_jacobian_times(fourbar), 0);
}

// A flexible beam on a driven hub: the extended (6 + m) passes.
TEST(RightHandSide, AFlexibleBeamAllocatesNothing) {
  const sim::Scene spinup = test::scene_file("spinup_beam");
  EXPECT_EQ(allocations_in_rhs(spinup, false), 0);
  EXPECT_EQ(allocations_in_jacobian_times(spinup), 0);
}

// Forces at a flexible body's points: gravity on its deformed mass, and a
// damped point spring, a bushing and an applied force at its tip's node.
TEST(RightHandSide, ForcesOnAFlexibleBeamAllocateNothing) {
  const sim::Scene spinup = test::scene_file(
      "spinup_beam",
      {{"gravity", "[0, 0, -9.81]"},
       {"point_springs",
        "[{body_a: ground, point_a: [10, 0, -1], body_b: beam, point_b: [10, 0, 0], stiffness: 10, rest_length: 1, "
        "damping: 1}]"},
       {"bushings",
        "[{name: prop, body_a: ground, point_a: [10, 0, 0], body_b: beam, point_b: [10, 0, 0], "
        "stiffness: [0, 0, 10, 0, 0, 0], damping: [0, 0, 1, 0, 0, 0]}]"},
       {"applied_forces", "[{body: beam, point: [10, 0, 0], force: [0, 0, -1], frame: base}]"}});
  EXPECT_EQ(allocations_in_rhs(spinup, false), 0);
  EXPECT_EQ(allocations_in_jacobian_times(spinup), 0);
}

// A flexible boom (read from an FE model) on a compliant hinge: the
// extended passes over the joint's six coordinates, its axes turning.
TEST(RightHandSide, AFlexibleBoomOnACompliantHingeAllocatesNothing) {
  const sim::Scene boom =
      sim::load_scene_file(std::string(UNFURL_SOURCE_DIR) + "/examples/fem/magnetometer_boom.yaml",
                           {{"bodies.boom.joint.compliance", "{radial: 1.0e6, axial: 1.0e6, tilt: 1.0e4}"}});
  ASSERT_TRUE(boom.model.joints[0].compliant);
  EXPECT_EQ(allocations_in_rhs(boom, false), 0);
  EXPECT_EQ(allocations_in_jacobian_times(boom), 0);
}

// The loops' share (full tuning), the free bus, a tree with bushings (no
// loops: the tree's passes alone), and the compliant pins and plates of
// the flexible panels.
TEST(NewtonPreconditioner, SolvesAllocateNothing) {
  EXPECT_EQ(allocations_in_preconditioner_solves(test::scene_file("pantograph")), 0);
  EXPECT_EQ(allocations_in_preconditioner_solves(test::scene_file("pantograph_free")), 0);
  EXPECT_EQ(allocations_in_preconditioner_solves(test::scene_file("pantograph_compliant")), 0);
  EXPECT_EQ(allocations_in_preconditioner_solves(test::scene_file("pantograph_flexible")), 0);
}

TEST(RightHandSide, GravitySceneAllocatesNothing) {
  EXPECT_EQ(allocations_in_rhs(test::scene_file("double_pendulum"), false), 0);
}

}  // namespace
}  // namespace unfurl
