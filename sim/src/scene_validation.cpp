#include "unfurl/sim/scene_validation.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <unordered_map>

#include "unfurl/sim/elements/joint_compliance.hpp"
#include "unfurl/sim/elements/joint_driver.hpp"
#include "unfurl/sim/kinematics.hpp"
#include "unfurl/sim/mechanism_scales.hpp"
#include "unfurl/sim/number_text.hpp"

namespace unfurl::sim {

namespace {

// Whether one of two bodies is an ancestor of the other.
bool on_one_branch(const Model& model, int a, int b) {
  auto descends = [&](int child, int ancestor) {
    for (int i = child; i >= 0; i = model.parent[i])
      if (i == ancestor) return true;
    return false;
  };
  return descends(a, b) || descends(b, a);
}

void check_name(const std::string& name, const std::string& field) {
  if (!is_valid_name(name))
    throw SceneInvalid(field, "the name '" + name +
                                  "' has characters other than letters, digits, '_' and '-' (or is empty or over 64)");
}

std::string joint_field(const Scene& scene, int i) {
  return scene.model.free_floating() && i == 0 ? "base" : body_field(scene, i) + ".joint";
}

void check_mass_properties(const Body& b, const std::string& field) {
  if (b.mass < 0) throw SceneInvalid(field + ".mass", "negative mass " + format_number(b.mass));
  if (!(b.mass > 0)) throw SceneInvalid(field + ".mass", "the mass must be positive");
  const Vec3 principal = Eigen::SelfAdjointEigenSolver<Mat3>(b.inertia_com).eigenvalues();
  if (!(principal.minCoeff() > 0)) {
    std::ostringstream s;
    s << "the inertia is not positive definite (smallest principal moment " << principal.minCoeff() << ")";
    throw SceneInvalid(field + ".inertia", s.str());
  }
  // Every mass distribution has I1 + I2 >= I3 for its principal moments
  // (equality for a flat body); allow round-off of the scene's digits.
  if (principal[0] + principal[1] < principal[2] * (1 - 1e-6)) {
    std::ostringstream s;
    s << "no body has these principal moments (" << principal[0] << ", " << principal[1] << ", " << principal[2]
      << "): the two smaller must add up to at least the largest";
    throw SceneInvalid(field + ".inertia", s.str());
  }
}

// Unit axes (a zero one is refused).
void check_joint(Scene& scene, int i) {
  Joint& j = scene.model.joints[i];
  const std::string field = joint_field(scene, i);
  check_name(j.name, field + ".name");
  if (j.type == JointType::free && i != 0)
    throw SceneInvalid(
        field + ".type",
        "a free joint is for a free-floating base only: give the base `free: true` and its mass properties");
  const bool axial = j.type == JointType::revolute || j.type == JointType::prismatic || j.type == JointType::planar ||
                     j.type == JointType::universal;
  const auto unit = [&](Vec3& axis, const char* key) {
    if (!(axis.norm() >= 1e-12)) throw SceneInvalid(field + "." + key, "the joint axis has zero length");
    axis.normalize();
  };
  if (axial) unit(j.axis, "axis");
  if (j.type == JointType::universal) {
    unit(j.axis2, "axis2");
    if (j.axis.cross(j.axis2).norm() < 1e-6)
      throw SceneInvalid(field + ".axis2", "a universal joint's two axes must not be parallel");
  }
}

}  // namespace

void validate_model(Scene& scene) {
  Model& model = scene.model;
  if (model.bodies.empty()) throw SceneInvalid("bodies", "expected a non-empty list of bodies");
  if (model.joints.size() != model.bodies.size() || model.parent.size() != model.bodies.size())
    throw SceneInvalid("bodies", "bodies, joints and parents differ in number");
  std::set<std::string> bodies, joints;
  for (int i = 0; i < model.size(); ++i) {
    const std::string field = body_field(scene, i);
    check_name(model.bodies[i].name, field + ".name");
    if (!bodies.insert(model.bodies[i].name).second || model.bodies[i].name == model.base_name)
      throw SceneInvalid(field, "a body named '" + model.bodies[i].name + "' already exists");
    if (model.parent[i] != kBase && (model.parent[i] < 0 || model.parent[i] >= i))
      throw SceneInvalid(field + ".parent", "numbering is not regular: the parent of '" + model.bodies[i].name +
                                                "' is listed after it (list every body after its parent)");
    check_mass_properties(model.bodies[i], field);
    check_joint(scene, i);
    if (!joints.insert(model.joints[i].name).second)
      throw SceneInvalid(joint_field(scene, i), "a joint named '" + model.joints[i].name + "' already exists");
  }
  model.finalize();
  if (model.nq == 0)
    throw SceneInvalid("bodies",
                       "every joint is fixed: there is nothing to move or integrate (give a joint a type "
                       "that moves)");
  if (scene.q0.empty()) {
    scene.q0.assign(model.nq, 0.0);
    for (int i = 0; i < model.size(); ++i)
      if (model.joints[i].dof() > 1) model.joints[i].neutral_positions(&scene.q0[model.first_position[i].value]);
  }
  if (scene.dq0.empty()) scene.dq0.assign(model.nv, 0.0);
}

namespace {

// q0 and dq0 of the right size (validate_model() gives neutral ones where
// none are), unit quaternions, p0 of the right size or empty.
void check_initial_state(Scene& scene) {
  const Model& model = scene.model;
  if (static_cast<int>(scene.q0.size()) != model.nq)
    throw SceneInvalid("initial.q", "expected " + std::to_string(model.nq) + " positions");
  if (static_cast<int>(scene.dq0.size()) != model.nv)
    throw SceneInvalid("initial.dq", "expected " + std::to_string(model.nv) + " rates");
  if (!scene.p0.empty() && static_cast<int>(scene.p0.size()) != model.nv)
    throw SceneInvalid("initial.p", "expected " + std::to_string(model.nv) + " momenta");
  for (int i = 0; i < model.size(); ++i) {
    const Joint& j = model.joints[i];
    if (j.driven && j.is_scalar()) {
      const int c = model.velocity_of(i).value;
      if (scene.dq0[c] != 0)
        throw SceneInvalid("initial.dq." + j.name, "joint '" + j.name + "' is driven: its rate is its driver's");
      if (!scene.p0.empty() && scene.p0[c] != 0)
        throw SceneInvalid("initial.p." + j.name, "joint '" + j.name + "' is driven: its momentum is not a state");
    }
    if (!j.has_quaternion()) continue;
    Eigen::Map<Eigen::Vector4d> quaternion(&scene.q0[(model.first_position[i] + j.quaternion_offset()).value]);
    if (quaternion.norm() < 1e-9) throw SceneInvalid("initial.q." + j.name, "the quaternion has zero length");
    quaternion.normalize();
  }
}

void check_loops(const Scene& scene) {
  const Model& model = scene.model;
  const double length = mechanism_length(model);
  std::vector<Pose> poses;
  body_poses(model, scene.q0.data(), poses);
  for (std::size_t l = 0; l < scene.loops.size(); ++l) {
    const Loop& loop = scene.loops[l];
    const std::string field = "loops[" + std::to_string(l) + "]";
    check_name(loop.name, field + ".name");
    if (loop.body < 0 || loop.body >= model.size()) throw SceneInvalid(field + ".body", "no such body");
    if (loop.image < 0 || loop.image >= model.size()) throw SceneInvalid(field + ".image", "no such body");
    if (loop.body == loop.image) throw SceneInvalid(field + ".image", "a body cannot be its own image");
    if (on_one_branch(model, loop.body, loop.image))
      throw SceneInvalid(field + ".image", "'" + model.bodies[loop.image].name + "' and '" +
                                               model.bodies[loop.body].name +
                                               "' lie on one branch of the tree (one is the other's ancestor): they do "
                                               "not close a loop");
    for (std::size_t k = 0; k < l; ++k) {
      const Loop& other = scene.loops[k];
      if (other.name == loop.name)
        throw SceneInvalid(field + ".name", "a loop named '" + loop.name + "' already exists");
      if (other.body == loop.body || other.image == loop.image || other.body == loop.image || other.image == loop.body)
        throw SceneInvalid(
            field, "this loop shares a split body with loop '" + other.name + "' (each loop splits a body of its own)");
    }
    const ClosureError e = closure_error(poses[loop.body], poses[loop.image]);
    if (e.distance > scene.closure_tolerance * length || e.angle > scene.closure_tolerance) {
      std::ostringstream s;
      s.precision(6);
      s << "loop '" << loop.name << "' does not close at the initial state: the origins of '"
        << model.bodies[loop.body].name << "' and '" << model.bodies[loop.image].name << "' are " << e.distance
        << " m apart and their frames " << e.angle << " rad apart (closure_tolerance " << scene.closure_tolerance
        << ": rad, and for a distance times the mechanism's length, " << length << " m)";
      throw SceneInvalid(field, s.str());
    }
  }
}

void check_regulator(const RegulatorSettings& r) {
  if (r.v_max) check_positive(*r.v_max, "regulator.v_max");
  check_positive(r.p0, "regulator.p0");
  check_positive(r.p1, "regulator.p1");
  if (r.regularization) check_positive(*r.regularization, "regulator.regularization");
  if (r.p1 >= 1) throw SceneInvalid("regulator.p1", "must be below 1 (b1 = p1 v_max < v_max)");
}

// Refuses up front what cannot finish or cannot be stored: more samples
// than max_samples, or more fixed RK4 steps than max_steps.
// A compliant hinge has its pin's stiffness, once.
void check_compliance(const Scene& scene) {
  std::vector<int> given(scene.model.size(), 0);
  for (const JointCompliance* c : scene.elements_of<JointCompliance>())
    if (c->joint >= 0 && c->joint < scene.model.size()) ++given[c->joint];
  for (int i = 0; i < scene.model.size(); ++i) {
    const int of_joint = given[i];
    if (scene.model.joints[i].compliant && of_joint != 1)
      throw SceneInvalid(body_field(scene, i) + ".joint.compliance",
                         of_joint == 0 ? "a compliant joint needs its pin's stiffness" : "given more than once");
  }
}

// Named uniquely, on a body, measuring something, each thing once.
void check_sensors(const Scene& scene) {
  std::set<std::string> names;
  for (std::size_t k = 0; k < scene.sensors.size(); ++k) {
    const Sensor& s = scene.sensors[k];
    const std::string field = "sensors[" + std::to_string(k) + "]";
    check_name(s.name, field + ".name");
    if (!names.insert(s.name).second) throw SceneInvalid(field + ".name", "a sensor named '" + s.name + "' already exists");
    if (s.body < 0 || s.body >= scene.model.size()) throw SceneInvalid(field + ".body", "no such body");
    if (!s.point.allFinite()) throw SceneInvalid(field + ".point", "must be finite");
    if (s.measures.empty()) throw SceneInvalid(field + ".measure", "measures nothing");
    const std::set<SensorQuantity> distinct(s.measures.begin(), s.measures.end());
    if (distinct.size() != s.measures.size()) throw SceneInvalid(field + ".measure", "names a quantity twice");
  }
}

void check_run(const RunSettings& run) {
  check_positive(run.t_end, "run.t_end");
  check_positive(run.rtol, "run.rtol");
  check_positive(run.atol, "run.atol");
  check_positive(run.dt, "run.dt");
  check_positive(run.sample, "run.sample");
  check_positive(run.max_closure, "run.max_closure");
  check_non_negative(run.event_window, "run.event_window");
  check_non_negative(run.max_wall_time, "run.max_wall_time");
  if (run.max_steps < 1 || run.max_steps > kMostSteps)
    throw SceneInvalid("run.max_steps", "expected a whole number from 1 to " + std::to_string(kMostSteps));
  if (run.max_samples < 1 || run.max_samples > kMostSteps)
    throw SceneInvalid("run.max_samples", "expected a whole number from 1 to " + std::to_string(kMostSteps));
  if (run.sample > run.t_end)
    throw SceneInvalid("run.sample", "the output interval " + format_number(run.sample) +
                                         " s is longer than the run (t_end " + format_number(run.t_end) + " s)");
  const double samples = run.t_end / run.sample + 1;
  if (samples > static_cast<double>(run.max_samples))
    throw SceneInvalid("run.sample", "t_end / sample makes " + format_number(samples) +
                                         " samples, more than run.max_samples (" + std::to_string(run.max_samples) +
                                         "); raise it if the memory is there");
  const double steps = run.t_end / run.dt;
  if (run.integrator == IntegratorKind::rk4 && steps > static_cast<double>(run.max_steps))
    throw SceneInvalid("run.dt", "t_end / dt makes " + format_number(steps) +
                                     " fixed steps, more than run.max_steps (" + std::to_string(run.max_steps) + ")");
}

}  // namespace

bool is_valid_name(const std::string& n) {
  return !n.empty() && n.size() <= 64 &&
         n.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-") == std::string::npos;
}

std::string body_field(const Scene& scene, int i) {
  const bool bus = !scene.model.joints.empty() && scene.model.joints[0].type == JointType::free;
  if (bus && i == 0) return "base";
  return "bodies[" + std::to_string(bus ? i - 1 : i) + "] (" + scene.model.bodies[i].name + ")";
}

std::vector<std::string> element_fields(const Scene& scene) {
  std::unordered_map<std::string, std::size_t> listed;  // how many of each list so far
  std::vector<std::string> fields;
  for (const auto& e : scene.elements) {
    const std::string list = e->list();
    const std::size_t index = listed[list]++;
    fields.push_back(list == "gravity" ? list : list + "[" + std::to_string(index) + "]");
  }
  return fields;
}

void check_positive(double x, const std::string& field) {
  if (!(x > 0)) throw SceneInvalid(field, "must be positive, got " + format_number(x));
}

void check_non_negative(double x, const std::string& field) {
  if (x < 0) throw SceneInvalid(field, "must not be negative, got " + format_number(x));
}

std::vector<std::string> scene_warnings(const Scene& scene) {
  std::vector<std::string> out;
  const Model& m = scene.model;
  for (int c = 0; c < m.nq && c < static_cast<int>(scene.q0.size()); ++c) {
    if (m.joint_of_position[c] < 0) continue;  // an elastic coordinate
    const Joint& j = m.joints[m.joint_of_position[c]];
    if (m.position_unit(c) != "rad" || j.type == JointType::spherical || j.type == JointType::free) continue;
    if (std::abs(scene.q0[c]) > 2 * M_PI)
      out.push_back("initial.q." + m.position_name(c) + ": " + format_number(scene.q0[c]) +
                    " rad is more than a turn; angles are in radians (degrees meant?)");
  }
  return out;
}

// A sensor on a flexible body rides on one of its nodes (the reader makes
// each such point one), at it or on a rigid bracket beside it: found here
// by its point.
void place_sensors_on_nodes(Scene& scene) {
  for (std::size_t k = 0; k < scene.sensors.size(); ++k) {
    Sensor& s = scene.sensors[k];
    s.node = -1;
    if (s.body < 0 || s.body >= scene.model.size() || !scene.model.flexible(s.body)) continue;
    s.node = scene.model.bodies[s.body].flexible->node_of(s.point);
    if (s.node < 0)
      throw SceneInvalid("sensors[" + std::to_string(k) + "].point",
                         "a sensor on a flexible body sits at one of its attachment points (a mesh node, a plate's "
                         "hinge line or root edge, or a rigid bracket beside one)");
  }
}

void validate(Scene& scene) {
  // Which joints are driven follows from the drivers alone (the sweep reads
  // it off the model).
  for (Joint& j : scene.model.joints) j.driven = false;
  for (const JointDriver* d : scene.elements_of<JointDriver>())
    if (d->joint >= 0 && d->joint < scene.model.size()) scene.model.joints[d->joint].driven = true;
  validate_model(scene);
  check_initial_state(scene);
  const std::vector<std::string> fields = element_fields(scene);
  for (std::size_t k = 0; k < scene.elements.size(); ++k) scene.elements[k]->validate(scene, fields[k]);
  check_compliance(scene);
  check_positive(scene.closure_tolerance, "closure_tolerance");
  if (scene.closure_tolerance > kLargestClosureTolerance)
    throw SceneInvalid("closure_tolerance",
                       "at most " + format_number(kLargestClosureTolerance) +
                           " (rad, or a distance over the mechanism's length): a loop opener than that is not "
                           "a loop (the regulator would snap it shut)");
  check_loops(scene);
  check_sensors(scene);
  place_sensors_on_nodes(scene);
  for (const auto& [name, x] : {std::pair{"spring", scene.torque_margin.spring}, {"friction", scene.torque_margin.friction},
                               {"damping", scene.torque_margin.damping}, {"harness", scene.torque_margin.harness},
                               {"inertia", scene.torque_margin.inertia}, {"required", scene.torque_margin.required}})
    check_positive(x, std::string("torque_margin.") + name);
  check_non_negative(scene.torque_margin.required_acceleration, "torque_margin.required_acceleration");
  check_regulator(scene.regulator);
  check_run(scene.run);
}

}  // namespace unfurl::sim
