#include "unfurl/sim/model.hpp"

#include <stdexcept>

namespace unfurl {

Mat3 Body::inertia_origin() const {
  return inertia_com + mass * (com.squaredNorm() * Mat3::Identity() - com * com.transpose());
}

void Model::finalize() {
  const int N = size();
  if (static_cast<int>(joints.size()) != N || static_cast<int>(parent.size()) != N)
    throw std::invalid_argument("model: bodies, joints and parents differ in number");
  children.assign(N, {});
  coordinate.assign(N, -1);
  joint_of_coordinate.clear();
  nq = 0;
  for (int i = 0; i < N; ++i) {
    if (parent[i] != kBase && (parent[i] < 0 || parent[i] >= i))
      throw std::invalid_argument("model: numbering is not regular: body '" + bodies[i].name +
                                  "' comes before its parent");
    if (parent[i] != kBase) children[parent[i]].push_back(i);
    if (joints[i].dof() == 1) {
      coordinate[i] = nq++;
      joint_of_coordinate.push_back(i);
    }
  }
}

int Model::find_body(const std::string& name) const {
  if (name == base_name) return kBase;
  for (int i = 0; i < size(); ++i)
    if (bodies[i].name == name) return i;
  return -2;
}

}  // namespace unfurl
