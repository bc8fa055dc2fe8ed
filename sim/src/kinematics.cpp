#include "unfurl/sim/kinematics.hpp"

namespace unfurl {

void body_poses(const Model& model, const double* q, std::vector<Pose>& poses) {
  poses.resize(model.size());
  for (int i = 0; i < model.size(); ++i) {
    const int c = model.coordinate[i];
    const int k = model.parent[i];
    poses[i] = (k == kBase ? Pose{} : poses[k]).child(model.joints[i].placement(c >= 0 ? q + c : nullptr));
  }
}

}  // namespace unfurl
