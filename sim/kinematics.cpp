#include "kinematics.hpp"

namespace unfurl {

void body_poses(const Model& model, const double* q, std::vector<Pose>& poses) {
  poses.resize(model.size());
  for (int i = 0; i < model.size(); ++i) {
    const int c = model.coordinate[i];
    const Placement X = model.joints[i].placement(c >= 0 ? q[c] : 0.0);
    const int k = model.parent[i];
    const Pose parent = k == kBase ? Pose{} : poses[k];
    poses[i].position = parent.to_base(X.rho);
    poses[i].rotation = X.G * parent.rotation;
  }
}

}  // namespace unfurl
