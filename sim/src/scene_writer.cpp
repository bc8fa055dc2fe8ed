// A scene as a scene file (assets/scenes/README.md), the reader's inverse:
// every number in its shortest form that reads back to the same double, so
// the file reloads to the same run.
#include <cmath>
#include <sstream>

#include "unfurl/sim/elements/all.hpp"
#include "unfurl/sim/flexible/flexible_body.hpp"
#include "unfurl/sim/number_text.hpp"
#include "unfurl/sim/scene_file.hpp"

namespace unfurl::sim {

namespace {

std::string vec(const Vec3& x) {
  return "[" + format_number(x[0]) + ", " + format_number(x[1]) + ", " + format_number(x[2]) + "]";
}

std::string numbers(const std::vector<double>& x) {
  std::string out = "[";
  for (std::size_t k = 0; k < x.size(); ++k) out += (k ? ", " : "") + format_number(x[k]);
  return out + "]";
}

// A double-quoted YAML scalar.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out + "\"";
}

// A 6 x 6 matrix: its diagonal when it is diagonal, else its rows.
std::string matrix6(const Mat6& K) {
  if (K.isDiagonal(0)) {
    const Vec6 diagonal = K.diagonal();  // a copy: the diagonal's own data has a stride
    return numbers({diagonal.data(), diagonal.data() + 6});
  }
  std::string out = "[";
  for (int i = 0; i < 6; ++i) {
    const Vec6 row = K.row(i).transpose();
    out += (i ? ", " : "") + numbers({row.data(), row.data() + 6});
  }
  return out + "]";
}

std::string rotation(const Vec3& axis, double degrees) {
  return "[" + format_number(axis[0]) + ", " + format_number(axis[1]) + ", " + format_number(axis[2]) + ", " +
         format_number(degrees) + "]";
}

std::string visual(const Visual& v) {
  const bool plain = v.scale == Vec3::Ones() && v.rotation_deg == 0 && v.offset.isZero(0);
  if (plain) return v.mesh;
  std::string out = "{name: " + v.mesh;
  if (v.scale != Vec3::Ones()) out += ", scale: " + vec(v.scale);
  if (v.rotation_deg != 0) out += ", rotation: " + rotation(v.rotation_axis, v.rotation_deg);
  if (!v.offset.isZero(0)) out += ", offset: " + vec(v.offset);
  return out + "}";
}

std::string collision_shape(const CollisionShape& c) {
  std::string out;
  switch (c.kind) {
    case CollisionShape::Kind::box: out = "{box: " + vec(c.size); break;
    case CollisionShape::Kind::sphere: out = "{sphere: " + format_number(c.radius); break;
    case CollisionShape::Kind::cylinder:
      out = "{cylinder: [" + format_number(c.radius) + ", " + format_number(c.length) + "]";
      break;
    case CollisionShape::Kind::mesh:
      out = "{mesh: " + c.mesh;
      if (c.scale != Vec3::Ones()) out += ", scale: " + vec(c.scale);
      break;
  }
  if (c.rotation_deg != 0) out += ", rotation: " + rotation(c.rotation_axis, c.rotation_deg);
  if (!c.offset.isZero(0)) out += ", offset: " + vec(c.offset);
  return out + "}";
}

// A declared `collision:` (nothing when the mesh stands for it).
void collision(std::ostream& out, const Visual& v, const std::string& pad) {
  if (!v.collision) return;
  if (v.collision->empty()) {
    out << pad << "collision: none\n";
    return;
  }
  out << pad << "collision:\n";
  for (const CollisionShape& c : *v.collision) out << pad << "  - " << collision_shape(c) << "\n";
}

void mass_properties(std::ostream& out, const Body& b, const std::string& pad) {
  out << pad << "mass: " << format_number(b.mass) << "\n";
  if (!b.com.isZero(0)) out << pad << "com: " << vec(b.com) << "\n";
  const Mat3& I = b.inertia_com;
  std::vector<double> inertia{I(0, 0), I(1, 1), I(2, 2)};
  if (I(0, 1) != 0 || I(0, 2) != 0 || I(1, 2) != 0) inertia.insert(inertia.end(), {I(0, 1), I(0, 2), I(1, 2)});
  out << pad << "inertia: " << numbers(inertia) << "\n";
}

std::string modes_text(int normal_modes, double up_to_hz) {
  return up_to_hz > 0 ? "{up_to: " + format_number(up_to_hz) + "}" : std::to_string(normal_modes);
}

std::string damping_text(const flexible::ModalDamping& d) {
  if (!d.per_coordinate.empty()) return numbers(d.per_coordinate);
  if (d.is_uniform()) return format_number(d.bands[0].ratio);
  std::string out = "[";
  for (std::size_t k = 0; k < d.bands.size(); ++k) {
    out += k ? ", {" : "{";
    if (k + 1 < d.bands.size()) out += "up_to: " + format_number(d.bands[k].up_to_hz) + ", ";
    out += "ratio: " + format_number(d.bands[k].ratio) + "}";
  }
  return out + "]";
}

// A flexible body's structure and modes, as the reader takes them (its
// attachments follow from its children's joints, its sensors and the
// elements' points on it).
void flexible_body(std::ostream& out, const flexible::BeamBodySpec& spec, const std::string& pad) {
  const flexible::BeamSection& s = spec.section;
  out << pad << "flexible:\n" << pad << "  beam: {length: " << format_number(s.length)
      << ", axial_stiffness: " << format_number(s.axial_stiffness) << ", bending_stiffness: ["
      << format_number(s.bending_stiffness_y) << ", " << format_number(s.bending_stiffness_z)
      << "], torsional_stiffness: " << format_number(s.torsional_stiffness)
      << ", mass_per_length: " << format_number(s.mass_per_length)
      << ", polar_inertia_per_length: " << format_number(s.polar_inertia_per_length) << ", elements: " << s.elements;
  if (!spec.root.isZero(0)) out << ", root: " << numbers({spec.root.x(), spec.root.y(), spec.root.z()});
  if (spec.axis != 0) out << ", axis: " << static_cast<char>('x' + spec.axis);
  out << "}\n"
      << pad << "  modes: " << modes_text(spec.normal_modes, spec.modes_up_to_hz) << "\n"
      << pad << "  damping: " << damping_text(spec.damping) << "\n";
  if (!spec.geometric_stiffening) out << pad << "  geometric_stiffening: false\n";
}

const char* edge_name(flexible::PlateEdge e) {
  switch (e) {
    case flexible::PlateEdge::x0: return "x0";
    case flexible::PlateEdge::x1: return "x1";
    case flexible::PlateEdge::y0: return "y0";
    case flexible::PlateEdge::y1: return "y1";
  }
  return "";
}

void flexible_body(std::ostream& out, const flexible::PlateBodySpec& spec, const std::string& pad) {
  const flexible::PlateSpec& p = spec.plate;
  out << pad << "flexible:\n" << pad << "  plate: {size: " << numbers({p.length_x, p.length_y});
  if (spec.youngs_modulus > 0)
    out << ", youngs_modulus: " << format_number(spec.youngs_modulus) << ", thickness: " << format_number(spec.thickness);
  else
    out << ", bending_stiffness: " << format_number(p.bending_stiffness);
  out << ", poisson: " << format_number(p.poisson) << ", mass_per_area: " << format_number(p.mass_per_area)
      << ", elements: [" << p.elements_x << ", " << p.elements_y << "]";
  if (!spec.corner.isZero(0)) out << ", corner: " << numbers({spec.corner.x(), spec.corner.y(), spec.corner.z()});
  if (spec.normal != 2) out << ", normal: " << static_cast<char>('x' + spec.normal);
  out << ", root_edge: " << edge_name(spec.root_edge);
  if (!spec.hinge_lines.empty()) {
    out << ", hinge_lines: [";
    for (std::size_t k = 0; k < spec.hinge_lines.size(); ++k) out << (k ? ", " : "") << edge_name(spec.hinge_lines[k]);
    out << "]";
  }
  if (!spec.brackets.empty()) {
    out << ", brackets: [";
    for (std::size_t k = 0; k < spec.brackets.size(); ++k)
      out << (k ? ", " : "") << numbers({spec.brackets[k][0], spec.brackets[k][1]});
    out << "]";
  }
  out << "}\n"
      << pad << "  modes: " << modes_text(spec.normal_modes, spec.modes_up_to_hz) << "\n"
      << pad << "  damping: " << damping_text(spec.damping) << "\n";
}

// The file's path as the reader resolved it (absolute), the modes kept
// where the scene chose, the damping where it gave one (else the file's).
void flexible_body(std::ostream& out, const flexible::FemBodySpec& spec, const std::string& pad) {
  out << pad << "flexible:\n" << pad << "  fem: " << quoted(spec.file) << "\n";
  if (spec.normal_modes > 0 || spec.modes_up_to_hz > 0)
    out << pad << "  modes: " << modes_text(spec.normal_modes, spec.modes_up_to_hz) << "\n";
  if (!spec.damping_from_file) out << pad << "  damping: " << damping_text(spec.damping) << "\n";
}

std::string joint_text(const Joint& j, const JointCompliance* compliance) {
  std::string out = "{name: " + j.name + ", type: " + joint_type_name(j.type);
  const bool axial = j.type == JointType::revolute || j.type == JointType::prismatic || j.type == JointType::planar ||
                     j.type == JointType::universal;
  if (axial) out += ", axis: " + vec(j.axis);
  if (j.type == JointType::universal) out += ", axis2: " + vec(j.axis2);
  out += ", parent_point: " + vec(j.parent_point) + ", child_point: " + vec(j.child_point);
  if (compliance)
    out += ", compliance: {radial: " + format_number(compliance->radial) + ", axial: " +
           format_number(compliance->axial) + ", tilt: " + format_number(compliance->tilt) +
           ", radial_damping: " + format_number(compliance->radial_damping) +
           ", axial_damping: " + format_number(compliance->axial_damping) +
           ", tilt_damping: " + format_number(compliance->tilt_damping) + "}";
  return out + "}";
}

// Joint i's compliance, if it has one.
const JointCompliance* compliance_of(const Scene& scene, int i) {
  for (const JointCompliance* c : scene.elements_of<JointCompliance>())
    if (c->joint == i) return c;
  return nullptr;
}

// Each list of elements, in the reader's order.
void elements(std::ostream& out, const Scene& scene) {
  const Model& m = scene.model;
  const auto joint = [&](int j) { return m.joints[j].name; };
  const auto body = [&](int i) { return i == kBase ? m.base_name : m.bodies[i].name; };
  const auto list = [&](const char* name, const auto& items, auto line) {
    if (items.empty()) return;
    out << "\n" << name << ":\n";
    for (const auto* e : items) out << "  - {" << line(*e) << "}\n";
  };
  list("springs", scene.elements_of<JointSpring>(), [&](const JointSpring& s) {
    std::string text = "joint: " + joint(s.joint);
    if (s.curve) {
      std::string table;
      for (std::size_t k = 0; k < s.curve->angles().size(); ++k)
        table += std::string(k ? ", " : "") + "[" + format_number(s.curve->angles()[k]) + ", " +
                 format_number(s.curve->torques()[k]) + "]";
      text += ", table: [" + table + "]";
    } else {
      text += ", stiffness: " + format_number(s.stiffness) + ", free_position: " + format_number(s.free_position);
    }
    return text + ", damping: " + format_number(s.damping);
  });
  list("dampers", scene.elements_of<JointDamper>(),
       [&](const JointDamper& d) { return "joint: " + joint(d.joint) + ", damping: " + format_number(d.damping); });
  list("friction", scene.elements_of<JointFriction>(), [&](const JointFriction& f) {
    return "joint: " + joint(f.joint) + ", coulomb: " + format_number(f.coulomb) +
           ", viscous: " + format_number(f.viscous) + ", velocity_scale: " + format_number(f.velocity_scale);
  });
  list("stops", scene.elements_of<JointStop>(), [&](const JointStop& s) {
    return "joint: " + joint(s.joint) + ", position: " + format_number(s.position) +
           ", stiffness: " + format_number(s.stiffness) + ", damping: " + format_number(s.damping);
  });
  list("limits", scene.elements_of<JointLimit>(), [&](const JointLimit& l) {
    std::string text = "joint: " + joint(l.joint);
    if (std::isfinite(l.lower)) text += ", lower: " + format_number(l.lower);
    if (std::isfinite(l.upper)) text += ", upper: " + format_number(l.upper);
    return text + ", stiffness: " + format_number(l.stiffness) + ", damping: " + format_number(l.damping);
  });
  list("latches", scene.latches(), [&](const Latch& l) {
    return "joint: " + joint(l.joint) + ", position: " + format_number(l.position) +
           ", stiffness: " + format_number(l.stiffness) + ", damping: " + format_number(l.damping) +
           ", free_play: " + format_number(l.free_play);
  });
  list("drivers", scene.elements_of<JointDriver>(), [&](const JointDriver& d) {
    return "joint: " + joint(d.joint) + ", profile: " + driver_profile_name(d.profile) +
           ", amount: " + format_number(d.amount) + ", duration: " + format_number(d.duration) +
           ", start: " + format_number(d.start);
  });
  list("applied_forces", scene.elements_of<AppliedForce>(), [&](const AppliedForce& l) {
    return "body: " + body(l.body) + ", force: " + vec(l.force) + ", torque: " + vec(l.torque) +
           ", point: " + vec(l.point) + ", frame: " + (l.in_base_frame ? "base" : "body");
  });
  list("point_springs", scene.elements_of<PointSpring>(), [&](const PointSpring& s) {
    return (s.named ? "name: " + s.name + ", " : std::string()) + "body_a: " + body(s.body_a) +
           ", point_a: " + vec(s.point_a) + ", body_b: " + body(s.body_b) + ", point_b: " + vec(s.point_b) +
           ", stiffness: " + format_number(s.stiffness) + ", rest_length: " + format_number(s.rest_length) +
           ", damping: " + format_number(s.damping) + ", tension_only: " + (s.tension_only ? "true" : "false");
  });
  list("bushings", scene.elements_of<Bushing>(), [&](const Bushing& s) {
    const auto frame = [&](const BushingFrame& f, const std::string& end) {
      std::string text = ", body_" + end + ": " + body(f.body) + ", point_" + end + ": " + vec(f.point);
      if (f.rotation_deg != 0)
        text += ", rotation_" + end + ": " + numbers({f.rotation_axis[0], f.rotation_axis[1], f.rotation_axis[2],
                                                      f.rotation_deg});
      return text;
    };
    return "name: " + s.name + frame(s.a, "a") + frame(s.b, "b") + ", stiffness: " + matrix6(s.stiffness) +
           ", damping: " + matrix6(s.damping) +
           ", preload: " + numbers({s.preload.data(), s.preload.data() + 6});
  });
}

// initial: the joints' positions where they differ from neutral, and their
// rates or momenta where not zero.
void initial(std::ostream& out, const Scene& scene) {
  const Model& m = scene.model;
  const auto entries = [&](const std::vector<double>& x, bool positions) {
    std::string text;
    for (int j = 0; j < m.size(); ++j) {
      const Joint& joint = m.joints[j];
      const int n = positions ? joint.positions() : joint.dof();
      if (n == 0) continue;
      const int from = positions ? m.first_position[j].value : m.first_velocity[j].value;
      std::vector<double> values(x.begin() + from, x.begin() + from + n), neutral(n, 0.0);
      if (positions && n > 1) joint.neutral_positions(neutral.data());
      if (values == neutral) continue;
      text += (text.empty() ? "" : ", ") + joint.name + ": " +
              (joint.is_scalar() ? format_number(values[0]) : numbers(values));
    }
    return text;
  };
  const std::string q = entries(scene.q0, true);
  const std::string rates = scene.p0.empty() ? entries(scene.dq0, false) : entries(scene.p0, false);
  if (q.empty() && rates.empty()) return;
  out << "\ninitial:\n";
  if (!q.empty()) out << "  q: {" << q << "}\n";
  if (!rates.empty()) out << "  " << (scene.p0.empty() ? "dq" : "p") << ": {" << rates << "}\n";
}

void regulator(std::ostream& out, const RegulatorSettings& r) {
  const char* solver = r.solver == ClosureSolverKind::dense    ? "dense"
                       : r.solver == ClosureSolverKind::sparse ? "sparse"
                                                               : "auto";
  out << "\nregulator: {gains: " << (r.gains == GainTuning::full ? "full" : "paper")
      << (r.v_max ? ", v_max: " + format_number(*r.v_max) : "") << ", p0: " << format_number(r.p0)
      << ", p1: " << format_number(r.p1)
      << (r.regularization ? ", regularization: " + format_number(*r.regularization) : "")
      << ", feedforward: " << (r.feedforward ? "true" : "false") << ", solver: " << solver << "}\n";
}

void run(std::ostream& out, const RunSettings& r) {
  const char* linear = r.linear_solver == LinearSolverKind::dense    ? "dense"
                       : r.linear_solver == LinearSolverKind::krylov ? "krylov"
                                                                     : "auto";
  out << "\nrun: {t_end: " << format_number(r.t_end) << ", integrator: " << integrator_name(r.integrator)
      << ", linear_solver: " << linear << ", rtol: " << format_number(r.rtol) << ", atol: " << format_number(r.atol)
      << ", dt: " << format_number(r.dt) << ", sample: " << format_number(r.sample)
      << ", max_closure: " << format_number(r.max_closure) << ", event_window: " << format_number(r.event_window)
      << ", max_steps: " << r.max_steps << ", max_samples: " << r.max_samples;
  if (r.max_wall_time > 0) out << ", max_wall_time: " << format_number(r.max_wall_time);
  if (!r.roundoff_guard) out << ", roundoff_guard: false";
  if (r.stability_limit_detection != StabilityLimitDetection::off)
    out << ", stability_limit_detection: " << stability_limit_detection_name(r.stability_limit_detection);
  if (r.max_order_after_latch != kBdfMaxOrder) out << ", max_order_after_latch: " << r.max_order_after_latch;
  out << "}\n";
}

}  // namespace

// Body i's drawing: none where the scene was built in code without
// visuals (SceneVisuals empty, or shorter than the model).
const Visual& body_visual(const SceneFile& file, int i) {
  static const Visual none;
  return i < static_cast<int>(file.visuals.bodies.size()) ? file.visuals.bodies[i] : none;
}

std::string write_scene_text(const SceneFile& file, const std::string& comment) {
  const Scene& scene = file.scene;
  const Model& m = scene.model;
  std::ostringstream out;
  std::istringstream lines(comment);
  for (std::string line; std::getline(lines, line);) out << "# " << line << "\n";
  out << "name: " << scene.name << "\n";
  if (!scene.description.empty()) out << "description: " << quoted(scene.description) << "\n";
  const bool bus = m.free_floating();
  out << "\nbase:\n  name: " << (bus ? m.bodies[0].name : m.base_name) << "\n";
  const Visual& base_visual = bus ? body_visual(file, 0) : file.visuals.base;
  if (!base_visual.mesh.empty()) out << "  mesh: " << visual(base_visual) << "\n";
  collision(out, base_visual, "  ");
  if (!m.base_velocity.isZero(0))
    out << "  velocity: " << numbers({m.base_velocity.data(), m.base_velocity.data() + 6}) << "\n";
  if (bus) {
    out << "  free: true\n";
    mass_properties(out, m.bodies[0], "  ");
  }
  if (!scene.gravity().isZero(0)) out << "\ngravity: " << vec(scene.gravity()) << "\n";
  out << "\nbodies:\n";
  for (int i = bus ? 1 : 0; i < m.size(); ++i) {
    const int k = m.parent[i];
    out << "  - name: " << m.bodies[i].name << "\n    parent: " << (k == kBase ? m.base_name : m.bodies[k].name)
        << "\n";
    if (m.bodies[i].flexible && m.bodies[i].flexible->fem)
      flexible_body(out, *m.bodies[i].flexible->fem, "    ");
    else if (m.bodies[i].flexible && m.bodies[i].flexible->plate)
      flexible_body(out, *m.bodies[i].flexible->plate, "    ");
    else if (m.bodies[i].flexible)
      flexible_body(out, m.bodies[i].flexible->beam, "    ");
    else
      mass_properties(out, m.bodies[i], "    ");
    if (!body_visual(file, i).mesh.empty()) out << "    mesh: " << visual(body_visual(file, i)) << "\n";
    collision(out, body_visual(file, i), "    ");
    out << "    joint: " << joint_text(m.joints[i], compliance_of(scene, i)) << "\n";
  }
  elements(out, scene);
  if (!scene.loops.empty()) {
    out << "\nloops:\n";
    for (const Loop& l : scene.loops)
      out << "  - {name: " << l.name << ", body: " << m.bodies[l.body].name << ", image: " << m.bodies[l.image].name
          << "}\n";
    regulator(out, scene.regulator);
    out << "closure_tolerance: " << format_number(scene.closure_tolerance) << "\n";
  }
  if (!scene.sensors.empty()) {
    out << "\nsensors:\n";
    for (const Sensor& s : scene.sensors) {
      std::string measures;
      for (const SensorQuantity q : s.measures) measures += (measures.empty() ? "" : ", ") + std::string(sensor_quantity_name(q));
      out << "  - {name: " << s.name << ", body: " << m.bodies[s.body].name << ", point: " << vec(s.point)
          << ", frame: " << sensor_frame_name(s.frame) << ", measure: [" << measures << "]}\n";
    }
  }
  const TorqueMarginFactors& f = scene.torque_margin;
  if (!(f.spring == TorqueMarginFactors{}.spring && f.friction == TorqueMarginFactors{}.friction &&
        f.damping == TorqueMarginFactors{}.damping && f.harness == TorqueMarginFactors{}.harness &&
        f.inertia == TorqueMarginFactors{}.inertia && f.required == TorqueMarginFactors{}.required &&
        f.required_acceleration == TorqueMarginFactors{}.required_acceleration))
    out << "\ntorque_margin: {spring: " << format_number(f.spring) << ", friction: " << format_number(f.friction)
        << ", damping: " << format_number(f.damping) << ", harness: " << format_number(f.harness)
        << ", inertia: " << format_number(f.inertia) << ", required: " << format_number(f.required)
        << ", required_acceleration: " << format_number(f.required_acceleration) << "}\n";
  initial(out, scene);
  run(out, scene.run);
  return out.str();
}

SceneFile apply_overrides(const SceneFile& file, const std::vector<Override>& overrides) {
  if (overrides.empty()) return file;
  return read_scene_text(write_scene_text(file), file.scene.source, overrides);
}

}  // namespace unfurl::sim
