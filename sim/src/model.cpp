#include "unfurl/sim/model.hpp"

#include <stdexcept>

namespace unfurl::sim {

Mat3 Body::inertia_origin() const {
  return inertia_com + mass * (com.squaredNorm() * Mat3::Identity() - com * com.transpose());
}

void Model::finalize() {
  const int N = size();
  if (static_cast<int>(joints.size()) != N || static_cast<int>(parent.size()) != N)
    throw std::invalid_argument("model: bodies, joints and parents differ in number");
  children.assign(N, {});
  first_position.assign(N, PositionIndex{});
  first_velocity.assign(N, VelocityIndex{});
  joint_of_position.clear();
  joint_of_velocity.clear();
  nq = nv = 0;
  for (int i = 0; i < N; ++i) {
    if (parent[i] != kBase && (parent[i] < 0 || parent[i] >= i))
      throw std::invalid_argument("model: numbering is not regular: body '" + bodies[i].name +
                                  "' comes before its parent");
    if (parent[i] != kBase) children[parent[i]].push_back(i);
  }
  const auto place = [&](int i) {
    first_position[i] = {nq};
    first_velocity[i] = {nv};
    nq += joints[i].positions();
    nv += joints[i].dof();
    joint_of_position.insert(joint_of_position.end(), joints[i].positions(), i);
    joint_of_velocity.insert(joint_of_velocity.end(), joints[i].dof(), i);
  };
  for (int i = 0; i < N; ++i)
    if (joints[i].is_scalar()) place(i);
  scalar_coordinates = nv;
  for (int i = 0; i < N; ++i)
    if (joints[i].dof() > 1) place(i);
  if (parent_node.empty()) parent_node.assign(N, -1);
  first_elastic_position.assign(N, -1);
  first_elastic_velocity.assign(N, -1);
  body_of_elastic_velocity.assign(nv, -1);
  elastic_coordinates = 0;
  for (int i = 0; i < N; ++i) {
    if (parent_node[i] >= 0 && (parent[i] == kBase || !bodies[parent[i]].flexible ||
                                parent_node[i] >= static_cast<int>(bodies[parent[i]].flexible->nodes.size())))
      throw std::invalid_argument("model: joint '" + joints[i].name + "' hangs on a node its parent does not have");
    if (!bodies[i].flexible) continue;
    const int m = bodies[i].flexible->modes();
    first_elastic_position[i] = nq;
    first_elastic_velocity[i] = nv;
    nq += m;
    nv += m;
    elastic_coordinates += m;
    joint_of_position.insert(joint_of_position.end(), m, -1);
    joint_of_velocity.insert(joint_of_velocity.end(), m, -1);
    body_of_elastic_velocity.insert(body_of_elastic_velocity.end(), m, i);
  }
}

namespace {

const char* entry_name(const Joint& joint, int k, bool position) {
  static const char* const compliant[] = {"", "u1", "u2", "ua", "r1", "r2"};
  if (joint.compliant) return compliant[k];
  const JointType type = joint.type;
  static const char* const free_q[] = {"x", "y", "z", "qw", "qx", "qy", "qz"};
  static const char* const free_v[] = {"vx", "vy", "vz", "wx", "wy", "wz"};
  static const char* const ball_q[] = {"qw", "qx", "qy", "qz"};
  static const char* const ball_v[] = {"wx", "wy", "wz"};
  static const char* const planar_q[] = {"x1", "x2", "angle"};
  static const char* const planar_v[] = {"v1", "v2", "w"};
  static const char* const universal[] = {"1", "2"};
  switch (type) {
    case JointType::universal: return universal[k];
    case JointType::free: return position ? free_q[k] : free_v[k];
    case JointType::spherical: return position ? ball_q[k] : ball_v[k];
    case JointType::planar: return position ? planar_q[k] : planar_v[k];
    default: return "";
  }
}

}  // namespace

std::string Model::position_name(int c) const {
  const int i = joint_of_position[c];
  if (i < 0) return velocity_name(c - nq + nv);  // an elastic coordinate: the same entry of the rates
  // A compliant hinge's angle keeps its joint's name.
  if (joints[i].is_scalar() || (joints[i].compliant && c == first_position[i].value)) return joints[i].name;
  return joints[i].name + "." + entry_name(joints[i], c - first_position[i].value, true);
}

std::string Model::velocity_name(int c) const {
  const int i = joint_of_velocity[c];
  if (i < 0) {
    const int b = body_of_elastic_velocity[c];
    return bodies[b].name + ".eta" + std::to_string(c - first_elastic_velocity[b] + 1);
  }
  if (joints[i].is_scalar() || (joints[i].compliant && c == first_velocity[i].value)) return joints[i].name;
  return joints[i].name + "." + entry_name(joints[i], c - first_velocity[i].value, false);
}

namespace {

// Whether velocity entry k of a joint is a translation.
bool translational_rate(const Joint& joint, int k) {
  if (joint.compliant) return k >= 1 && k <= 3;
  switch (joint.type) {
    case JointType::prismatic:
      return true;
    case JointType::planar:
      return k < 2;
    case JointType::free:
      return k < 3;
    default:
      return false;
  }
}

}  // namespace

// A modal coordinate of unit modal mass: a displacement times the square
// root of a mass.
constexpr const char* kModal = "m kg^0.5";

std::string Model::position_unit(int c) const {
  if (joint_of_position[c] < 0) return kModal;
  const int i = joint_of_position[c], k = c - first_position[i].value;
  if (joints[i].has_quaternion() && k >= joints[i].quaternion_offset()) return "";
  return translational_rate(joints[i], k) ? "m" : "rad";
}

std::string Model::velocity_unit(int c) const {
  if (joint_of_velocity[c] < 0) return "m kg^0.5/s";
  const int i = joint_of_velocity[c];
  return translational_rate(joints[i], c - first_velocity[i].value) ? "m/s" : "rad/s";
}

std::string Model::momentum_unit(int c) const {
  if (joint_of_velocity[c] < 0) return "m kg^0.5/s";  // unit modal mass: p = eta'
  const int i = joint_of_velocity[c];
  return translational_rate(joints[i], c - first_velocity[i].value) ? "N s" : "N m s";
}

std::optional<int> Model::find_body(const std::string& name) const {
  if (name == base_name) return kBase;
  for (int i = 0; i < size(); ++i)
    if (bodies[i].name == name) return i;
  return std::nullopt;
}

std::optional<int> Model::find_joint(const std::string& name) const {
  for (int j = 0; j < size(); ++j)
    if (joints[j].name == name) return j;
  return std::nullopt;
}

}  // namespace unfurl::sim
