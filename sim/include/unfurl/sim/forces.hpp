// Applied forces: torsion (or linear) springs with a free position,
// viscous joint dampers, constant body loads and constant gravity.
#pragma once

#include <memory>
#include <vector>

#include "unfurl/sim/kinematics.hpp"
#include "unfurl/sim/model.hpp"
#include "unfurl/sim/spring_curve.hpp"

namespace unfurl {

// tau = -stiffness (q - free_position) - damping dq on one joint, or with a
// measured curve tau = curve(q) - damping dq.
struct JointSpring {
  int joint = 0;
  double stiffness = 0;
  double free_position = 0;  // the preload: the spring is relaxed here
  double damping = 0;
  std::shared_ptr<const SpringCurve> curve;  // replaces stiffness and free_position

  double elastic_torque(double q) const { return curve ? curve->torque(q) : -stiffness * (q - free_position); }
  double torque(double q, double dq) const { return elastic_torque(q) - damping * dq; }
  double energy(double q) const {
    return curve ? curve->energy(q) : 0.5 * stiffness * (q - free_position) * (q - free_position);
  }
  // -d tau / dq of the elastic part at q.
  double local_stiffness(double q) const { return curve ? -curve->slope(q) : stiffness; }
};

// A constant force and torque on a body; the force acts at `point` (body
// frame). Both are given in the body frame, or in the base frame.
struct BodyLoad {
  int body = 0;
  Vec3 force = Vec3::Zero();
  Vec3 torque = Vec3::Zero();
  Vec3 point = Vec3::Zero();
  bool in_base_frame = false;
};

// Adds the loads and gravity to F_i (body frame, at the body origin).
// `poses` is read only when a load is in the base frame or gravity is on.
void add_body_loads(const Model& model, const std::vector<BodyLoad>& loads,
                    const std::vector<Pose>& poses, std::vector<Vec6>& F);

// Potential energy of gravity, -sum m_i g . r_c,i.
double gravity_energy(const Model& model, const std::vector<Pose>& poses);

// Whether add_body_loads needs body orientations.
bool loads_need_poses(const Model& model, const std::vector<BodyLoad>& loads);

}  // namespace unfurl
