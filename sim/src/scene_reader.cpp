// Scene files (YAML) into a Scene and its visuals; the format is documented
// in assets/scenes/README.md.
#include <yaml-cpp/yaml.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "scene_overrides.hpp"
#include "scene_validation.hpp"
#include "unfurl/sim/elements/all.hpp"
#include "unfurl/sim/number_text.hpp"
#include "unfurl/sim/scene_file.hpp"
#include "unfurl/input/yaml_fields.hpp"

namespace unfurl {

namespace {

// Reads one scene document into a Scene and its visuals, checking every
// key and value.
// Limits of what a scene may ask for (each error message names them).
constexpr long kMostSteps = 1'000'000'000'000;
constexpr double kLargestClosureTolerance = 0.05;
constexpr const char* kInertialFrame = "inertial";

// "x, y, z, qw, qx, qy, qz": the names of a joint's positions or rates.
std::string entry_names(const Model& model, int joint, bool positions) {
  std::string names;
  const int from = positions ? model.first_position[joint].value : model.first_velocity[joint].value;
  const int n = positions ? model.joints[joint].positions() : model.joints[joint].dof();
  for (int k = 0; k < n; ++k) {
    const std::string full = positions ? model.position_name(from + k) : model.velocity_name(from + k);
    names += (k ? ", " : "") + full.substr(full.rfind('.') + 1);
  }
  return names;
}

// Whether one of two bodies is an ancestor of the other.
bool on_one_branch(const Model& model, int a, int b) {
  auto descends = [&](int child, int ancestor) {
    for (int i = child; i >= 0; i = model.parent[i])
      if (i == ancestor) return true;
    return false;
  };
  return descends(a, b) || descends(b, a);
}

class SceneReader : private input::YamlFields {
 public:
  explicit SceneReader(std::string source) : input::YamlFields(std::move(source)) {}

  SceneFile read(const std::string& text, const std::vector<Override>& overrides);

 private:
  void read_base(const YAML::Node& node, Scene& scene);
  void read_body(const YAML::Node& node, int index, const YAML::Node& all, Scene& scene);
  void read_mass_properties(const YAML::Node& node, const std::string& field, Body& b) const;
  Joint read_joint(const YAML::Node& node, const std::string& field) const;
  Visual read_visual(const YAML::Node& node, const std::string& field) const;
  void read_springs(const YAML::Node& list, Scene& scene) const;
  void read_dampers(const YAML::Node& list, Scene& scene) const;
  void read_friction(const YAML::Node& list, Scene& scene) const;
  std::shared_ptr<const SpringCurve> spring_curve(const YAML::Node& table, const std::string& field) const;
  void read_point_springs(const YAML::Node& list, Scene& scene) const;
  int body_or_base(const YAML::Node& node, const Scene& scene, const std::string& field) const;
  void read_loads(const YAML::Node& list, Scene& scene) const;
  void read_latches(const YAML::Node& list, Scene& scene) const;
  void read_loops(const YAML::Node& list, Scene& scene);
  void read_regulator(const YAML::Node& node, Scene& scene) const;
  void read_initial(const YAML::Node& node, Scene& scene) const;
  void read_run(const YAML::Node& node, RunSettings& run) const;
  void check_run_size(const YAML::Node& node, const RunSettings& run) const;

  int joint_by_name(const YAML::Node& node, const Scene& scene, const std::string& field,
                    bool needs_coordinate) const;
  int body_by_name(const YAML::Node& node, const Scene& scene, const std::string& field) const;

  SceneVisuals visuals_;
  std::vector<YAML::Node> loop_nodes_;
  std::map<std::string, int> joint_index_;
};

Visual SceneReader::read_visual(const YAML::Node& node, const std::string& field) const {
  Visual v;
  if (node.IsScalar()) {
    v.mesh = node.Scalar();
    return v;
  }
  check_keys(node, {"name", "scale", "rotation", "offset"}, field);
  v.mesh = text(require(node, "name", field), field + ".name");
  const YAML::Node scale = node["scale"];
  if (scale && scale.IsScalar()) {
    v.scale = Vec3::Constant(positive(scale, field + ".scale"));
  } else if (scale) {
    v.scale = vec3(scale, field + ".scale");
    if ((v.scale.array() <= 0).any()) fail(scale, field + ".scale", "must be positive");
  }
  if (const YAML::Node rotation = node["rotation"]) {
    const std::vector<double> r = numbers(rotation, field + ".rotation");
    if (r.size() != 4 || Vec3(r[0], r[1], r[2]).norm() < 1e-12)
      fail(rotation, field + ".rotation", "expected [axis x, axis y, axis z, angle in degrees] with a nonzero axis");
    v.rotation_axis = Vec3(r[0], r[1], r[2]).normalized();
    v.rotation_deg = r[3];
  }
  v.offset = vec3_or(node, "offset", Vec3::Zero(), field);
  return v;
}

void SceneReader::read_base(const YAML::Node& node, Scene& scene) {
  check_keys(node, {"name", "mesh", "velocity", "free", "mass", "com", "inertia"}, "base");
  if (node["name"]) scene.model.base_name = name(node["name"], "base.name");
  if (node["mesh"]) visuals_.base = read_visual(node["mesh"], "base.mesh");
  const bool free = node["free"] && flag(node["free"], "base.free");
  if (!free) {
    for (const char* key : {"mass", "com", "inertia"})
      if (node[key]) fail(node[key], std::string("base.") + key, "only a free base (`free: true`) has mass properties");
  } else {
    // The bus becomes body 0 on a free joint in the inertial frame (which
    // keeps the name "inertial"); the bodies name it as their parent as before.
    if (node["velocity"]) fail(node["velocity"], "base.velocity", "a free base moves by itself: give no velocity");
    Body bus;
    bus.name = scene.model.base_name;
    read_mass_properties(node, "base", bus);
    Joint joint;
    joint.name = bus.name;
    joint.type = JointType::free;
    scene.model.base_name = kInertialFrame;
    joint_index_[joint.name] = 0;
    scene.model.bodies.push_back(bus);
    scene.model.joints.push_back(joint);
    scene.model.parent.push_back(kBase);
    visuals_.bodies.push_back(visuals_.base);
    visuals_.base = Visual{};
    return;
  }
  if (const YAML::Node v = node["velocity"]) {
    const std::vector<double> x = numbers(v, "base.velocity");
    if (x.size() != 6) fail(v, "base.velocity", "expected 6 numbers (vx, vy, vz, wx, wy, wz)");
    for (int k = 0; k < 6; ++k) scene.model.base_velocity[k] = x[k];
  }
}

Joint SceneReader::read_joint(const YAML::Node& node, const std::string& field) const {
  check_keys(node, {"name", "type", "axis", "axis2", "parent_point", "child_point"}, field);
  Joint j;
  const YAML::Node type = require(node, "type", field);
  const std::string t = text(type, field + ".type");
  const auto parsed = parse_joint_type(t);
  if (!parsed)
    fail(type, field + ".type",
         "unknown joint type '" + t + "' (expected revolute, prismatic, fixed, universal, spherical, planar or free)");
  j.type = *parsed;
  const auto unit_axis = [&](const char* key) {
    const YAML::Node axis = require(node, key, field);
    Vec3 a = vec3(axis, field + "." + key);
    if (a.norm() < 1e-12) fail(axis, field + "." + key, "the joint axis has zero length");
    return a.normalized();
  };
  if (j.type == JointType::revolute || j.type == JointType::prismatic || j.type == JointType::planar ||
      j.type == JointType::universal) {
    j.axis = unit_axis("axis");
  } else if (node["axis"]) {
    fail(node["axis"], field + ".axis", std::string("a ") + joint_type_name(j.type) + " joint has no axis");
  }
  if (j.type == JointType::universal) {
    j.axis2 = unit_axis("axis2");
    if (j.axis.cross(j.axis2).norm() < 1e-6)
      fail(node["axis2"], field + ".axis2", "a universal joint's two axes must not be parallel");
  } else if (node["axis2"]) {
    fail(node["axis2"], field + ".axis2", "only a universal joint has a second axis");
  }
  j.parent_point = vec3(require(node, "parent_point", field), field + ".parent_point");
  j.child_point = vec3(require(node, "child_point", field), field + ".child_point");
  if (node["name"]) j.name = name(node["name"], field + ".name");
  return j;
}

// mass, com and inertia of a body (or of a free base), checked.
void SceneReader::read_mass_properties(const YAML::Node& node, const std::string& field, Body& b) const {
  const YAML::Node mass = require(node, "mass", field);
  b.mass = number(mass, field + ".mass");
  if (b.mass < 0) fail(mass, field + ".mass", "negative mass " + mass.Scalar());
  if (b.mass == 0) fail(mass, field + ".mass", "the mass must be positive");
  b.com = vec3_or(node, "com", Vec3::Zero(), field);

  const YAML::Node inertia = require(node, "inertia", field);
  const std::vector<double> I = numbers(inertia, field + ".inertia");
  if (I.size() != 3 && I.size() != 6)
    fail(inertia, field + ".inertia", "expected [Ixx, Iyy, Izz] or [Ixx, Iyy, Izz, Ixy, Ixz, Iyz]");
  b.inertia_com.diagonal() << I[0], I[1], I[2];
  if (I.size() == 6) {
    b.inertia_com(0, 1) = b.inertia_com(1, 0) = I[3];
    b.inertia_com(0, 2) = b.inertia_com(2, 0) = I[4];
    b.inertia_com(1, 2) = b.inertia_com(2, 1) = I[5];
  }
  const Vec3 principal = Eigen::SelfAdjointEigenSolver<Mat3>(b.inertia_com).eigenvalues();
  if (!(principal.minCoeff() > 0)) {
    std::ostringstream s;
    s << "the inertia is not positive definite (smallest principal moment " << principal.minCoeff() << ")";
    fail(inertia, field + ".inertia", s.str());
  }
  // Every mass distribution has I1 + I2 >= I3 for its principal moments
  // (equality for a flat body); allow round-off of the scene's digits.
  if (principal[0] + principal[1] < principal[2] * (1 - 1e-6)) {
    std::ostringstream s;
    s << "no body has these principal moments (" << principal[0] << ", " << principal[1] << ", " << principal[2]
      << "): the two smaller must add up to at least the largest";
    fail(inertia, field + ".inertia", s.str());
  }

}

void SceneReader::read_body(const YAML::Node& node, int index, const YAML::Node& all, Scene& scene) {
  std::string field = input::index_field("bodies", index);
  check_keys(node, {"name", "parent", "mass", "com", "inertia", "mesh", "joint"}, field);
  Body b;
  b.name = name(require(node, "name", field), field + ".name");
  field += " (" + b.name + ")";
  Model& model = scene.model;
  if (model.find_body(b.name) != -2) fail(node["name"], field, "a body named '" + b.name + "' already exists");

  const YAML::Node parent = require(node, "parent", field);
  const std::string parent_name = text(parent, field + ".parent");
  const int k = model.find_body(parent_name);
  if (k == -2) {
    for (std::size_t later = index + 1; later < all.size(); ++later)
      if (all[later].IsMap() && all[later]["name"] && all[later]["name"].Scalar() == parent_name)
        fail(parent, field + ".parent",
             "numbering is not regular: the parent '" + parent_name + "' is listed after its child (list " +
                 "every body after its parent)");
    fail(parent, field + ".parent", "unknown parent '" + parent_name + "'");
  }

  read_mass_properties(node, field, b);

  Joint j = read_joint(require(node, "joint", field), field + ".joint");
  if (j.name.empty()) j.name = b.name;
  if (joint_index_.count(j.name)) fail(node["joint"], field + ".joint", "a joint named '" + j.name + "' already exists");
  if (j.type == JointType::free)
    fail(node["joint"]["type"], field + ".joint.type",
         "a free joint is for a free-floating base only: give the base `free: true` and its mass properties");
  joint_index_[j.name] = model.size();

  visuals_.bodies.push_back(node["mesh"] ? read_visual(node["mesh"], field + ".mesh") : Visual{});
  model.bodies.push_back(b);
  model.joints.push_back(j);
  model.parent.push_back(k);
}

int SceneReader::joint_by_name(const YAML::Node& node, const Scene& scene, const std::string& field,
                               bool needs_coordinate) const {
  const std::string name = text(node, field);
  const auto it = joint_index_.find(name);
  if (it == joint_index_.end()) fail(node, field, "unknown joint '" + name + "'");
  const Joint& joint = scene.model.joints[it->second];
  if (needs_coordinate && joint.dof() == 0) fail(node, field, "joint '" + name + "' is fixed: it has no coordinate");
  if (needs_coordinate && !joint.is_scalar())
    fail(node, field,
         "joint '" + name + "' is " + joint_type_name(joint.type) +
             ": springs, dampers, friction and latches act on revolute and prismatic joints");
  return it->second;
}

int SceneReader::body_by_name(const YAML::Node& node, const Scene& scene, const std::string& field) const {
  const std::string name = text(node, field);
  const int i = scene.model.find_body(name);
  if (i < 0) fail(node, field, i == kBase ? "the base cannot carry this" : "unknown body '" + name + "'");
  return i;
}

void SceneReader::read_springs(const YAML::Node& list, Scene& scene) const {
  if (!list.IsSequence()) fail(list, "springs", "expected a list");
  for (std::size_t n = 0; n < list.size(); ++n) {
    const YAML::Node s = list[n];
    const std::string field = input::index_field("springs", n);
    check_keys(s, {"joint", "stiffness", "free_position", "damping", "table"}, field);
    auto spring = std::make_shared<JointSpring>(joint_by_name(require(s, "joint", field), scene, field + ".joint", true));
    if (const YAML::Node table = s["table"]) {
      for (const char* key : {"stiffness", "free_position"})
        if (s[key]) fail(s[key], field + "." + key, "a spring with a table takes its torque from the table alone");
      spring->curve = spring_curve(table, field + ".table");
    } else {
      spring->stiffness = non_negative(require(s, "stiffness", field), field + ".stiffness");
      spring->free_position = number_or(s, "free_position", 0.0, field);
    }
    if (s["damping"]) spring->damping = non_negative(s["damping"], field + ".damping");
    scene.elements.push_back(spring);
  }
}

std::shared_ptr<const SpringCurve> SceneReader::spring_curve(const YAML::Node& table, const std::string& field) const {
  if (!table.IsSequence() || table.size() < 2)
    fail(table, field, "expected a list of at least two [angle, torque] points, e.g. [[0, 0.3], [1.57, 0.15]]");
  std::vector<double> q, tau;
  for (std::size_t k = 0; k < table.size(); ++k) {
    const std::string point = field + "[" + std::to_string(k) + "]";
    const std::vector<double> p = numbers(table[k], point);
    if (p.size() != 2) fail(table[k], point, "expected [angle, torque]");
    if (!q.empty() && !(p[0] > q.back()))
      fail(table[k], point, "the angles must increase along the table (" + format_number(p[0]) + " after " +
                                format_number(q.back()) + ")");
    if (!q.empty() && !std::isfinite((p[1] - tau.back()) / (p[0] - q.back())))
      fail(table[k], point, "too close to the point before: the curve's slope between them is not finite");
    q.push_back(p[0]);
    tau.push_back(p[1]);
  }
  return std::make_shared<const SpringCurve>(q, tau);
}

void SceneReader::read_dampers(const YAML::Node& list, Scene& scene) const {
  if (!list.IsSequence()) fail(list, "dampers", "expected a list");
  for (std::size_t n = 0; n < list.size(); ++n) {
    const YAML::Node d = list[n];
    const std::string field = input::index_field("dampers", n);
    check_keys(d, {"joint", "damping"}, field);
    auto damper = std::make_shared<JointDamper>(joint_by_name(require(d, "joint", field), scene, field + ".joint", true));
    damper->damping = non_negative(require(d, "damping", field), field + ".damping");
    scene.elements.push_back(damper);
  }
}

void SceneReader::read_friction(const YAML::Node& list, Scene& scene) const {
  if (!list.IsSequence()) fail(list, "friction", "expected a list");
  for (std::size_t n = 0; n < list.size(); ++n) {
    const YAML::Node f = list[n];
    const std::string field = input::index_field("friction", n);
    check_keys(f, {"joint", "coulomb", "viscous", "velocity_scale"}, field);
    auto friction = std::make_shared<JointFriction>(joint_by_name(require(f, "joint", field), scene, field + ".joint", true));
    if (f["coulomb"]) friction->coulomb = non_negative(f["coulomb"], field + ".coulomb");
    if (f["viscous"]) friction->viscous = non_negative(f["viscous"], field + ".viscous");
    if (f["velocity_scale"]) {
      friction->velocity_scale = positive(f["velocity_scale"], field + ".velocity_scale");
      if (friction->velocity_scale < 1e-9)
        fail(f["velocity_scale"], field + ".velocity_scale",
             "below 1e-9 rad/s the smoothed friction is a step no integrator can follow");
    }
    if (!f["coulomb"] && !f["viscous"]) fail(f, field, "give coulomb, viscous or both");
    scene.elements.push_back(friction);
  }
}

int SceneReader::body_or_base(const YAML::Node& node, const Scene& scene, const std::string& field) const {
  const int i = scene.model.find_body(text(node, field));
  if (i < kBase) fail(node, field, "unknown body '" + node.Scalar() + "' (nor the base, '" + scene.model.base_name + "')");
  return i;
}

void SceneReader::read_point_springs(const YAML::Node& list, Scene& scene) const {
  if (!list.IsSequence()) fail(list, "point_springs", "expected a list");
  std::vector<Pose> poses;
  body_poses(scene.model, scene.q0.data(), poses);
  for (std::size_t n = 0; n < list.size(); ++n) {
    const YAML::Node node = list[n];
    const std::string field = input::index_field("point_springs", n);
    check_keys(node,
               {"name", "body_a", "point_a", "body_b", "point_b", "stiffness", "rest_length", "damping",
                "tension_only"},
               field);
    auto s = std::make_shared<PointSpring>();
    s->named = static_cast<bool>(node["name"]);
    s->name = s->named ? name(node["name"], field + ".name") : "spring" + std::to_string(n);
    for (const PointSpring* other : scene.elements_of<PointSpring>())
      if (other->name == s->name) fail(node, field + ".name", "a point spring named '" + s->name + "' already exists");
    s->body_a = body_or_base(require(node, "body_a", field), scene, field + ".body_a");
    s->body_b = body_or_base(require(node, "body_b", field), scene, field + ".body_b");
    if (s->body_a == s->body_b) fail(node["body_b"], field + ".body_b", "both ends are on one body: it would pull on itself");
    s->point_a = vec3_or(node, "point_a", Vec3::Zero(), field);
    s->point_b = vec3_or(node, "point_b", Vec3::Zero(), field);
    s->stiffness = non_negative(require(node, "stiffness", field), field + ".stiffness");
    s->rest_length = non_negative(require(node, "rest_length", field), field + ".rest_length");
    if (node["damping"]) s->damping = non_negative(node["damping"], field + ".damping");
    if (node["tension_only"]) s->tension_only = flag(node["tension_only"], field + ".tension_only");
    const auto at = [&](int body, const Vec3& r) { return body == kBase ? r : poses[body].to_base(r); };
    if ((at(s->body_b, s->point_b) - at(s->body_a, s->point_a)).norm() < 1e-9)
      fail(node, field, "its two points coincide at the initial state: the line of the force has no direction");
    scene.elements.push_back(s);
  }
}

void SceneReader::read_loads(const YAML::Node& list, Scene& scene) const {
  if (!list.IsSequence()) fail(list, "loads", "expected a list");
  for (std::size_t n = 0; n < list.size(); ++n) {
    const YAML::Node l = list[n];
    const std::string field = input::index_field("loads", n);
    check_keys(l, {"body", "force", "torque", "point", "frame"}, field);
    auto load = std::make_shared<AppliedForce>();
    load->body = body_by_name(require(l, "body", field), scene, field + ".body");
    load->force = vec3_or(l, "force", Vec3::Zero(), field);
    load->torque = vec3_or(l, "torque", Vec3::Zero(), field);
    load->point = vec3_or(l, "point", Vec3::Zero(), field);
    if (const YAML::Node frame = l["frame"]) {
      const std::string f = text(frame, field + ".frame");
      if (f != "body" && f != "base") fail(frame, field + ".frame", "expected 'body' or 'base'");
      load->in_base_frame = f == "base";
      if (load->in_base_frame && scene.model.base_rotates())
        fail(frame, field + ".frame", "base-frame loads need a base that does not rotate");
    }
    scene.elements.push_back(load);
  }
}

void SceneReader::read_latches(const YAML::Node& list, Scene& scene) const {
  if (!list.IsSequence()) fail(list, "latches", "expected a list");
  for (std::size_t n = 0; n < list.size(); ++n) {
    const YAML::Node l = list[n];
    const std::string field = input::index_field("latches", n);
    check_keys(l, {"joint", "position", "stiffness", "damping", "free_play"}, field);
    auto latch = std::make_shared<Latch>(joint_by_name(require(l, "joint", field), scene, field + ".joint", true));
    latch->position = number_or(l, "position", 0.0, field);
    latch->stiffness = positive(require(l, "stiffness", field), field + ".stiffness");
    latch->damping = non_negative(require(l, "damping", field), field + ".damping");
    if (l["free_play"]) latch->free_play = non_negative(l["free_play"], field + ".free_play");
    for (const Latch* other : scene.latches())
      if (other->joint == latch->joint) fail(l["joint"], field + ".joint", "this joint already has a latch");
    scene.elements.push_back(latch);
  }
}

void SceneReader::read_loops(const YAML::Node& list, Scene& scene) {
  if (!list.IsSequence()) fail(list, "loops", "expected a list");
  for (std::size_t n = 0; n < list.size(); ++n) {
    const YAML::Node l = list[n];
    const std::string field = input::index_field("loops", n);
    check_keys(l, {"name", "body", "image"}, field);
    Loop loop;
    loop.body = body_by_name(require(l, "body", field), scene, field + ".body");
    loop.image = body_by_name(require(l, "image", field), scene, field + ".image");
    loop.name = l["name"] ? name(l["name"], field + ".name") : scene.model.bodies[loop.body].name;
    if (loop.body == loop.image) fail(l["image"], field + ".image", "a body cannot be its own image");
    if (on_one_branch(scene.model, loop.body, loop.image))
      fail(l["image"], field + ".image",
           "'" + scene.model.bodies[loop.image].name + "' and '" + scene.model.bodies[loop.body].name +
               "' lie on one branch of the tree (one is the other's ancestor): they do not close a loop");
    for (const Loop& other : scene.loops) {
      if (other.name == loop.name) fail(l, field + ".name", "a loop named '" + loop.name + "' already exists");
      if (other.body == loop.body || other.image == loop.image || other.body == loop.image || other.image == loop.body)
        fail(l, field, "this loop shares a split body with loop '" + other.name + "' (each loop splits a body of its own)");
    }
    scene.loops.push_back(loop);
    loop_nodes_.push_back(l);
  }
}

void SceneReader::read_regulator(const YAML::Node& node, Scene& scene) const {
  check_keys(node, {"gains", "v_max", "p0", "p1", "regularization", "feedforward", "solver"}, "regulator");
  RegulatorSettings& r = scene.regulator;
  if (const YAML::Node gains = node["gains"]) {
    const std::string g = text(gains, "regulator.gains");
    if (g == "full")
      r.gains = GainTuning::full;
    else if (g == "paper")
      r.gains = GainTuning::paper;
    else
      fail(gains, "regulator.gains", "expected 'full' or 'paper', got '" + g + "'");
  }
  if (node["v_max"]) r.v_max = positive(node["v_max"], "regulator.v_max");
  if (node["p0"]) r.p0 = positive(node["p0"], "regulator.p0");
  if (node["p1"]) r.p1 = positive(node["p1"], "regulator.p1");
  if (node["regularization"]) r.regularization = positive(node["regularization"], "regulator.regularization");
  if (node["feedforward"]) r.feedforward = flag(node["feedforward"], "regulator.feedforward");
  if (const YAML::Node solver = node["solver"]) {
    const std::string name = text(solver, "regulator.solver");
    if (name == "auto")
      r.solver = ClosureSolverKind::automatic;
    else if (name == "dense")
      r.solver = ClosureSolverKind::dense;
    else if (name == "sparse")
      r.solver = ClosureSolverKind::sparse;
    else
      fail(solver, "regulator.solver", "expected 'auto', 'dense' or 'sparse', got '" + name + "'");
  }
  if (r.p1 >= 1) fail(node["p1"], "regulator.p1", "must be below 1 (b1 = p1 v_max < v_max)");
}

void SceneReader::read_initial(const YAML::Node& node, Scene& scene) const {
  check_keys(node, {"q", "dq", "p"}, "initial");
  if (node["dq"] && node["p"]) fail(node["p"], "initial.p", "give either dq or p, not both");
  auto read = [&](const char* key, std::vector<double>& out) {
    const YAML::Node map = node[key];
    if (!map) return;
    const std::string field = std::string("initial.") + key;
    check_map(map, field);
    const bool positions = std::string(key) == "q";
    const Model& model = scene.model;
    if (!positions || out.empty()) out.assign(positions ? model.nq : model.nv, 0.0);
    for (const auto& item : map) {
      const std::string entry = field + "." + item.first.Scalar();
      const int j = joint_by_name(item.first, scene, field, false);
      const Joint& joint = model.joints[j];
      if (joint.dof() == 0) fail(item.first, field, "joint '" + joint.name + "' is fixed: it has no coordinate");
      double* x = out.data() + (positions ? model.first_position[j].value : model.first_velocity[j].value);
      if (joint.is_scalar()) {
        x[0] = number(item.second, entry);
        continue;
      }
      // A ball, planar or free joint: all its entries as a list.
      const int n = positions ? joint.positions() : joint.dof();
      const std::vector<double> values = numbers(item.second, entry);
      if (static_cast<int>(values.size()) != n)
        fail(item.second, entry,
             "a " + std::string(joint_type_name(joint.type)) + " joint takes " + std::to_string(n) + " numbers here (" +
                 entry_names(model, j, positions) + ")");
      std::copy(values.begin(), values.end(), x);
      if (positions && joint.has_quaternion()) {
        Eigen::Map<Eigen::Vector4d> quaternion(x + joint.quaternion_offset());
        if (quaternion.norm() < 1e-9) fail(item.second, entry, "the quaternion has zero length");
        quaternion.normalize();
      }
    }
  };
  read("q", scene.q0);
  read("dq", scene.dq0);
  read("p", scene.p0);
}

void SceneReader::read_run(const YAML::Node& node, RunSettings& run) const {
  check_keys(node,
             {"t_end", "integrator", "linear_solver", "rtol", "atol", "dt", "sample", "max_closure", "event_window",
              "max_steps", "max_samples", "max_wall_time"},
             "run");
  if (node["t_end"]) run.t_end = positive(node["t_end"], "run.t_end");
  if (const YAML::Node integrator = node["integrator"]) {
    const auto kind = parse_integrator(text(integrator, "run.integrator"));
    if (!kind)
      fail(integrator, "run.integrator",
           "unknown integrator '" + integrator.Scalar() +
               "' (expected cvode-bdf, cvode-adams, arkode-erk, arkode-dirk or rk4)");
    run.integrator = *kind;
  }
  if (const YAML::Node solver = node["linear_solver"]) {
    const std::string name = text(solver, "run.linear_solver");
    if (name == "auto")
      run.linear_solver = LinearSolverKind::automatic;
    else if (name == "dense")
      run.linear_solver = LinearSolverKind::dense;
    else if (name == "krylov")
      run.linear_solver = LinearSolverKind::krylov;
    else
      fail(solver, "run.linear_solver", "expected 'auto', 'dense' or 'krylov', got '" + name + "'");
  }
  if (node["rtol"]) run.rtol = positive(node["rtol"], "run.rtol");
  if (node["atol"]) run.atol = positive(node["atol"], "run.atol");
  if (node["dt"]) run.dt = positive(node["dt"], "run.dt");
  if (node["sample"]) run.sample = positive(node["sample"], "run.sample");
  if (node["max_closure"]) run.max_closure = positive(node["max_closure"], "run.max_closure");
  if (node["event_window"]) run.event_window = non_negative(node["event_window"], "run.event_window");
  if (node["max_wall_time"]) run.max_wall_time = positive(node["max_wall_time"], "run.max_wall_time");
  if (node["max_steps"]) run.max_steps = count(node["max_steps"], "run.max_steps", 1, kMostSteps);
  if (node["max_samples"]) run.max_samples = count(node["max_samples"], "run.max_samples", 1, kMostSteps);
  check_run_size(node, run);
}

// Refuses up front what cannot finish or cannot be stored: more samples
// than max_samples, or more fixed RK4 steps than max_steps.
void SceneReader::check_run_size(const YAML::Node& node, const RunSettings& run) const {
  const YAML::Node at = node["sample"] ? node["sample"] : node;
  if (run.sample > run.t_end)
    fail(at, "run.sample",
         "the output interval " + format_number(run.sample) + " s is longer than the run (t_end " +
             format_number(run.t_end) + " s)");
  const double samples = run.t_end / run.sample + 1;
  if (samples > static_cast<double>(run.max_samples))
    fail(at, "run.sample",
         "t_end / sample makes " + format_number(samples) + " samples, more than run.max_samples (" +
             std::to_string(run.max_samples) + "); raise it if the memory is there");
  const double steps = run.t_end / run.dt;
  if (run.integrator == IntegratorKind::rk4 && steps > static_cast<double>(run.max_steps))
    fail(node["dt"] ? node["dt"] : node, "run.dt",
         "t_end / dt makes " + format_number(steps) + " fixed steps, more than run.max_steps (" +
             std::to_string(run.max_steps) + ")");
}

SceneFile SceneReader::read(const std::string& text_in, const std::vector<Override>& overrides) {
  YAML::Node root = load_document(text_in);
  if (!root.IsMap()) throw input::InputError(source() + ": a scene file is a YAML mapping (name, bodies, ...)");
  for (const Override& o : overrides) apply_override(root, o, *this);

  check_keys(root,
             {"name", "description", "base", "gravity", "bodies", "springs", "dampers", "friction", "point_springs",
              "loads", "latches",
              "loops", "regulator", "initial", "closure_tolerance", "run"},
             "");
  Scene scene;
  scene.source = source();
  scene.name = root["name"] ? text(root["name"], "name") : "scene";
  if (root["description"]) scene.description = text(root["description"], "description");
  if (root["base"]) read_base(root["base"], scene);
  Vec3 gravity = Vec3::Zero();
  if (root["gravity"]) {
    gravity = vec3(root["gravity"], "gravity");
    if (!gravity.isZero(0) && scene.model.base_rotates())
      fail(root["gravity"], "gravity", "gravity needs a base that does not rotate");
  }
  const YAML::Node bodies = require(root, "bodies", "");
  if (!bodies.IsSequence() || bodies.size() == 0) fail(bodies, "bodies", "expected a non-empty list of bodies");
  for (std::size_t i = 0; i < bodies.size(); ++i) read_body(bodies[i], static_cast<int>(i), bodies, scene);
  scene.model.finalize();
  if (scene.model.nq == 0)
    fail(bodies, "bodies", "every joint is fixed: there is nothing to move or integrate (give a joint a type "
                           "that moves)");

  // The elements in the order their forces add up.
  if (root["springs"]) read_springs(root["springs"], scene);
  if (root["dampers"]) read_dampers(root["dampers"], scene);
  if (root["friction"]) read_friction(root["friction"], scene);
  if (root["latches"]) read_latches(root["latches"], scene);
  if (root["loads"]) read_loads(root["loads"], scene);
  if (!gravity.isZero(0)) scene.elements.push_back(std::make_shared<Gravity>(gravity));
  if (root["loops"]) read_loops(root["loops"], scene);
  if (root["regulator"]) read_regulator(root["regulator"], scene);
  scene.q0.assign(scene.model.nq, 0.0);
  for (int i = 0; i < scene.model.size(); ++i)
    if (scene.model.joints[i].dof() > 1) scene.model.joints[i].neutral_positions(&scene.q0[scene.model.first_position[i].value]);
  scene.dq0.assign(scene.model.nv, 0.0);
  if (root["initial"]) read_initial(root["initial"], scene);
  if (scene.dq0.size() != static_cast<std::size_t>(scene.model.nv)) scene.dq0.assign(scene.model.nv, 0.0);
  if (root["point_springs"]) read_point_springs(root["point_springs"], scene);
  if (root["closure_tolerance"]) {
    scene.closure_tolerance = positive(root["closure_tolerance"], "closure_tolerance");
    if (scene.closure_tolerance > kLargestClosureTolerance)
      fail(root["closure_tolerance"], "closure_tolerance",
           "at most " + format_number(kLargestClosureTolerance) +
               " m or rad: a loop opener than that is not a loop (the regulator would snap it shut)");
  }
  read_run(root["run"] ? root["run"] : YAML::Node(YAML::NodeType::Map), scene.run);
  check_loops_close(scene, loop_nodes_, *this);
  return {scene, visuals_};
}

}  // namespace

SceneFile read_scene_text(const std::string& text, const std::string& source, const std::vector<Override>& overrides) {
  return SceneReader(source).read(text, overrides);
}

SceneFile read_scene_file(const std::string& path, const std::vector<Override>& overrides) {
  std::ifstream in(path);
  if (!in) throw input::InputError(path + ": cannot open the scene file");
  std::stringstream text;
  text << in.rdbuf();
  return read_scene_text(text.str(), path, overrides);
}

Scene load_scene_text(const std::string& text, const std::string& source, const std::vector<Override>& overrides) {
  return read_scene_text(text, source, overrides).scene;
}

Scene load_scene_file(const std::string& path, const std::vector<Override>& overrides) {
  return read_scene_file(path, overrides).scene;
}

}  // namespace unfurl
