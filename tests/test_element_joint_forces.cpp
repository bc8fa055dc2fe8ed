// Dynamics::element_joint_forces, which the torque margins ask for at every
// sample and at 101 angles per driven joint, carries each element's wrenches
// straight to the joints above their bodies. Checked against two other
// formulations: the sweep's force pass (Q = A^T T^T F, every body, one
// element at a time) on every element of every built-in scene, flexible
// bodies, multi-axis joints and a steadily moving base included; and, for
// the compliant pantograph's bushings, the fall of their stored energy as
// each hinge turns.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "unfurl/sim/dynamics.hpp"
#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/sweep.hpp"

namespace unfurl {
namespace {

// A state off the scene's start: every coordinate moved a little, every
// rate set, both reproducibly.
struct State {
  std::vector<double> q, w;
};
State state_off_start(const sim::Scene& scene) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> offset(-0.1, 0.1);
  State s{scene.q0, std::vector<double>(scene.model.nv)};
  for (double& x : s.q) x += offset(random);
  for (double& x : s.w) x = 10 * offset(random);
  return s;
}

// The joint coordinates (elastic ones left out).
std::vector<int> joint_coordinates(const sim::Model& model) {
  std::vector<int> out;
  for (int c = 0; c < model.nv; ++c)
    if (model.joint_of_velocity[c] >= 0) out.push_back(c);
  return out;
}

// Each element's generalized forces by the force pass, as the sweep forms
// them in a run: the poses and body velocities (the base moving), the
// element's wrenches on every body, then Q = A^T T^T F.
Eigen::MatrixXd by_force_pass(const sim::Scene& scene, const State& s, const std::vector<int>& coordinates) {
  const sim::Model& model = scene.model;
  sim::Sweep sweep(model);
  sweep.set_configuration(s.q.data());
  std::vector<sim::Pose> poses(model.size());
  sweep.poses(poses);
  std::vector<sim::Vec6> v(model.size());
  for (int i = 0; i < model.size(); ++i) {
    const int k = model.parent[i];
    v[i] = sweep.placement(i).transform_velocity(model.node_of(i) >= 0 ? sweep.node_velocity(i, v, s.w.data())
                                                 : k != sim::kBase      ? v[k]
                                                                        : model.base_velocity);
    for (int r = 0; r < model.joints[i].dof(); ++r)
      v[i] += sweep.motion_axes(i).col(r) * s.w[(model.first_velocity[i] + r).value];
  }
  Eigen::MatrixXd Q(scene.elements.size(), coordinates.size());
  for (std::size_t e = 0; e < scene.elements.size(); ++e) {
    std::vector<sim::Vec6> F(model.size(), sim::Vec6::Zero());
    Eigen::VectorXd direct = Eigen::VectorXd::Zero(model.nv), passed(model.nv);
    sim::ElementForces out{sim::RatesOut(direct.data()), F};
    const sim::ElementState state{model, sim::Positions(s.q.data()), sim::Rates(s.w.data()), poses, v,
                                  model.base_velocity, false, &sweep};
    scene.elements[e]->add_forces(state, out);
    sweep.generalized_forces(F, passed.data());
    for (std::size_t j = 0; j < coordinates.size(); ++j) Q(e, j) = passed[coordinates[j]] + direct[coordinates[j]];
  }
  return Q;
}

std::vector<std::size_t> all_elements(const sim::Scene& scene) {
  std::vector<std::size_t> out(scene.elements.size());
  for (std::size_t e = 0; e < out.size(); ++e) out[e] = e;
  return out;
}

TEST(ElementJointForces, EqualTheForcePassOnEveryBuiltInScene) {
  int with_forces = 0;  // scenes whose elements put a force on some joint (a driven beam's does not)
  for (const std::string& name : sim::builtin_scene_names()) {
    const sim::Scene scene = sim::load_builtin_scene(name);
    const State s = state_off_start(scene);
    const std::vector<int> coordinates = joint_coordinates(scene.model);
    sim::Dynamics dynamics(scene);
    const Eigen::MatrixXd Q =
        dynamics.element_joint_forces(all_elements(scene), coordinates, s.q.data(), s.w.data());
    const Eigen::MatrixXd reference = by_force_pass(scene, s, coordinates);
    with_forces += reference.cwiseAbs().maxCoeff() > 0;
    // Round-off of the two orders of summation, on the largest force.
    EXPECT_LE((Q - reference).cwiseAbs().maxCoeff(), 1e-11 * reference.cwiseAbs().maxCoeff()) << name;
  }
  EXPECT_GE(with_forces, 12);
}

// One joint at a time, elements whose bodies none of the joint moves are
// skipped (force_element.hpp): the column asked alone must be the one asked
// with every joint, to the bit.
TEST(ElementJointForces, OneJointAtATimeEqualsEveryJointAtOnce) {
  for (const std::string& name : sim::builtin_scene_names()) {
    const sim::Scene scene = sim::load_builtin_scene(name);
    const State s = state_off_start(scene);
    const std::vector<int> coordinates = joint_coordinates(scene.model);
    sim::Dynamics dynamics(scene);
    const Eigen::MatrixXd all = dynamics.element_joint_forces(all_elements(scene), coordinates, s.q.data(), s.w.data());
    for (std::size_t j = 0; j < coordinates.size(); ++j) {
      const Eigen::MatrixXd one =
          dynamics.element_joint_forces(all_elements(scene), {coordinates[j]}, s.q.data(), s.w.data());
      EXPECT_EQ(one.col(0), all.col(static_cast<Eigen::Index>(j))) << name << ", coordinate " << coordinates[j];
    }
  }
}

// The forces take only the sweep's placements (Sweep::set_placements), not
// its articulated inertias: a right-hand side after them must still form
// its own configuration, and give what it gave before.
TEST(ElementJointForces, LeaveTheRightHandSideAsItWas) {
  for (const char* name : {"pantograph", "pantograph_compliant", "zfold_flexible"}) {
    const sim::Scene scene = sim::load_builtin_scene(name);
    sim::Dynamics dynamics(scene);
    const std::vector<double> y = dynamics.initial_state();
    std::vector<double> before(y.size()), after(y.size());
    ASSERT_TRUE(dynamics.rhs(0, y.data(), before.data())) << name;
    const State s = state_off_start(scene);
    dynamics.element_joint_forces(all_elements(scene), joint_coordinates(scene.model), s.q.data(), s.w.data());
    ASSERT_TRUE(dynamics.rhs(0, y.data(), after.data())) << name;
    EXPECT_EQ(before, after) << name;
  }
}

TEST(ElementJointForces, AreTheFallOfTheBushingsEnergyAsEachHingeTurns) {
  const sim::Scene scene = sim::load_builtin_scene("pantograph_compliant");
  const sim::Model& model = scene.model;
  const State s = state_off_start(scene);
  const std::vector<double> at_rest(model.nv, 0.0);
  const std::vector<int> coordinates = joint_coordinates(model);
  std::vector<std::size_t> bushings;
  for (std::size_t e = 0; e < scene.elements.size(); ++e)
    if (scene.elements[e]->kind() == "bushing") bushings.push_back(e);
  ASSERT_EQ(bushings.size(), 3u);
  sim::Dynamics dynamics(scene);
  const Eigen::MatrixXd Q = dynamics.element_joint_forces(bushings, coordinates, s.q.data(), at_rest.data());
  auto energy = [&](std::size_t e, const std::vector<double>& q) {
    sim::Sweep sweep(model);
    sweep.set_configuration(q.data());
    std::vector<sim::Pose> poses(model.size());
    sweep.poses(poses);
    const std::vector<sim::Vec6> v(model.size(), sim::Vec6::Zero());
    return scene.elements[e]->potential_energy({model, sim::Positions(q.data()), sim::Rates(at_rest.data()), poses,
                                                v, sim::Vec6::Zero(), false, &sweep});
  };
  const double h = 1e-6;
  for (std::size_t b = 0; b < bushings.size(); ++b) {
    for (std::size_t j = 0; j < coordinates.size(); ++j) {
      const int c = model.position_of(model.joint_of_velocity[coordinates[j]]).value;
      std::vector<double> ahead = s.q, behind = s.q;
      ahead[c] += h;
      behind[c] -= h;
      const double falling = -(energy(bushings[b], ahead) - energy(bushings[b], behind)) / (2 * h);
      EXPECT_NEAR(Q(b, j), falling, 1e-6 * Q.row(b).cwiseAbs().maxCoeff()) << "bushing " << b << " coordinate " << c;
    }
    EXPECT_GT(Q.row(b).cwiseAbs().maxCoeff(), 0) << "bushing " << b << " is deflected off the start";
  }
}

}  // namespace
}  // namespace unfurl
