// Scene files (YAML) into a Scene and its visuals; the format is documented
// in assets/scenes/README.md. The reader parses: keys, types, numbers, names
// resolved to bodies and joints. The scene's rules are SceneBuilder's and
// validate()'s; their errors come back here with a field path, and the
// reader adds where in the file (or which --set) the field is.
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "scene_overrides.hpp"
#include "unfurl/input/yaml_fields.hpp"
#include "unfurl/sim/elements/all.hpp"
#include "unfurl/sim/flexible/flexible_body.hpp"
#include "unfurl/sim/flexible/plate_point.hpp"
#include "unfurl/sim/number_text.hpp"
#include "unfurl/sim/scene_builder.hpp"
#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/scene_validation.hpp"

namespace unfurl::sim {

namespace {

// The node a field path names ("bodies[3] (bob).joint.type" ->
// root["bodies"][3]["joint"]["type"]), or the deepest one that exists.
YAML::Node node_at(const YAML::Node& root, const std::string& field) {
  YAML::Node node = root;
  std::stringstream parts(field);
  for (std::string part; std::getline(parts, part, '.');) {
    if (const auto paren = part.find(" ("); paren != std::string::npos) part.erase(paren);
    const auto bracket = part.find('[');
    const std::string key = part.substr(0, bracket);
    const YAML::Node& here = node;  // const: looking a key up must not add it
    if (!here.IsMap() || !here[key]) return node;
    YAML::Node next = here[key];
    if (bracket != std::string::npos) {
      const std::size_t index = std::stoul(part.substr(bracket + 1));
      if (!next.IsSequence() || index >= next.size()) return next;
      next.reset(next[index]);
    }
    node.reset(next);
  }
  return node;
}

class SceneReader : private input::YamlFields {
 public:
  explicit SceneReader(std::string source) : YamlFields(std::move(source)) {}

  SceneFile read(const std::string& text, const std::vector<Override>& overrides);

 private:
  void read_base(const YAML::Node& node, SceneBuilder& b);
  void read_body(const YAML::Node& node, int index, const YAML::Node& all, SceneBuilder& b) const;
  Body read_mass_properties(const YAML::Node& node, const std::string& field) const;
  std::shared_ptr<const flexible::FlexibleBody> read_flexible(const YAML::Node& node, const std::string& name,
                                                              const YAML::Node& all, const std::string& field) const;
  flexible::BeamSection read_beam_section(const YAML::Node& node, const std::string& field) const;
  flexible::PlateBodySpec read_plate(const YAML::Node& node, const std::string& field) const;
  std::string fem_path(const YAML::Node& node, const std::string& field) const;
  flexible::ModalDamping read_modal_damping(const YAML::Node& node, const std::string& field) const;
  Joint read_joint(const YAML::Node& node, const std::string& field) const;
  std::shared_ptr<JointCompliance> read_compliance(const YAML::Node& node, int joint, const std::string& field) const;
  Visual read_visual(const YAML::Node& node, const std::string& field) const;
  std::vector<CollisionShape> read_collision(const YAML::Node& node, const std::string& field) const;
  CollisionShape read_collision_shape(const YAML::Node& node, const std::string& field) const;
  Vec3 read_scale(const YAML::Node& scale, const std::string& field) const;
  void read_rotation(const YAML::Node& rotation, const std::string& field, Vec3& axis, double& degrees) const;
  void read_springs(const YAML::Node& list, SceneBuilder& b) const;
  void read_dampers(const YAML::Node& list, SceneBuilder& b) const;
  void read_stops(const YAML::Node& list, SceneBuilder& b) const;
  void read_limits(const YAML::Node& list, SceneBuilder& b) const;
  void read_friction(const YAML::Node& list, SceneBuilder& b) const;
  std::shared_ptr<const SpringCurve> spring_curve(const YAML::Node& table, const std::string& field) const;
  void read_point_springs(const YAML::Node& list, SceneBuilder& b) const;
  void read_bushings(const YAML::Node& list, SceneBuilder& b) const;
  Mat6 read_matrix6(const YAML::Node& node, const std::string& field) const;
  void read_bushing_frame(const YAML::Node& node, char end, const SceneBuilder& b, const std::string& field,
                          BushingFrame& frame) const;
  int element_body(const YAML::Node& entry, const char* key, const SceneBuilder& b, const std::string& field) const;
  void read_applied_forces(const YAML::Node& list, SceneBuilder& b) const;
  void read_latches(const YAML::Node& list, SceneBuilder& b) const;
  void read_drivers(const YAML::Node& list, SceneBuilder& b) const;
  void read_loops(const YAML::Node& list, SceneBuilder& b) const;
  void read_sensors(const YAML::Node& list, SceneBuilder& b) const;
  RegulatorSettings read_regulator(const YAML::Node& node) const;
  void read_initial(const YAML::Node& node, SceneBuilder& b) const;
  RunSettings read_run(const YAML::Node& node) const;
  TorqueMarginFactors read_torque_margin(const YAML::Node& node) const;
  // Each item of a list, checked to be a mapping of the given keys.
  template <class Read>
  void each(const YAML::Node& list, const char* name, Keys keys, Read read) const;
  // The joint a list entry names, for an element acting on it.
  int element_joint(const YAML::Node& entry, const SceneBuilder& b, const std::string& field) const;

  // The file: the sensors and the elements' points on a flexible body make
  // its nodes.
  YAML::Node root_;
};

template <class Read>
void SceneReader::each(const YAML::Node& list, const char* name, Keys keys, Read read) const {
  if (!list.IsSequence()) fail(list, name, "expected a list");
  for (std::size_t n = 0; n < list.size(); ++n) {
    const std::string field = input::index_field(name, n);
    check_keys(list[n], keys, field);
    read(list[n], field, n);
  }
}

int SceneReader::element_joint(const YAML::Node& entry, const SceneBuilder& b, const std::string& field) const {
  const YAML::Node joint = require(entry, "joint", field);
  return b.joint_index(text(joint, field + ".joint"), field + ".joint");
}

Vec3 SceneReader::read_scale(const YAML::Node& scale, const std::string& field) const {
  if (scale.IsScalar()) return Vec3::Constant(positive(scale, field));
  const Vec3 v = vec3(scale, field);
  if ((v.array() <= 0).any()) fail(scale, field, "must be positive");
  return v;
}

void SceneReader::read_rotation(const YAML::Node& rotation, const std::string& field, Vec3& axis,
                                double& degrees) const {
  const std::vector<double> r = numbers(rotation, field);
  if (r.size() != 4 || Vec3(r[0], r[1], r[2]).norm() < 1e-12)
    fail(rotation, field, "expected [axis x, axis y, axis z, angle in degrees] with a nonzero axis");
  axis = Vec3(r[0], r[1], r[2]).normalized();
  degrees = r[3];
}

Visual SceneReader::read_visual(const YAML::Node& node, const std::string& field) const {
  Visual v;
  if (node.IsScalar()) {
    v.mesh = node.Scalar();
    return v;
  }
  check_keys(node, {"name", "scale", "rotation", "offset"}, field);
  v.mesh = text(require(node, "name", field), field + ".name");
  if (const YAML::Node scale = node["scale"]) v.scale = read_scale(scale, field + ".scale");
  if (const YAML::Node rotation = node["rotation"])
    read_rotation(rotation, field + ".rotation", v.rotation_axis, v.rotation_deg);
  v.offset = vec3_or(node, "offset", Vec3::Zero(), field);
  return v;
}

// `collision: none`, or a list of shapes.
std::vector<CollisionShape> SceneReader::read_collision(const YAML::Node& node, const std::string& field) const {
  if (node.IsScalar() && node.Scalar() == "none") return {};
  if (!node.IsSequence())
    fail(node, field, "expected `none` or a list of shapes ({box: [x, y, z]}, {sphere: r}, "
                      "{cylinder: [radius, length]}, {mesh: NAME})");
  std::vector<CollisionShape> shapes;
  for (std::size_t n = 0; n < node.size(); ++n)
    shapes.push_back(read_collision_shape(node[n], input::index_field(field, n)));
  return shapes;
}

CollisionShape SceneReader::read_collision_shape(const YAML::Node& node, const std::string& field) const {
  check_keys(node, {"box", "sphere", "cylinder", "mesh", "scale", "rotation", "offset"}, field);
  CollisionShape c;
  int kinds = 0;
  if (const YAML::Node box = node["box"]) {
    c.kind = CollisionShape::Kind::box;
    c.size = vec3(box, field + ".box");
    if ((c.size.array() <= 0).any()) fail(box, field + ".box", "edge lengths must be positive");
    ++kinds;
  }
  if (const YAML::Node sphere = node["sphere"]) {
    c.kind = CollisionShape::Kind::sphere;
    c.radius = positive(sphere, field + ".sphere");
    ++kinds;
  }
  if (const YAML::Node cylinder = node["cylinder"]) {
    c.kind = CollisionShape::Kind::cylinder;
    const std::vector<double> r = numbers(cylinder, field + ".cylinder");
    if (r.size() != 2 || !(r[0] > 0) || !(r[1] > 0))
      fail(cylinder, field + ".cylinder", "expected [radius, length], both positive");
    c.radius = r[0];
    c.length = r[1];
    ++kinds;
  }
  if (const YAML::Node mesh = node["mesh"]) {
    c.kind = CollisionShape::Kind::mesh;
    c.mesh = text(mesh, field + ".mesh");
    ++kinds;
  }
  if (kinds != 1) fail(node, field, "expected one of box, sphere, cylinder or mesh");
  if (const YAML::Node scale = node["scale"]) {
    if (c.kind != CollisionShape::Kind::mesh) fail(scale, field + ".scale", "only a mesh is scaled (give a box its size)");
    c.scale = read_scale(scale, field + ".scale");
  }
  if (const YAML::Node rotation = node["rotation"])
    read_rotation(rotation, field + ".rotation", c.rotation_axis, c.rotation_deg);
  c.offset = vec3_or(node, "offset", Vec3::Zero(), field);
  return c;
}

void SceneReader::read_base(const YAML::Node& node, SceneBuilder& b) {
  check_keys(node, {"name", "mesh", "collision", "velocity", "free", "mass", "com", "inertia"}, "base");
  const std::string name = node["name"] ? text(node["name"], "base.name") : "base";
  Visual visual = node["mesh"] ? read_visual(node["mesh"], "base.mesh") : Visual{};
  if (node["collision"]) visual.collision = read_collision(node["collision"], "base.collision");
  const bool free = node["free"] && flag(node["free"], "base.free");
  if (free) {
    if (node["velocity"]) fail(node["velocity"], "base.velocity", "a free base moves by itself: give no velocity");
    Body bus = read_mass_properties(node, "base");
    bus.name = name;
    b.free_base(bus, visual);
    return;
  }
  for (const char* key : {"mass", "com", "inertia"})
    if (node[key]) fail(node[key], std::string("base.") + key, "only a free base (`free: true`) has mass properties");
  Vec6 velocity = Vec6::Zero();
  if (const YAML::Node v = node["velocity"]) {
    const std::vector<double> x = numbers(v, "base.velocity");
    if (x.size() != 6) fail(v, "base.velocity", "expected 6 numbers (vx, vy, vz, wx, wy, wz)");
    for (int k = 0; k < 6; ++k) velocity[k] = x[k];
  }
  b.fixed_base(name, velocity, visual);
}

Joint SceneReader::read_joint(const YAML::Node& node, const std::string& field) const {
  check_keys(node, {"name", "type", "axis", "axis2", "parent_point", "child_point", "compliance"}, field);
  Joint j;
  const YAML::Node type = require(node, "type", field);
  const std::string t = text(type, field + ".type");
  const auto parsed = parse_joint_type(t);
  if (!parsed)
    fail(type, field + ".type",
         "unknown joint type '" + t + "' (expected revolute, prismatic, fixed, universal, spherical, planar or free)");
  j.type = *parsed;
  const bool axial = j.type == JointType::revolute || j.type == JointType::prismatic || j.type == JointType::planar ||
                     j.type == JointType::universal;
  if (axial)
    j.axis = vec3(require(node, "axis", field), field + ".axis");
  else if (node["axis"])
    fail(node["axis"], field + ".axis", std::string("a ") + joint_type_name(j.type) + " joint has no axis");
  if (j.type == JointType::universal)
    j.axis2 = vec3(require(node, "axis2", field), field + ".axis2");
  else if (node["axis2"])
    fail(node["axis2"], field + ".axis2", "only a universal joint has a second axis");
  j.parent_point = vec3(require(node, "parent_point", field), field + ".parent_point");
  j.child_point = vec3(require(node, "child_point", field), field + ".child_point");
  if (node["name"]) j.name = text(node["name"], field + ".name");
  if (const YAML::Node compliance = node["compliance"]) {
    if (j.type != JointType::revolute)
      fail(compliance, field + ".compliance",
           std::string("compliance is for revolute joints (this one is ") + joint_type_name(j.type) + ")");
    j.compliant = true;
  }
  return j;
}

std::shared_ptr<JointCompliance> SceneReader::read_compliance(const YAML::Node& node, int joint,
                                                               const std::string& field) const {
  check_keys(node, {"radial", "axial", "tilt", "radial_damping", "axial_damping", "tilt_damping"}, field);
  auto c = std::make_shared<JointCompliance>();
  c->joint = joint;
  c->radial = number(require(node, "radial", field), field + ".radial");
  c->axial = number(require(node, "axial", field), field + ".axial");
  c->tilt = number(require(node, "tilt", field), field + ".tilt");
  const auto optional = [&](const char* key) { return node[key] ? number(node[key], field + "." + key) : 0.0; };
  c->radial_damping = optional("radial_damping");
  c->axial_damping = optional("axial_damping");
  c->tilt_damping = optional("tilt_damping");
  return c;
}

// mass, com and inertia of a body (or of a free base).
Body SceneReader::read_mass_properties(const YAML::Node& node, const std::string& field) const {
  Body b;
  b.mass = number(require(node, "mass", field), field + ".mass");
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
  return b;
}

void SceneReader::read_body(const YAML::Node& node, int index, const YAML::Node& all, SceneBuilder& b) const {
  std::string field = input::index_field("bodies", index);
  check_keys(node, {"name", "parent", "mass", "com", "inertia", "flexible", "mesh", "collision", "joint"}, field);
  const std::string name = text(require(node, "name", field), field + ".name");
  field += " (" + name + ")";
  const YAML::Node parent = require(node, "parent", field);
  const std::string parent_name = text(parent, field + ".parent");
  if (!b.has_body(parent_name))
    for (std::size_t later = index + 1; later < all.size(); ++later)
      if (all[later].IsMap() && all[later]["name"] && all[later]["name"].Scalar() == parent_name)
        fail(parent, field + ".parent",
             "numbering is not regular: the parent '" + parent_name + "' is listed after its child (list " +
                 "every body after its parent)");
  Body body;
  if (const YAML::Node flexible = node["flexible"]) {
    for (const char* key : {"mass", "com", "inertia"})
      if (node[key])
        fail(node[key], field + "." + key, "a flexible body's mass properties are its structure's (leave out " +
                                               std::string(key) + ")");
    body.flexible = read_flexible(flexible, name, all, field + ".flexible");
  } else {
    body = read_mass_properties(node, field);
  }
  body.name = name;
  const Joint joint = read_joint(require(node, "joint", field), field + ".joint");
  // In a file the free-floating bus is the base's (`base: {free: true}`).
  if (joint.type == JointType::free)
    fail(node["joint"]["type"], field + ".joint.type",
         "a free joint is for a free-floating base only: give the base `free: true` and its mass properties");
  Visual visual = node["mesh"] ? read_visual(node["mesh"], field + ".mesh") : Visual{};
  if (node["collision"]) visual.collision = read_collision(node["collision"], field + ".collision");
  b.body(body, parent_name, joint, visual);
  if (joint.compliant)
    b.element(read_compliance(node["joint"]["compliance"], b.joint_index(joint.name.empty() ? name : joint.name, field),
                              field + ".joint.compliance"));
}

// Where a point may not attach to a beam, said as the rest of an error
// ("... sits at a mesh node ..."), or empty where it may.
std::string beam_attachment_error(const flexible::BeamBodySpec& spec, const Vec3& p) {
  const double L = spec.section.length, h = L / spec.section.elements;
  const double x = Vec3::Unit(spec.axis).dot(p - spec.root), node_x = h * std::round(x / h);
  if (std::abs(x - node_x) <= 1e-9 * L && x >= -1e-9 * L && x <= L * (1 + 1e-9)) return "";
  return "at a mesh node (or on a rigid bracket beside one): its distance along the axis from the root a multiple of " +
         format_number(h) + " m (length / elements) in [0, " + format_number(L) + "]";
}

std::string plate_attachment_error(const flexible::PlateBodySpec& spec, const Vec3& p) {
  if (flexible::locate(spec, p).attaches()) return "";
  const flexible::PlateSpec& s = spec.plate;
  return "on the plate (its own x in [0, " + format_number(s.length_x) + "], y in [0, " + format_number(s.length_y) +
         "] from its corner), on its root edge or a hinge line, or over a mesh node (x a multiple of " +
         format_number(s.length_x / s.elements_x) + " m, y of " + format_number(s.length_y / s.elements_y) +
         " m), on the plate or on a rigid bracket off it";
}

// How many elastic coordinates a body has (-1 where it cannot be made),
// its damping aside: a ratio list of the wrong length is the damping
// field's fault, not the body's.
template <class Spec, class Make>
int elastic_coordinates(Spec spec, Make make) {
  spec.damping = flexible::ModalDamping::uniform(0);
  try {
    return make(spec).modes();
  } catch (const std::invalid_argument&) {
    return -1;
  }
}

// Where a point may not attach to an FE model, as beam_attachment_error.
std::string fem_attachment_error(const flexible::FemBodySpec& spec, const Vec3& p) {
  if (spec.model->attaches(p)) return "";
  return "at a node of the FE model (its coordinates are the body frame's) or at the frame's origin";
}

// A flexible body (docs/FLEXIBLE.md): its structure (a beam, a plate or a
// reduced FE model), the modes kept and their damping. The points its
// children's joints hang on, its sensors' and the points where elements
// push on it become the reduction's interface nodes, so they must lie at
// mesh nodes, on a plate's hinge lines, or on brackets beside them.
std::shared_ptr<const flexible::FlexibleBody> SceneReader::read_flexible(const YAML::Node& node,
                                                                         const std::string& name,
                                                                         const YAML::Node& all,
                                                                         const std::string& field) const {
  check_keys(node, {"beam", "plate", "fem", "modes", "damping", "geometric_stiffening"}, field);
  const int kinds = static_cast<int>(node["beam"].IsDefined()) + static_cast<int>(node["plate"].IsDefined()) +
                    static_cast<int>(node["fem"].IsDefined());
  if (kinds > 1) {
    const char* second = node["beam"] && node["plate"] ? "plate" : "fem";
    fail(node[second], field + "." + second, "a flexible body is a beam, a plate or an FE model (`fem`), not several");
  }
  if (kinds == 0) fail(node, field, "a flexible body is a `beam`, a `plate` or an FE model (`fem: file.fem`)");
  const bool plate = static_cast<bool>(node["plate"]), fem = static_cast<bool>(node["fem"]);
  const char* kind = fem ? "FE model" : plate ? "plate" : "beam";
  flexible::BeamBodySpec beam;
  flexible::PlateBodySpec panel;
  flexible::FemBodySpec model;
  if (plate || fem) {
    if (node["geometric_stiffening"])
      fail(node["geometric_stiffening"], field + ".geometric_stiffening",
           plate ? "a plate carries no foreshortening (its stiffening by in-plane loads is a membrane effect, left out)"
                 : "an FE model carries no foreshortening (its stiffening is its own modes', as the file gives them)");
  }
  if (plate) {
    panel = read_plate(node["plate"], field + ".plate");
  } else if (fem) {
    model.file = fem_path(node["fem"], field + ".fem");
    try {
      model.model = std::make_shared<const flexible::FemModel>(flexible::read_fem(model.file));
    } catch (const flexible::FemFileError& e) {
      fail(node["fem"], field + ".fem", e.what());
    }
    model.damping_from_file = !node["damping"] && model.model->damping.size() > 0;
  } else {
    beam.section = read_beam_section(node["beam"], field + ".beam");
    if (node["geometric_stiffening"])
      beam.geometric_stiffening = flag(node["geometric_stiffening"], field + ".geometric_stiffening");
    const YAML::Node b = node["beam"];
    if (const YAML::Node root = b["root"]) beam.root = vec3(root, field + ".beam.root");
    if (const YAML::Node axis = b["axis"]) {
      const std::string a = text(axis, field + ".beam.axis");
      if (a != "x" && a != "y" && a != "z") fail(axis, field + ".beam.axis", "expected x, y or z (the body axis the beam runs along)");
      beam.axis = a[0] - 'x';
    }
  }
  int& normal_modes = fem ? model.normal_modes : plate ? panel.normal_modes : beam.normal_modes;
  double& modes_up_to_hz = fem ? model.modes_up_to_hz : plate ? panel.modes_up_to_hz : beam.modes_up_to_hz;
  flexible::ModalDamping& damping = fem ? model.damping : plate ? panel.damping : beam.damping;
  std::vector<Vec3>& attachments = fem ? model.attachments : plate ? panel.attachments : beam.attachments;
  // A count of fixed-interface modes, or every one up to a frequency.
  if (const YAML::Node modes = node["modes"]; modes && modes.IsMap()) {
    check_keys(modes, {"up_to"}, field + ".modes");
    modes_up_to_hz = positive(require(modes, "up_to", field + ".modes"), field + ".modes.up_to");
  } else if (modes) {
    normal_modes = static_cast<int>(count(modes, field + ".modes", fem ? 1 : 0, flexible::kMaxModes));
  }
  if (node["damping"]) damping = read_modal_damping(node["damping"], field + ".damping");
  // A point where something attaches: at a mesh node (a beam's, on its
  // axis; a plate's, or anywhere on a hinge line), on the body or on a
  // rigid bracket beside it; an FE model's node.
  const auto attach = [&](const Vec3& p, const YAML::Node& at_node, const std::string& at, const char* what) {
    const std::string where = fem     ? fem_attachment_error(model, p)
                              : plate ? plate_attachment_error(panel, p)
                                      : beam_attachment_error(beam, p);
    if (!where.empty())
      fail(at_node, at, std::string("a ") + what + " of the flexible " + kind + " '" + name + "' sits " + where);
    attachments.push_back(p);
  };
  // Each entry of a list whose `body` key names this body, at its point; a
  // missing point is the body's origin.
  const auto attach_entries = [&](const char* list, const char* body, const char* point, const char* what) {
    const YAML::Node entries = root_[list];
    if (!entries || !entries.IsSequence()) return;
    for (std::size_t k = 0; k < entries.size(); ++k) {
      const YAML::Node e = entries[k];
      if (!e.IsMap() || !e[body] || !e[body].IsScalar() || e[body].Scalar() != name) continue;
      const std::string at = input::index_field(list, k) + "." + point;
      if (e[point]) attach(vec3(e[point], at), e[point], at, what);
      else attach(Vec3::Zero(), e, at, what);
    }
  };
  attach_entries("sensors", "body", "point", "sensor");
  attach_entries("point_springs", "body_a", "point_a", "point spring's end");
  attach_entries("point_springs", "body_b", "point_b", "point spring's end");
  attach_entries("bushings", "body_a", "point_a", "bushing's end");
  attach_entries("bushings", "body_b", "point_b", "bushing's end");
  attach_entries("applied_forces", "body", "point", "applied force's point");
  for (std::size_t c = 0; c < all.size(); ++c) {
    const YAML::Node child = all[c];
    if (!child.IsMap() || !child["parent"] || !child["parent"].IsScalar() || child["parent"].Scalar() != name ||
        !child["joint"] || !child["joint"].IsMap() || !child["joint"]["parent_point"])
      continue;
    const std::string at = input::index_field("bodies", c) + ".joint.parent_point";
    attach(vec3(child["joint"]["parent_point"], at), child["joint"]["parent_point"], at, "child");
  }
  const auto make_beam = [](const flexible::BeamBodySpec& s) { return flexible::beam_body(s); };
  const auto make_plate = [](const flexible::PlateBodySpec& s) { return flexible::plate_body(s); };
  const auto make_fem = [](const flexible::FemBodySpec& s) { return flexible::fem_body(s); };
  try {
    return std::make_shared<const flexible::FlexibleBody>(fem     ? make_fem(model)
                                                          : plate ? make_plate(panel)
                                                                  : make_beam(beam));
  } catch (const std::invalid_argument& e) {
    const std::size_t ratios = damping.per_coordinate.size();
    const int coordinates = fem     ? elastic_coordinates(model, make_fem)
                            : plate ? elastic_coordinates(panel, make_plate)
                                    : elastic_coordinates(beam, make_beam);
    if (ratios > 0 && static_cast<int>(ratios) != coordinates) fail(node["damping"], field + ".damping", e.what());
    fail(fem ? node["fem"] : node, fem ? field + ".fem" : field, e.what());
  }
}

// An FE model's file: relative to the scene file's directory, as a mesh
// is; kept absolute, so that a scene written elsewhere reads it back.
std::string SceneReader::fem_path(const YAML::Node& node, const std::string& field) const {
  const std::filesystem::path given = text(node, field);
  if (given.empty()) fail(node, field, "expected the path of a modal data file (.fem)");
  if (given.is_absolute()) return given.lexically_normal().string();
  const std::filesystem::path scene = source();
  const std::filesystem::path directory = scene.has_parent_path() ? scene.parent_path() : std::filesystem::path(".");
  return std::filesystem::absolute(directory / given).lexically_normal().string();
}

// A rectangular plate's properties and placement: its bending stiffness D
// given, or Young's modulus and the thickness (D = E t^3 / (12 (1 -
// nu^2))); its mass per area always given (a panel's carries cells, cover
// glass and adhesive that add mass, not stiffness).
flexible::PlateBodySpec SceneReader::read_plate(const YAML::Node& node, const std::string& field) const {
  check_keys(node, {"size", "corner", "normal", "bending_stiffness", "youngs_modulus", "thickness", "poisson",
                    "mass_per_area", "elements", "root_edge", "hinge_lines", "brackets"},
             field);
  flexible::PlateBodySpec spec;
  flexible::PlateSpec& p = spec.plate;
  const YAML::Node size = require(node, "size", field);
  const std::vector<double> ab = numbers(size, field + ".size");
  if (ab.size() != 2 || !(ab[0] > 0) || !(ab[1] > 0))
    fail(size, field + ".size", "expected two positive lengths, [along the plate's x, along its y]");
  p.length_x = ab[0], p.length_y = ab[1];
  p.poisson = number(require(node, "poisson", field), field + ".poisson");
  if (!(p.poisson > -1 && p.poisson < 0.5)) fail(node["poisson"], field + ".poisson", "Poisson's ratio lies in (-1, 0.5)");
  if (node["bending_stiffness"]) {
    for (const char* key : {"youngs_modulus", "thickness"})
      if (node[key])
        fail(node[key], field + "." + key,
             "give the bending stiffness or Young's modulus and the thickness, not both");
    p.bending_stiffness = positive(node["bending_stiffness"], field + ".bending_stiffness");
  } else {
    if (!node["youngs_modulus"] || !node["thickness"])
      fail(node, field, "expected bending_stiffness (D, N m), or youngs_modulus (Pa) and thickness (m)");
    spec.youngs_modulus = positive(node["youngs_modulus"], field + ".youngs_modulus");
    spec.thickness = positive(node["thickness"], field + ".thickness");
    p.bending_stiffness = spec.youngs_modulus * std::pow(spec.thickness, 3) / (12 * (1 - p.poisson * p.poisson));
  }
  p.mass_per_area = positive(require(node, "mass_per_area", field), field + ".mass_per_area");
  if (const YAML::Node elements = node["elements"]) {
    if (!elements.IsSequence() || elements.size() != 2)
      fail(elements, field + ".elements", "expected two counts, [along x, along y]");
    p.elements_x = static_cast<int>(count(elements[0], field + ".elements[0]", 1, 24));
    p.elements_y = static_cast<int>(count(elements[1], field + ".elements[1]", 1, 24));
  }
  spec.corner = vec3_or(node, "corner", Vec3::Zero(), field);
  if (const YAML::Node normal = node["normal"]) {
    const std::string a = text(normal, field + ".normal");
    if (a != "x" && a != "y" && a != "z") fail(normal, field + ".normal", "expected x, y or z (the body axis normal to the plate)");
    spec.normal = a[0] - 'x';
  }
  const auto edge = [&](const YAML::Node& e, const std::string& at) {
    const std::string t = text(e, at);
    if (t == "x0") return flexible::PlateEdge::x0;
    if (t == "x1") return flexible::PlateEdge::x1;
    if (t == "y0") return flexible::PlateEdge::y0;
    if (t == "y1") return flexible::PlateEdge::y1;
    fail(e, at, "expected an edge: x0, x1, y0 or y1 (the plate's own x = 0, x = its length, y = 0, y = its length)");
  };
  if (node["root_edge"]) spec.root_edge = edge(node["root_edge"], field + ".root_edge");
  if (const YAML::Node lines = node["hinge_lines"]) {
    if (!lines.IsSequence()) fail(lines, field + ".hinge_lines", "expected a list of edges, [x0, x1, y0, y1]");
    for (std::size_t k = 0; k < lines.size(); ++k) {
      const std::string at = input::index_field(field + ".hinge_lines", k);
      const flexible::PlateEdge e = edge(lines[k], at);
      if (e == spec.root_edge) fail(lines[k], at, "the root edge is held to the frame already");
      const bool along_x = e == flexible::PlateEdge::x0 || e == flexible::PlateEdge::x1;
      const bool root_along_x = spec.root_edge == flexible::PlateEdge::x0 || spec.root_edge == flexible::PlateEdge::x1;
      if (along_x != root_along_x)
        fail(lines[k], at,
             "a hinge line is the edge opposite the root edge: this one meets it at a corner, which the root holds");
      for (flexible::PlateEdge seen : spec.hinge_lines)
        if (seen == e) fail(lines[k], at, "this edge is listed twice");
      spec.hinge_lines.push_back(e);
    }
  }
  if (const YAML::Node brackets = node["brackets"]) {
    const bool along_x = spec.root_edge == flexible::PlateEdge::y0 || spec.root_edge == flexible::PlateEdge::y1;
    const double edge_length = along_x ? p.length_x : p.length_y;
    if (!brackets.IsSequence() || brackets.size() == 0)
      fail(brackets, field + ".brackets", "expected a list of spans along the hinge lines, [[from, to], ...] (m)");
    for (std::size_t k = 0; k < brackets.size(); ++k) {
      const std::string at = input::index_field(field + ".brackets", k);
      const std::vector<double> span = numbers(brackets[k], at);
      if (span.size() != 2 || !(span[0] >= 0) || !(span[0] <= span[1]) || !(span[1] <= edge_length))
        fail(brackets[k], at,
             "expected a span [from, to] along the edge, 0 <= from <= to <= " + format_number(edge_length) +
                 " m (the edge's length)");
      const double h = edge_length / (along_x ? p.elements_x : p.elements_y);
      if (std::ceil(span[0] / h - 1e-9) > std::floor(span[1] / h + 1e-9))
        fail(brackets[k], at,
             "this span fastens no mesh node: they lie " + format_number(h) +
                 " m apart along the edge (its length / elements); widen it or refine the mesh");
      spec.brackets.push_back({span[0], span[1]});
    }
  }
  return spec;
}

// A flexible body's damping: one ratio for every coordinate, one each
// ([0.01, 0.02, ...]), or bands of the coordinates' frequencies
// ([{up_to: 100, ratio: 0.005}, ..., {ratio: 0.5}], the last open-ended).
flexible::ModalDamping SceneReader::read_modal_damping(const YAML::Node& node, const std::string& field) const {
  const auto ratio = [&](const YAML::Node& r, const std::string& at) {
    const double zeta = non_negative(r, at);
    if (zeta >= 1) fail(r, at, "a modal damping ratio is below 1");
    return zeta;
  };
  if (!node.IsSequence()) return flexible::ModalDamping::uniform(ratio(node, field));
  if (node.size() == 0) fail(node, field, "expected a ratio, a ratio per coordinate, or frequency bands");
  std::size_t bands = 0;
  for (std::size_t k = 0; k < node.size(); ++k) bands += node[k].IsMap() ? 1 : 0;
  if (bands != 0 && bands != node.size())
    fail(node, field, "either a ratio per coordinate or frequency bands, not both");
  flexible::ModalDamping damping;
  damping.bands.clear();
  for (std::size_t k = 0; k < node.size(); ++k) {
    const std::string at = input::index_field(field, k);
    if (!node[k].IsMap()) {
      damping.per_coordinate.push_back(ratio(node[k], at));
      continue;
    }
    check_keys(node[k], {"up_to", "ratio"}, at);
    flexible::DampingBand band;
    band.ratio = ratio(require(node[k], "ratio", at), at + ".ratio");
    const bool last = k + 1 == node.size();
    if (node[k]["up_to"]) {
      if (last) fail(node[k]["up_to"], at + ".up_to", "the last band has no up_to: it holds every higher frequency");
      band.up_to_hz = positive(node[k]["up_to"], at + ".up_to");
      if (!damping.bands.empty() && band.up_to_hz <= damping.bands.back().up_to_hz)
        fail(node[k]["up_to"], at + ".up_to", "bands go up in frequency");
    } else if (!last) {
      fail(node[k], at, "a band before the last says up_to which frequency (Hz) it holds");
    }
    damping.bands.push_back(band);
  }
  return damping;
}

// A beam's section along its axis (read_flexible places it). One bending
// stiffness is both planes'.
flexible::BeamSection SceneReader::read_beam_section(const YAML::Node& node, const std::string& field) const {
  check_keys(node, {"length", "axial_stiffness", "bending_stiffness", "torsional_stiffness", "mass_per_length",
                    "polar_inertia_per_length", "elements", "root", "axis"},
             field);
  flexible::BeamSection s;
  s.length = positive(require(node, "length", field), field + ".length");
  s.axial_stiffness = positive(require(node, "axial_stiffness", field), field + ".axial_stiffness");
  const YAML::Node bending = require(node, "bending_stiffness", field);
  if (bending.IsSequence()) {
    const std::vector<double> EI = numbers(bending, field + ".bending_stiffness");
    if (EI.size() != 2 || !(EI[0] > 0) || !(EI[1] > 0))
      fail(bending, field + ".bending_stiffness", "expected one positive number or two, [EI_y, EI_z]");
    s.bending_stiffness_y = EI[0], s.bending_stiffness_z = EI[1];
  } else {
    s.bending_stiffness_y = s.bending_stiffness_z = positive(bending, field + ".bending_stiffness");
  }
  s.torsional_stiffness = positive(require(node, "torsional_stiffness", field), field + ".torsional_stiffness");
  s.mass_per_length = positive(require(node, "mass_per_length", field), field + ".mass_per_length");
  s.polar_inertia_per_length =
      positive(require(node, "polar_inertia_per_length", field), field + ".polar_inertia_per_length");
  s.elements = static_cast<int>(node["elements"] ? count(node["elements"], field + ".elements", 1, 200) : 16);
  return s;
}

void SceneReader::read_springs(const YAML::Node& list, SceneBuilder& b) const {
  each(list, "springs", {"joint", "stiffness", "free_position", "preload_torque", "preload_angle", "damping", "table"},
       [&](const YAML::Node& s, const std::string& field, std::size_t) {
         auto spring = std::make_shared<JointSpring>(element_joint(s, b, field));
         if (const YAML::Node table = s["table"]) {
           for (const char* key : {"stiffness", "free_position", "preload_torque", "preload_angle"})
             if (s[key]) fail(s[key], field + "." + key, "a spring with a table takes its torque from the table alone");
           spring->curve = spring_curve(table, field + ".table");
         } else {
           spring->stiffness = number(require(s, "stiffness", field), field + ".stiffness");
           spring->free_position = number_or(s, "free_position", 0.0, field);
           // The preload as a torque at an angle: tau = -k (q - q_free) is
           // preload_torque at preload_angle.
           if (s["preload_torque"] || s["preload_angle"]) {
             if (s["free_position"])
               fail(s["free_position"], field + ".free_position",
                    "give the preload as free_position or as preload_torque at preload_angle, not both");
             const double torque = number(require(s, "preload_torque", field), field + ".preload_torque");
             const double angle = number(require(s, "preload_angle", field), field + ".preload_angle");
             if (!(spring->stiffness > 0))
               fail(s["stiffness"], field + ".stiffness", "a preload given as a torque needs a positive stiffness");
             spring->free_position = angle + torque / spring->stiffness;
           }
         }
         spring->damping = number_or(s, "damping", 0.0, field);
         b.element(spring);
       });
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

void SceneReader::read_dampers(const YAML::Node& list, SceneBuilder& b) const {
  each(list, "dampers", {"joint", "damping"}, [&](const YAML::Node& d, const std::string& field, std::size_t) {
    auto damper = std::make_shared<JointDamper>(element_joint(d, b, field));
    damper->damping = number(require(d, "damping", field), field + ".damping");
    b.element(damper);
  });
}

void SceneReader::read_stops(const YAML::Node& list, SceneBuilder& b) const {
  each(list, "stops", {"joint", "position", "stiffness", "damping"},
       [&](const YAML::Node& s, const std::string& field, std::size_t) {
         auto stop = std::make_shared<JointStop>(element_joint(s, b, field));
         stop->position = number(require(s, "position", field), field + ".position");
         stop->stiffness = number(require(s, "stiffness", field), field + ".stiffness");
         stop->damping = number_or(s, "damping", 0.0, field);
         b.element(stop);
       });
}

void SceneReader::read_limits(const YAML::Node& list, SceneBuilder& b) const {
  each(list, "limits", {"joint", "lower", "upper", "stiffness", "damping"},
       [&](const YAML::Node& l, const std::string& field, std::size_t) {
         auto limit = std::make_shared<JointLimit>(element_joint(l, b, field));
         if (!l["lower"] && !l["upper"]) fail(l, field, "give lower, upper or both: the ends of the joint's range");
         limit->lower = number_or(l, "lower", limit->lower, field);
         limit->upper = number_or(l, "upper", limit->upper, field);
         limit->stiffness = number(require(l, "stiffness", field), field + ".stiffness");
         limit->damping = number_or(l, "damping", 0.0, field);
         b.element(limit);
       });
}

void SceneReader::read_friction(const YAML::Node& list, SceneBuilder& b) const {
  each(list, "friction", {"joint", "coulomb", "viscous", "velocity_scale"},
       [&](const YAML::Node& f, const std::string& field, std::size_t) {
         auto friction = std::make_shared<JointFriction>(element_joint(f, b, field));
         friction->coulomb = number_or(f, "coulomb", 0.0, field);
         friction->viscous = number_or(f, "viscous", 0.0, field);
         friction->velocity_scale = number_or(f, "velocity_scale", friction->velocity_scale, field);
         if (!f["coulomb"] && !f["viscous"]) fail(f, field, "give coulomb, viscous or both");
         b.element(friction);
       });
}

void SceneReader::read_point_springs(const YAML::Node& list, SceneBuilder& b) const {
  each(list, "point_springs",
       {"name", "body_a", "point_a", "body_b", "point_b", "stiffness", "rest_length", "damping", "tension_only"},
       [&](const YAML::Node& node, const std::string& field, std::size_t n) {
         auto s = std::make_shared<PointSpring>();
         s->named = static_cast<bool>(node["name"]);
         s->name = s->named ? text(node["name"], field + ".name") : "spring" + std::to_string(n);
         s->body_a = element_body(node, "body_a", b, field);
         s->body_b = element_body(node, "body_b", b, field);
         s->point_a = vec3_or(node, "point_a", Vec3::Zero(), field);
         s->point_b = vec3_or(node, "point_b", Vec3::Zero(), field);
         s->stiffness = number(require(node, "stiffness", field), field + ".stiffness");
         s->rest_length = number(require(node, "rest_length", field), field + ".rest_length");
         s->damping = number_or(node, "damping", 0.0, field);
         if (node["tension_only"]) s->tension_only = flag(node["tension_only"], field + ".tension_only");
         b.element(s);
       });
}

int SceneReader::element_body(const YAML::Node& entry, const char* key, const SceneBuilder& b,
                              const std::string& field) const {
  const std::string name = text(require(entry, key, field), field + "." + key);
  if (!b.has_body(name))
    fail(entry[key], field + "." + key, "unknown body '" + name + "' (nor the base, '" + b.scene().model.base_name + "')");
  return b.body_index(name, field + "." + key);
}

// Six numbers (a diagonal) or six rows of six.
Mat6 SceneReader::read_matrix6(const YAML::Node& node, const std::string& field) const {
  if (!node.IsSequence() || node.size() != 6)
    fail(node, field, "expected 6 numbers (the diagonal: x, y, z, rx, ry, rz) or 6 rows of 6");
  Mat6 K = Mat6::Zero();
  if (!node[0].IsSequence()) {
    const std::vector<double> d = numbers(node, field);
    for (int k = 0; k < 6; ++k) K(k, k) = d[k];
    return K;
  }
  for (int i = 0; i < 6; ++i) {
    const std::string row = field + "[" + std::to_string(i) + "]";
    const std::vector<double> r = numbers(node[i], row);
    if (r.size() != 6) fail(node[i], row, "expected a row of 6 numbers");
    for (int j = 0; j < 6; ++j) K(i, j) = r[j];
  }
  return K;
}

// body_a, point_a and rotation_a ([axis x, axis y, axis z, angle in
// degrees], as a mesh's rotation), or b's.
void SceneReader::read_bushing_frame(const YAML::Node& node, char end, const SceneBuilder& b,
                                     const std::string& field, BushingFrame& frame) const {
  const std::string body = std::string("body_") + end, point = std::string("point_") + end,
                    rotation = std::string("rotation_") + end;
  frame.body = element_body(node, body.c_str(), b, field);
  frame.point = vec3_or(node, point.c_str(), Vec3::Zero(), field);
  if (const YAML::Node turn = node[rotation]) {
    const std::vector<double> r = numbers(turn, field + "." + rotation);
    if (r.size() != 4 || Vec3(r[0], r[1], r[2]).norm() < 1e-12)
      fail(turn, field + "." + rotation, "expected [axis x, axis y, axis z, angle in degrees] with a nonzero axis");
    frame.rotation_axis = Vec3(r[0], r[1], r[2]).normalized();
    frame.rotation_deg = r[3];
  }
}

void SceneReader::read_bushings(const YAML::Node& list, SceneBuilder& b) const {
  each(list, "bushings",
       {"name", "body_a", "point_a", "rotation_a", "body_b", "point_b", "rotation_b", "stiffness", "damping",
        "preload"},
       [&](const YAML::Node& node, const std::string& field, std::size_t) {
         auto s = std::make_shared<Bushing>();
         s->name = text(require(node, "name", field), field + ".name");
         read_bushing_frame(node, 'a', b, field, s->a);
         read_bushing_frame(node, 'b', b, field, s->b);
         s->stiffness = read_matrix6(require(node, "stiffness", field), field + ".stiffness");
         if (node["damping"]) s->damping = read_matrix6(node["damping"], field + ".damping");
         if (const YAML::Node preload = node["preload"]) {
           const std::vector<double> p = numbers(preload, field + ".preload");
           if (p.size() != 6) fail(preload, field + ".preload", "expected 6 numbers (fx, fy, fz, mx, my, mz)");
           for (int k = 0; k < 6; ++k) s->preload[k] = p[k];
         }
         b.element(s);
       });
}

void SceneReader::read_applied_forces(const YAML::Node& list, SceneBuilder& b) const {
  each(list, "applied_forces", {"body", "force", "torque", "point", "frame"},
       [&](const YAML::Node& l, const std::string& field, std::size_t) {
         auto load = std::make_shared<AppliedForce>();
         load->body = b.body_index(text(require(l, "body", field), field + ".body"), field + ".body");
         load->force = vec3_or(l, "force", Vec3::Zero(), field);
         load->torque = vec3_or(l, "torque", Vec3::Zero(), field);
         load->point = vec3_or(l, "point", Vec3::Zero(), field);
         if (const YAML::Node frame = l["frame"]) {
           const std::string f = text(frame, field + ".frame");
           if (f != "body" && f != "base") fail(frame, field + ".frame", "expected 'body' or 'base'");
           load->in_base_frame = f == "base";
         }
         b.element(load);
       });
}

void SceneReader::read_latches(const YAML::Node& list, SceneBuilder& b) const {
  each(list, "latches", {"joint", "position", "stiffness", "damping", "free_play"},
       [&](const YAML::Node& l, const std::string& field, std::size_t) {
         auto latch = std::make_shared<Latch>(element_joint(l, b, field));
         latch->position = number_or(l, "position", 0.0, field);
         latch->stiffness = number(require(l, "stiffness", field), field + ".stiffness");
         latch->damping = number(require(l, "damping", field), field + ".damping");
         latch->free_play = number_or(l, "free_play", 0.0, field);
         b.element(latch);
       });
}

void SceneReader::read_drivers(const YAML::Node& list, SceneBuilder& b) const {
  each(list, "drivers", {"joint", "profile", "amount", "duration", "start"},
       [&](const YAML::Node& d, const std::string& field, std::size_t) {
         auto driver = std::make_shared<JointDriver>(element_joint(d, b, field));
         const YAML::Node profile = require(d, "profile", field);
         const auto parsed = parse_driver_profile(text(profile, field + ".profile"));
         if (!parsed) fail(profile, field + ".profile", "expected move or spin_up");
         driver->profile = *parsed;
         driver->amount = number(require(d, "amount", field), field + ".amount");
         driver->duration = number(require(d, "duration", field), field + ".duration");
         driver->start = number_or(d, "start", 0.0, field);
         b.element(driver);
       });
}

void SceneReader::read_loops(const YAML::Node& list, SceneBuilder& b) const {
  each(list, "loops", {"name", "body", "image"}, [&](const YAML::Node& l, const std::string& field, std::size_t) {
    const std::string body = text(require(l, "body", field), field + ".body");
    const std::string image = text(require(l, "image", field), field + ".image");
    b.loop(l["name"] ? text(l["name"], field + ".name") : "", body, image);
  });
}

void SceneReader::read_sensors(const YAML::Node& list, SceneBuilder& b) const {
  each(list, "sensors", {"name", "body", "point", "frame", "measure"},
       [&](const YAML::Node& node, const std::string& field, std::size_t) {
         Sensor s;
         s.name = text(require(node, "name", field), field + ".name");
         s.point = vec3_or(node, "point", Vec3::Zero(), field);
         if (const YAML::Node frame = node["frame"]) {
           const std::string f = text(frame, field + ".frame");
           if (f != "body" && f != "inertial") fail(frame, field + ".frame", "expected body or inertial");
           s.frame = f == "body" ? SensorFrame::body : SensorFrame::inertial;
         }
         if (const YAML::Node measure = node["measure"]) {
           if (!measure.IsSequence() || measure.size() == 0)
             fail(measure, field + ".measure",
                  "expected a list of position, velocity, acceleration, angular_rate, angular_acceleration");
           s.measures.clear();
           for (std::size_t k = 0; k < measure.size(); ++k) {
             const std::string item = input::index_field(field + ".measure", k);
             const std::string name = text(measure[k], item);
             bool known = false;
             for (const SensorQuantity q : {SensorQuantity::position, SensorQuantity::velocity,
                                            SensorQuantity::acceleration, SensorQuantity::angular_rate,
                                            SensorQuantity::angular_acceleration})
               if (name == sensor_quantity_name(q)) s.measures.push_back(q), known = true;
             if (!known)
               fail(measure[k], item,
                    "'" + name + "': expected position, velocity, acceleration, angular_rate or angular_acceleration");
           }
         }
         const std::string body = text(require(node, "body", field), field + ".body");
         if (!b.has_body(body)) fail(node["body"], field + ".body", "unknown body '" + body + "'");
         b.sensor(std::move(s), body);
       });
}

RegulatorSettings SceneReader::read_regulator(const YAML::Node& node) const {
  check_keys(node, {"gains", "v_max", "p0", "p1", "regularization", "feedforward", "solver"}, "regulator");
  RegulatorSettings r;
  if (const YAML::Node gains = node["gains"]) {
    const std::string g = text(gains, "regulator.gains");
    if (g == "full")
      r.gains = GainTuning::full;
    else if (g == "paper")
      r.gains = GainTuning::paper;
    else
      fail(gains, "regulator.gains", "expected 'full' or 'paper', got '" + g + "'");
  }
  // "auto" (or absent): the regulator chooses (from the mechanism's own
  // rate; from W's weakest mode).
  const auto number_or_auto = [&](const char* key) -> std::optional<double> {
    const YAML::Node v = node[key];
    if (!v || (v.IsScalar() && v.Scalar() == "auto")) return std::nullopt;
    return number(v, std::string("regulator.") + key);
  };
  r.v_max = number_or_auto("v_max");
  r.p0 = number_or(node, "p0", r.p0, "regulator");
  r.p1 = number_or(node, "p1", r.p1, "regulator");
  r.regularization = number_or_auto("regularization");
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
  return r;
}

void SceneReader::read_initial(const YAML::Node& node, SceneBuilder& b) const {
  check_keys(node, {"q", "dq", "p"}, "initial");
  if (node["dq"] && node["p"]) fail(node["p"], "initial.p", "give either dq or p, not both");
  for (const char* key : {"q", "dq", "p"}) {
    const YAML::Node map = node[key];
    if (!map) continue;
    const std::string field = std::string("initial.") + key;
    check_map(map, field);
    for (const auto& item : map) {
      const std::string joint = text(item.first, field);
      const std::string entry = field + "." + joint;
      const std::vector<double> values =
          item.second.IsSequence() ? numbers(item.second, entry) : std::vector<double>{number(item.second, entry)};
      if (key == std::string("q"))
        b.initial_position(joint, values);
      else if (key == std::string("dq"))
        b.initial_rate(joint, values);
      else
        b.initial_momentum(joint, values);
    }
  }
}

TorqueMarginFactors SceneReader::read_torque_margin(const YAML::Node& node) const {
  check_keys(node, {"spring", "friction", "damping", "harness", "inertia", "required", "required_acceleration"},
             "torque_margin");
  TorqueMarginFactors f;
  f.spring = number_or(node, "spring", f.spring, "torque_margin");
  f.friction = number_or(node, "friction", f.friction, "torque_margin");
  f.damping = number_or(node, "damping", f.damping, "torque_margin");
  f.harness = number_or(node, "harness", f.harness, "torque_margin");
  f.inertia = number_or(node, "inertia", f.inertia, "torque_margin");
  f.required = number_or(node, "required", f.required, "torque_margin");
  f.required_acceleration = number_or(node, "required_acceleration", f.required_acceleration, "torque_margin");
  return f;
}

RunSettings SceneReader::read_run(const YAML::Node& node) const {
  check_keys(node,
             {"t_end", "integrator", "linear_solver", "rtol", "atol", "dt", "sample", "max_closure", "event_window",
              "max_steps", "max_samples", "max_wall_time", "roundoff_guard",
              "stability_limit_detection", "max_order_after_latch"},
             "run");
  RunSettings run;
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
  run.t_end = number_or(node, "t_end", run.t_end, "run");
  run.rtol = number_or(node, "rtol", run.rtol, "run");
  run.atol = number_or(node, "atol", run.atol, "run");
  run.dt = number_or(node, "dt", run.dt, "run");
  run.sample = number_or(node, "sample", run.sample, "run");
  run.max_closure = number_or(node, "max_closure", run.max_closure, "run");
  run.event_window = number_or(node, "event_window", run.event_window, "run");
  run.max_wall_time = number_or(node, "max_wall_time", run.max_wall_time, "run");
  if (node["max_steps"]) run.max_steps = count(node["max_steps"], "run.max_steps", 1, kMostSteps);
  if (node["roundoff_guard"]) run.roundoff_guard = flag(node["roundoff_guard"], "run.roundoff_guard");
  if (const YAML::Node detection = node["stability_limit_detection"]) {
    const std::string name = text(detection, "run.stability_limit_detection");
    const auto parsed = parse_stability_limit_detection(name);
    if (!parsed)
      fail(detection, "run.stability_limit_detection", "expected true, false or after_latch, got '" + name + "'");
    run.stability_limit_detection = *parsed;
  }
  if (node["max_samples"]) run.max_samples = count(node["max_samples"], "run.max_samples", 1, kMostSteps);
  if (node["max_order_after_latch"])
    run.max_order_after_latch =
        static_cast<int>(count(node["max_order_after_latch"], "run.max_order_after_latch", 1, kBdfMaxOrder));
  return run;
}

SceneFile SceneReader::read(const std::string& text_in, const std::vector<Override>& overrides) {
  YAML::Node root = load_document(text_in);
  if (!root.IsMap()) throw input::InputError(source() + ": a scene file is a YAML mapping (name, bodies, ...)");
  for (const Override& o : overrides) apply_override(root, o, *this);

  // "loads" named both applied forces and the loads a run reports: the
  // former are applied_forces since 0.3.
  if (root["loads"]) fail(root["loads"], "loads", "renamed: the constant forces on bodies are `applied_forces:`");
  check_keys(root,
             {"name", "description", "base", "gravity", "bodies", "springs", "dampers", "stops", "limits", "friction",
              "point_springs", "bushings", "applied_forces", "latches", "drivers", "loops", "sensors", "regulator", "initial",
              "closure_tolerance", "torque_margin", "run"},
             "");
  SceneBuilder b(root["name"] ? text(root["name"], "name") : "scene",
                 root["description"] ? text(root["description"], "description") : "");
  b.source(source());
  try {
    if (root["base"]) read_base(root["base"], b);
    if (root["gravity"]) b.gravity(vec3(root["gravity"], "gravity"));
    root_.reset(root);
    const YAML::Node bodies = require(root, "bodies", "");
    if (!bodies.IsSequence() || bodies.size() == 0) fail(bodies, "bodies", "expected a non-empty list of bodies");
    for (std::size_t i = 0; i < bodies.size(); ++i) read_body(bodies[i], static_cast<int>(i), bodies, b);
    // The elements in the order their forces add up.
    if (root["springs"]) read_springs(root["springs"], b);
    if (root["dampers"]) read_dampers(root["dampers"], b);
    if (root["stops"]) read_stops(root["stops"], b);
    if (root["limits"]) read_limits(root["limits"], b);
    if (root["friction"]) read_friction(root["friction"], b);
    if (root["latches"]) read_latches(root["latches"], b);
    if (root["applied_forces"]) read_applied_forces(root["applied_forces"], b);
    if (root["point_springs"]) read_point_springs(root["point_springs"], b);
    if (root["bushings"]) read_bushings(root["bushings"], b);
    if (root["drivers"]) read_drivers(root["drivers"], b);
    if (root["loops"]) read_loops(root["loops"], b);
    if (root["sensors"]) read_sensors(root["sensors"], b);
    if (root["regulator"]) b.regulator(read_regulator(root["regulator"]));
    if (root["initial"]) read_initial(root["initial"], b);
    if (root["closure_tolerance"]) b.closure_tolerance(number(root["closure_tolerance"], "closure_tolerance"));
    if (root["torque_margin"]) b.torque_margin(read_torque_margin(root["torque_margin"]));
    b.run(read_run(root["run"] ? root["run"] : YAML::Node(YAML::NodeType::Map)));
    return b.build();
  } catch (const SceneInvalid& e) {
    fail(node_at(root, e.field()), e.field(), e.reason());
  }
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

}  // namespace unfurl::sim
