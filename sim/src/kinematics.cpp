#include "unfurl/sim/kinematics.hpp"

namespace unfurl::sim {

void body_poses(const Model& model, const double* q, std::vector<Pose>& poses) {
  poses.resize(model.size());
  for (int i = 0; i < model.size(); ++i) {
    const PositionIndex c = model.first_position[i];
    const int k = model.parent[i];
    poses[i] = (k == kBase ? Pose{} : poses[k]).child(model.joints[i].placement(c.valid() ? q + c.value : nullptr));
  }
}

void position_rates(const Model& model, const double* q, const double* w, double* dq) {
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
