#include "unfurl/sim/kinematics.hpp"

#include "unfurl/sim/flexible/node_frame.hpp"

namespace unfurl::sim {

Placement joint_placement(const Model& model, int i, const double* q) {
  const PositionIndex c = model.first_position[i];
  return model.joints[i].placement(c.valid() ? q + c.value : nullptr);
}

Placement placement_in_parent(const Model& model, int i, const double* q) {
  const int a = model.node_of(i);
  if (a < 0) return joint_placement(model, i, q);
  const int k = model.parent[i];
  const flexible::FlexibleNode& node = model.bodies[k].flexible->nodes[a];
  Placement X = joint_placement(model, i, q);
  X.rho -= node.point;
  flexible::NodeFrame frame;
  frame.set(node, q + model.first_elastic_position[k]);
  return flexible::then(frame.placement(), X);
}

void body_poses(const Model& model, const double* q, std::vector<Pose>& poses) {
  poses.resize(model.size());
  for (int i = 0; i < model.size(); ++i) {
    const int k = model.parent[i];
    poses[i] = (k == kBase ? Pose{} : poses[k]).child(placement_in_parent(model, i, q));
  }
}

void position_rates(const Model& model, const double* q, const double* w, double* dq) {
  for (int c = 0; c < model.elastic_coordinates; ++c) dq[model.nq - 1 - c] = w[model.nv - 1 - c];
  for (int i = 0; i < model.size(); ++i) {
    const Joint& joint = model.joints[i];
    const int c = model.first_position[i].value, v = model.first_velocity[i].value;
    if (joint.is_scalar())
      dq[c] = w[v];
    else if (joint.dof() > 1)
      joint.position_rates(q + c, w + v, dq + c);
  }
}

void rates_from_position_rates(const Model& model, const double* q, const double* dq, double* w) {
  for (int c = 0; c < model.elastic_coordinates; ++c) w[model.nv - 1 - c] = dq[model.nq - 1 - c];
  for (int i = 0; i < model.size(); ++i) {
    const Joint& joint = model.joints[i];
    const int c = model.first_position[i].value, v = model.first_velocity[i].value;
    if (joint.is_scalar())
      w[v] = dq[c];
    else if (joint.dof() > 1)
      joint.rates(q + c, dq + c, w + v);
  }
}

}  // namespace unfurl::sim
