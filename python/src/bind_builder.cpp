// Scenes built in code (SceneBuilder): bodies on their joints, the force
// elements, loops, sensors and initial values by name, validated as a
// scene file is; errors name the field ("bodies[1] (arm).mass").
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "py_types.hpp"
#include "unfurl/sim/elements/all.hpp"
#include "unfurl/sim/scene_builder.hpp"

namespace unfurl::python {

namespace py = pybind11;

namespace {

sim::Mat3 inertia_matrix(const std::vector<double>& I) {
  if (I.size() != 3 && I.size() != 6)
    throw py::value_error("inertia: expected [Ixx, Iyy, Izz] or [Ixx, Iyy, Izz, Ixy, Ixz, Iyz]");
  sim::Mat3 J = sim::Mat3::Zero();
  J.diagonal() << I[0], I[1], I[2];
  if (I.size() == 6) J(0, 1) = J(1, 0) = I[3], J(0, 2) = J(2, 0) = I[4], J(1, 2) = J(2, 1) = I[5];
  return J;
}

sim::Body body_of(const std::string& name, double mass, const std::vector<double>& inertia, const sim::Vec3& com) {
  sim::Body b;
  b.name = name;
  b.mass = mass;
  b.com = com;
  b.inertia_com = inertia_matrix(inertia);
  return b;
}

template <class T>
T get_or(const py::dict& d, const char* key, T fallback) {
  return d.contains(key) ? d[key].cast<T>() : fallback;
}

sim::Joint joint_of(const py::dict& d) {
  sim::Joint j;
  const std::string type = get_or<std::string>(d, "type", "revolute");
  const auto parsed = sim::parse_joint_type(type);
  if (!parsed) throw py::value_error("joint type '" + type + "': expected revolute, prismatic, fixed, universal, spherical or planar");
  j.type = *parsed;
  j.name = get_or<std::string>(d, "name", "");
  j.axis = get_or<sim::Vec3>(d, "axis", sim::Vec3::UnitX());
  j.axis2 = get_or<sim::Vec3>(d, "axis2", sim::Vec3::UnitY());
  j.parent_point = get_or<sim::Vec3>(d, "parent_point", sim::Vec3::Zero());
  j.child_point = get_or<sim::Vec3>(d, "child_point", sim::Vec3::Zero());
  j.compliant = d.contains("compliance");
  for (auto item : d) {
    const std::string key = item.first.cast<std::string>();
    if (key != "type" && key != "name" && key != "axis" && key != "axis2" && key != "parent_point" &&
        key != "child_point" && key != "compliance")
      throw py::value_error("joint: unknown key '" + key + "'");
  }
  return j;
}

sim::Mat6 matrix6(const std::vector<std::vector<double>>& rows) {
  sim::Mat6 K = sim::Mat6::Zero();
  if (rows.size() == 1 && rows[0].size() == 6) {
    for (int k = 0; k < 6; ++k) K(k, k) = rows[0][k];
    return K;
  }
  if (rows.size() != 6) throw py::value_error("expected 6 numbers (a diagonal) or 6 rows of 6");
  for (int i = 0; i < 6; ++i) {
    if (rows[i].size() != 6) throw py::value_error("expected 6 rows of 6");
    for (int j = 0; j < 6; ++j) K(i, j) = rows[i][j];
  }
  return K;
}

// A 6-vector or a 6 x 6 matrix from Python.
sim::Mat6 matrix6(const py::object& x) {
  if (x.is_none()) return sim::Mat6::Zero();
  const auto list = x.cast<std::vector<py::object>>();
  if (list.size() == 6 && !py::isinstance<py::sequence>(list[0]))
    return matrix6(std::vector<std::vector<double>>{x.cast<std::vector<double>>()});
  return matrix6(x.cast<std::vector<std::vector<double>>>());
}

sim::BushingFrame frame_of(int body, const sim::Vec3& point, const std::optional<std::vector<double>>& rotation) {
  sim::BushingFrame f;
  f.body = body;
  f.point = point;
  if (rotation) {
    if (rotation->size() != 4) throw py::value_error("rotation: expected [axis x, axis y, axis z, angle in degrees]");
    f.rotation_axis = sim::Vec3((*rotation)[0], (*rotation)[1], (*rotation)[2]).normalized();
    f.rotation_deg = (*rotation)[3];
  }
  return f;
}

}  // namespace

void bind_builder(py::module_& m) {
  using B = sim::SceneBuilder;
  py::class_<B>(m, "_SceneBuilder")
      .def(py::init<std::string, std::string>(), py::arg("name"), py::arg("description") = "")
      .def("fixed_base",
           [](B& b, const std::string& name, const sim::Vec6& velocity) { b.fixed_base(name, velocity); },
           py::arg("name"), py::arg("velocity") = sim::Vec6::Zero())
      .def("free_base",
           [](B& b, const std::string& name, double mass, const std::vector<double>& inertia, const sim::Vec3& com) {
             b.free_base(body_of(name, mass, inertia, com));
           },
           py::arg("name"), py::arg("mass"), py::arg("inertia"), py::arg("com") = sim::Vec3::Zero())
      .def("body",
           [](B& b, const std::string& name, const std::string& parent, double mass,
              const std::vector<double>& inertia, const sim::Vec3& com, const py::dict& joint,
              const std::optional<std::string>& mesh) {
             sim::Visual visual;
             if (mesh) visual.mesh = *mesh;
             const sim::Joint j = joint_of(joint);
             b.body(body_of(name, mass, inertia, com), parent, j, visual);
             if (!j.compliant) return;
             const py::dict c = joint["compliance"].cast<py::dict>();
             auto pin = std::make_shared<sim::JointCompliance>();
             pin->joint = b.joint_index(j.name.empty() ? name : j.name, "compliance");
             pin->radial = get_or<double>(c, "radial", 0), pin->axial = get_or<double>(c, "axial", 0);
             pin->tilt = get_or<double>(c, "tilt", 0);
             pin->radial_damping = get_or<double>(c, "radial_damping", 0);
             pin->axial_damping = get_or<double>(c, "axial_damping", 0);
             pin->tilt_damping = get_or<double>(c, "tilt_damping", 0);
             b.element(pin);
           },
           py::arg("name"), py::arg("parent"), py::arg("mass"), py::arg("inertia"), py::arg("com") = sim::Vec3::Zero(),
           py::arg("joint") = py::dict(), py::arg("mesh") = std::nullopt)
      .def("spring",
           [](B& b, const std::string& joint, double stiffness, double free_position, double damping) {
             auto s = std::make_shared<sim::JointSpring>(b.joint_index(joint, "springs.joint"));
             s->stiffness = stiffness, s->free_position = free_position, s->damping = damping;
             b.element(s);
           },
           py::arg("joint"), py::arg("stiffness"), py::arg("free_position"), py::arg("damping") = 0.0)
      .def("damper",
           [](B& b, const std::string& joint, double damping) {
             auto d = std::make_shared<sim::JointDamper>(b.joint_index(joint, "dampers.joint"));
             d->damping = damping;
             b.element(d);
           },
           py::arg("joint"), py::arg("damping"))
      .def("friction",
           [](B& b, const std::string& joint, double coulomb, double viscous, double velocity_scale) {
             auto f = std::make_shared<sim::JointFriction>(b.joint_index(joint, "friction.joint"));
             f->coulomb = coulomb, f->viscous = viscous, f->velocity_scale = velocity_scale;
             b.element(f);
           },
           py::arg("joint"), py::arg("coulomb"), py::arg("viscous") = 0.0, py::arg("velocity_scale") = 1e-3)
      .def("latch",
           [](B& b, const std::string& joint, double position, double stiffness, double damping, double free_play) {
             auto l = std::make_shared<sim::Latch>(b.joint_index(joint, "latches.joint"));
             l->position = position, l->stiffness = stiffness, l->damping = damping, l->free_play = free_play;
             b.element(l);
           },
           py::arg("joint"), py::arg("position"), py::arg("stiffness"), py::arg("damping"), py::arg("free_play") = 0.0)
      .def("limit",
           [](B& b, const std::string& joint, double stiffness, std::optional<double> lower,
              std::optional<double> upper, double damping) {
             if (!lower && !upper) throw py::value_error("limit: give lower, upper or both");
             auto l = std::make_shared<sim::JointLimit>(b.joint_index(joint, "limits.joint"));
             if (lower) l->lower = *lower;
             if (upper) l->upper = *upper;
             l->stiffness = stiffness, l->damping = damping;
             b.element(l);
           },
           py::arg("joint"), py::arg("stiffness"), py::arg("lower") = std::nullopt, py::arg("upper") = std::nullopt,
           py::arg("damping") = 0.0)
      .def("driver",
           [](B& b, const std::string& joint, const std::string& profile, double amount, double duration, double start) {
             auto d = std::make_shared<sim::JointDriver>(b.joint_index(joint, "drivers.joint"));
             const auto parsed = sim::parse_driver_profile(profile);
             if (!parsed) throw py::value_error("profile: expected move or spin_up, got '" + profile + "'");
             d->profile = *parsed, d->amount = amount, d->duration = duration, d->start = start;
             b.element(d);
           },
           py::arg("joint"), py::arg("profile"), py::arg("amount"), py::arg("duration"), py::arg("start") = 0.0)
      .def("point_spring",
           [](B& b, const std::string& name, const std::string& body_a, const sim::Vec3& point_a,
              const std::string& body_b, const sim::Vec3& point_b, double stiffness, double rest_length,
              double damping, bool tension_only) {
             auto s = std::make_shared<sim::PointSpring>();
             s->name = name, s->named = true;
             s->body_a = b.body_index(body_a, "point_springs.body_a");
             s->body_b = b.body_index(body_b, "point_springs.body_b");
             s->point_a = point_a, s->point_b = point_b;
             s->stiffness = stiffness, s->rest_length = rest_length, s->damping = damping;
             s->tension_only = tension_only;
             b.element(s);
           },
           py::arg("name"), py::arg("body_a"), py::arg("point_a"), py::arg("body_b"), py::arg("point_b"),
           py::arg("stiffness"), py::arg("rest_length"), py::arg("damping") = 0.0, py::arg("tension_only") = false)
      .def("bushing",
           [](B& b, const std::string& name, const std::string& body_a, const sim::Vec3& point_a,
              const std::string& body_b, const sim::Vec3& point_b, const py::object& stiffness,
              const py::object& damping, const std::optional<std::vector<double>>& preload,
              const std::optional<std::vector<double>>& rotation_a,
              const std::optional<std::vector<double>>& rotation_b) {
             auto s = std::make_shared<sim::Bushing>();
             s->name = name;
             s->a = frame_of(b.body_index(body_a, "bushings.body_a"), point_a, rotation_a);
             s->b = frame_of(b.body_index(body_b, "bushings.body_b"), point_b, rotation_b);
             s->stiffness = matrix6(stiffness);
             s->damping = matrix6(damping);
             if (preload) {
               if (preload->size() != 6) throw py::value_error("preload: expected 6 numbers");
               for (int k = 0; k < 6; ++k) s->preload[k] = (*preload)[k];
             }
             b.element(s);
           },
           py::arg("name"), py::arg("body_a"), py::arg("point_a"), py::arg("body_b"), py::arg("point_b"),
           py::arg("stiffness"), py::arg("damping") = py::none(), py::arg("preload") = std::nullopt,
           py::arg("rotation_a") = std::nullopt, py::arg("rotation_b") = std::nullopt)
      .def("applied_force",
           [](B& b, const std::string& body, const sim::Vec3& force, const sim::Vec3& torque, const sim::Vec3& point,
              const std::string& frame) {
             auto f = std::make_shared<sim::AppliedForce>();
             f->body = b.body_index(body, "applied_forces.body");
             f->force = force, f->torque = torque, f->point = point;
             if (frame != "body" && frame != "base") throw py::value_error("frame: expected body or base");
             f->in_base_frame = frame == "base";
             b.element(f);
           },
           py::arg("body"), py::arg("force") = sim::Vec3::Zero(), py::arg("torque") = sim::Vec3::Zero(),
           py::arg("point") = sim::Vec3::Zero(), py::arg("frame") = "body")
      .def("gravity", [](B& b, const sim::Vec3& g) { b.gravity(g); }, py::arg("g"))
      .def("loop", [](B& b, const std::string& name, const std::string& body,
                      const std::string& image) { b.loop(name, body, image); },
           py::arg("name"), py::arg("body"), py::arg("image"))
      .def("sensor",
           [](B& b, const std::string& name, const std::string& body, const sim::Vec3& point,
              const std::string& frame, const std::vector<std::string>& measure) {
             sim::Sensor s;
             s.name = name;
             s.point = point;
             if (frame != "body" && frame != "inertial") throw py::value_error("frame: expected body or inertial");
             s.frame = frame == "body" ? sim::SensorFrame::body : sim::SensorFrame::inertial;
             s.measures.clear();
             for (const std::string& q : measure) {
               bool known = false;
               for (const auto k : {sim::SensorQuantity::position, sim::SensorQuantity::velocity,
                                    sim::SensorQuantity::acceleration, sim::SensorQuantity::angular_rate,
                                    sim::SensorQuantity::angular_acceleration})
                 if (q == sim::sensor_quantity_name(k)) s.measures.push_back(k), known = true;
               if (!known) throw py::value_error("measure: unknown quantity '" + q + "'");
             }
             b.sensor(std::move(s), body);
           },
           py::arg("name"), py::arg("body"), py::arg("point") = sim::Vec3::Zero(), py::arg("frame") = "body",
           py::arg("measure") = std::vector<std::string>{"acceleration"})
      .def("initial",
           [](B& b, const std::string& joint, const std::optional<std::vector<double>>& q,
              const std::optional<std::vector<double>>& dq) {
             if (q) b.initial_position(joint, *q);
             if (dq) b.initial_rate(joint, *dq);
           },
           py::arg("joint"), py::arg("q") = std::nullopt, py::arg("dq") = std::nullopt)
      .def("run",
           [](B& b, double t_end, const std::string& integrator, double rtol, double atol, double sample) {
             sim::RunSettings r;
             r.t_end = t_end, r.rtol = rtol, r.atol = atol, r.sample = sample;
             const auto kind = sim::parse_integrator(integrator);
             if (!kind) throw py::value_error("integrator '" + integrator + "' is not one unfurl has");
             r.integrator = *kind;
             b.run(r);
           },
           py::arg("t_end") = 10.0, py::arg("integrator") = "cvode-bdf", py::arg("rtol") = 1e-8,
           py::arg("atol") = 1e-10, py::arg("sample") = 0.01)
      .def("build", [](B& b) { return PyScene{b.build()}; });
}

}  // namespace unfurl::python
