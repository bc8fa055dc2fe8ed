#include "unfurl/sim/scene_builder.hpp"

#include "unfurl/sim/elements/elasticity.hpp"
#include "unfurl/sim/elements/gravity.hpp"
#include "unfurl/sim/scene_validation.hpp"

namespace unfurl::sim {

namespace {

// The inertial frame's name when the bus is body 0 on a free joint (the
// bodies still name the bus as their parent).
constexpr const char* kInertialFrame = "inertial";

std::string body_list_field(const Scene& scene) {
  const bool bus = !scene.model.joints.empty() && scene.model.joints[0].type == JointType::free;
  return "bodies[" + std::to_string(scene.model.size() - (bus ? 1 : 0)) + "]";
}

}  // namespace

SceneBuilder::SceneBuilder(std::string name, std::string description) {
  scene_.name = std::move(name);
  scene_.description = std::move(description);
  scene_.source = "code";
}

SceneBuilder& SceneBuilder::source(std::string source) {
  scene_.source = std::move(source);
  return *this;
}

SceneBuilder& SceneBuilder::fixed_base(std::string name, const Vec6& velocity, Visual visual) {
  scene_.model.base_name = std::move(name);
  scene_.model.base_velocity = velocity;
  visuals_.base = std::move(visual);
  return *this;
}

SceneBuilder& SceneBuilder::free_base(const Body& bus, Visual visual) {
  if (!scene_.model.bodies.empty()) throw SceneInvalid("base", "the free base comes before every body");
  Joint joint;
  joint.name = bus.name;
  joint.type = JointType::free;
  scene_.model.base_name = kInertialFrame;
  append(bus, kBase, std::move(joint), std::move(visual));
  return *this;
}

void SceneBuilder::append(const Body& body, int parent, Joint joint, Visual visual) {
  scene_.model.parent.push_back(parent);
  scene_.model.bodies.push_back(body.flexible ? undeformed(body) : body);
  scene_.model.joints.push_back(std::move(joint));
  visuals_.bodies.push_back(std::move(visual));
  if (body.flexible) scene_.elements.push_back(std::make_shared<Elasticity>(scene_.model.size() - 1, body.flexible));
}

bool SceneBuilder::has_body(const std::string& name) const { return scene_.model.find_body(name).has_value(); }

int SceneBuilder::body_index(const std::string& name, const std::string& field) const {
  const std::optional<int> i = scene_.model.find_body(name);
  if (!i) throw SceneInvalid(field, "unknown body '" + name + "'");
  return *i;
}

int SceneBuilder::joint_index(const std::string& name, const std::string& field) const {
  const std::optional<int> j = scene_.model.find_joint(name);
  if (!j) throw SceneInvalid(field, "unknown joint '" + name + "'");
  return *j;
}

SceneBuilder& SceneBuilder::body(const Body& body, const std::string& parent, Joint joint, Visual visual) {
  const std::string field = body_list_field(scene_);
  if (has_body(body.name))
    throw SceneInvalid(field + " (" + body.name + ")", "a body named '" + body.name + "' already exists");
  if (!has_body(parent)) throw SceneInvalid(field + " (" + body.name + ").parent", "unknown parent '" + parent + "'");
  if (joint.name.empty()) joint.name = body.name;
  for (const Joint& other : scene_.model.joints)
    if (other.name == joint.name)
      throw SceneInvalid(field + " (" + body.name + ").joint", "a joint named '" + joint.name + "' already exists");
  const int k = body_index(parent, field + ".parent");
  scene_.model.parent_node.resize(scene_.model.size(), -1);
  scene_.model.parent_node.push_back(k == kBase ? -1 : node_at(k, joint.parent_point, field + ".joint.parent_point"));
  append(body, k, std::move(joint), std::move(visual));
  return *this;
}

// A flexible body's mass, centre of mass and inertia are its undeformed
// shape's (what the rules, the mechanism's scales and the drawing read).
Body SceneBuilder::undeformed(Body body) {
  const int m = body.flexible->modes();
  const Eigen::MatrixXd M = body.flexible->inertia.mass_matrix(Eigen::VectorXd::Zero(m));
  body.mass = M(0, 0);
  const Mat3 mc = M.block<3, 3>(3, 0);  // (m c)~
  body.com = Vec3(mc(2, 1), mc(0, 2), mc(1, 0)) / body.mass;
  body.inertia_com = M.block<3, 3>(3, 3) -
                     body.mass * (body.com.squaredNorm() * Mat3::Identity() - body.com * body.com.transpose());
  return body;
}

// A child of a flexible body hangs on the node at its joint's point (the
// frame itself where no node is there and the point rides on the frame:
// the beam's root, the plate's held edge).
int SceneBuilder::node_at(int k, const Vec3& point, const std::string& field) const {
  const auto& flexible = scene_.model.bodies[k].flexible;
  if (!flexible) return -1;
  if (const int a = flexible->node_of(point); a >= 0) return a;
  if (flexible->on_frame(point)) return -1;
  throw SceneInvalid(field, "no node of the flexible body '" + scene_.model.bodies[k].name + "' is at this point");
}

SceneBuilder& SceneBuilder::element(std::shared_ptr<const ForceElement> element) {
  scene_.elements.push_back(std::move(element));
  return *this;
}

SceneBuilder& SceneBuilder::gravity(const Vec3& g) {
  gravity_ = g;
  return *this;
}

SceneBuilder& SceneBuilder::sensor(Sensor sensor, const std::string& body) {
  const std::string field = "sensors[" + std::to_string(scene_.sensors.size()) + "]";
  sensor.body = body_index(body, field + ".body");
  if (sensor.body == kBase) throw SceneInvalid(field + ".body", "a sensor goes on a body, not the base");
  scene_.sensors.push_back(std::move(sensor));
  return *this;
}

SceneBuilder& SceneBuilder::loop(std::string name, const std::string& body, const std::string& image) {
  const std::string field = "loops[" + std::to_string(scene_.loops.size()) + "]";
  Loop loop;
  loop.name = name.empty() ? body : std::move(name);
  loop.body = body_index(body, field + ".body");
  loop.image = body_index(image, field + ".image");
  if (loop.body == kBase || loop.image == kBase) throw SceneInvalid(field, "the base cannot close a loop");
  scene_.loops.push_back(loop);
  return *this;
}

SceneBuilder& SceneBuilder::regulator(const RegulatorSettings& settings) {
  scene_.regulator = settings;
  return *this;
}

SceneBuilder& SceneBuilder::closure_tolerance(double tolerance) {
  scene_.closure_tolerance = tolerance;
  return *this;
}

SceneBuilder& SceneBuilder::run(const RunSettings& settings) {
  scene_.run = settings;
  return *this;
}

SceneBuilder& SceneBuilder::torque_margin(const TorqueMarginFactors& factors) {
  scene_.torque_margin = factors;
  return *this;
}

void SceneBuilder::set_initial(const std::string& joint, std::vector<double> values, int which) {
  initial_.push_back({joint, std::move(values), which});
}

SceneBuilder& SceneBuilder::initial_position(const std::string& joint, std::vector<double> q) {
  set_initial(joint, std::move(q), 0);
  return *this;
}

SceneBuilder& SceneBuilder::initial_rate(const std::string& joint, std::vector<double> w) {
  set_initial(joint, std::move(w), 1);
  return *this;
}

SceneBuilder& SceneBuilder::initial_momentum(const std::string& joint, std::vector<double> p) {
  set_initial(joint, std::move(p), 2);
  return *this;
}

SceneFile SceneBuilder::build() {
  Scene scene = scene_;
  // Gravity acts after the elements given (the order their forces add in).
  if (!gravity_.isZero(0)) scene.elements.push_back(std::make_shared<Gravity>(gravity_));
  // The coordinates' places are known once the tree is.
  validate_model(scene);
  const Model& model = scene.model;
  bool rates = false, momenta = false;
  for (const Initial& x : initial_) {
    static const char* const key[] = {"q", "dq", "p"};
    const std::string field = std::string("initial.") + key[x.which] + "." + x.joint;
    const int j = joint_index(x.joint, field);
    const Joint& joint = model.joints[j];
    if (joint.dof() == 0) throw SceneInvalid(field, "joint '" + joint.name + "' is fixed: it has no coordinate");
    const int n = x.which == 0 ? joint.positions() : joint.dof();
    // A compliant hinge takes its angle alone (its pin starts undeflected)
    // or all six.
    const bool hinge_only = joint.compliant && x.values.size() == 1;
    if (static_cast<int>(x.values.size()) != n && !hinge_only) {
      // "(qw, qx, qy, qz)": what the entries are.
      std::string names;
      const int from = x.which == 0 ? model.first_position[j].value : model.first_velocity[j].value;
      for (int k = 0; k < n; ++k) {
        const std::string full = x.which == 0 ? model.position_name(from + k) : model.velocity_name(from + k);
        names += (k ? ", " : "") + full.substr(full.rfind('.') + 1);
      }
      throw SceneInvalid(field, "a " + std::string(joint_type_name(joint.type)) + " joint takes " + std::to_string(n) +
                                    " numbers here (" + names + ")");
    }
    rates = rates || x.which == 1;
    momenta = momenta || x.which == 2;
    if (rates && momenta) throw SceneInvalid("initial.p", "give either dq or p, not both");
    std::vector<double>& target = x.which == 0 ? scene.q0 : x.which == 1 ? scene.dq0 : scene.p0;
    if (target.empty()) target.assign(model.nv, 0.0);  // p0 (validate() sized q0 and dq0)
    const int at = x.which == 0 ? model.first_position[j].value : model.first_velocity[j].value;
    std::copy(x.values.begin(), x.values.end(), target.begin() + at);
  }
  validate(scene);
  return {scene, visuals_};
}

namespace joints {

Joint revolute(std::string name, const Vec3& axis, const Vec3& parent_point, const Vec3& child_point) {
  Joint j;
  j.name = std::move(name);
  j.type = JointType::revolute;
  j.axis = axis;
  j.parent_point = parent_point;
  j.child_point = child_point;
  return j;
}

Joint prismatic(std::string name, const Vec3& axis, const Vec3& parent_point, const Vec3& child_point) {
  Joint j = revolute(std::move(name), axis, parent_point, child_point);
  j.type = JointType::prismatic;
  return j;
}

}  // namespace joints

}  // namespace unfurl::sim
