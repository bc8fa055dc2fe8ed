// A scene as a MuJoCo model (MJCF), for running the same mechanism in an
// engine a user already trusts.
//
// The bodies are placed at the scene's initial coordinates q0 and every
// hinge's and slide's `ref` is q0, so MuJoCo's joint positions are unfurl's
// q; a ball, universal or planar joint's body sits at the joint's neutral
// position instead (its qpos is then unfurl's q), a free bus where q0 puts
// it (a `freejoint`, whose qpos is its pose). Each
// closed loop is merged back: the split body takes its image's mass and
// inertia, and the joint that carried the image becomes an `equality/connect`
// at its pivot (a point constraint: the rest of the mechanism fixes the
// relative rotation of a planar loop). Springs and dampers become the
// joints' stiffness, springref and damping. What MJCF cannot say is written
// as a comment and listed: the latches (also kept as custom numeric data,
// latch:JOINT = [position, stiffness, damping, side], side = sign of
// q0 - position or 0 when it starts engaged), body loads and a moving base.
// A mechanism nested deeper than MuJoCo's parser reads is exported with a
// warning (MjcfModel::warnings), not cut into a shallower tree.
#pragma once

#include <string>
#include <vector>

#include "unfurl/sim/scene.hpp"

namespace unfurl::io {

// MuJoCo 2.2's XML parser (tinyxml2) refuses elements nested 100 deep: with
// <mujoco> and <worldbody> above them and a joint inside, bodies may nest
// this deep (measured: the generated 95-stage pantograph, 96 deep, loads;
// 97 does not).
inline constexpr int kMujocoDeepestBody = 96;

struct MjcfModel {
  std::string xml;
  std::vector<std::string> not_exported;  // what the model leaves out
  std::vector<std::string> warnings;      // what keeps MuJoCo from loading it
};

// Throws std::runtime_error for a mechanism MJCF cannot hold (an image
// with children of its own, a loop closed at a joint other than a hinge).
MjcfModel export_mjcf(const sim::Scene& scene);

}  // namespace unfurl::io
