#include "unfurl/sim/kinematics.hpp"

#include <algorithm>

namespace unfurl {

void body_poses(const Model& model, const double* q, std::vector<Pose>& poses) {
  poses.resize(model.size());
  for (int i = 0; i < model.size(); ++i) {
    const int c = model.coordinate[i];
    const int k = model.parent[i];
    poses[i] = (k == kBase ? Pose{} : poses[k]).child(model.joints[i].placement(c >= 0 ? q + c : nullptr));
  }
}

void position_rates(const Model& model, const double* q, const double* w, double* dq) {
  std::copy_n(w, model.scalar_coordinates, dq);
  if (!model.has_multi_dof_joints()) return;
  for (int i = 0; i < model.size(); ++i)
    if (model.joints[i].dof() > 1)
      model.joints[i].position_rates(q + model.coordinate[i], w + model.velocity[i], dq + model.coordinate[i]);
}

void rates_from_position_rates(const Model& model, const double* q, const double* dq, double* w) {
  std::copy_n(dq, model.scalar_coordinates, w);
  if (!model.has_multi_dof_joints()) return;
  for (int i = 0; i < model.size(); ++i)
    if (model.joints[i].dof() > 1)
      model.joints[i].rates(q + model.coordinate[i], dq + model.coordinate[i], w + model.velocity[i]);
}

}  // namespace unfurl
