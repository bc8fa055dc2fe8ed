#include "unfurl/io/mjcf_export.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "unfurl/sim/dynamics.hpp"
#include "unfurl/sim/elements/all.hpp"
#include "unfurl/sim/kinematics.hpp"
#include "unfurl/sim/number_text.hpp"
#include "unfurl/io/output_file.hpp"

namespace unfurl::io {

namespace {

std::string num(double x) { return sim::format_number(x); }

std::string vec(const sim::Vec3& v) { return num(v.x()) + " " + num(v.y()) + " " + num(v.z()); }

// Where a limit's open end is written: MJCF's range and numerics are finite.
constexpr double kOpenEnd = 1e10;

// Text safe inside an XML comment.
std::string comment_text(std::string s) {
  for (std::size_t at = s.find("--"); at != std::string::npos; at = s.find("--")) s.replace(at, 2, "- -");
  return s;
}

struct MassProperties {
  double mass = 0;
  sim::Vec3 com = sim::Vec3::Zero();
  sim::Mat3 inertia = sim::Mat3::Zero();  // about com, body axes
};

// A body's mass properties with another body's added, that one placed in
// this one's frame by (R, p): x_this = R x_other + p.
MassProperties merged(const sim::Body& a, const sim::Body& b, const sim::Mat3& R, const sim::Vec3& p) {
  MassProperties out;
  out.mass = a.mass + b.mass;
  const sim::Vec3 cb = R * b.com + p;
  out.com = (a.mass * a.com + b.mass * cb) / out.mass;
  auto shifted = [](double m, const sim::Vec3& d) {
    return m * (d.squaredNorm() * sim::Mat3::Identity() - d * d.transpose());
  };
  out.inertia = a.inertia_com + shifted(a.mass, a.com - out.com) + R * b.inertia_com * R.transpose() +
                shifted(b.mass, cb - out.com);
  // The round-off of bringing a coinciding image over, not physics.
  const double scale = out.inertia.norm(), length = std::sqrt(scale / out.mass);
  out.inertia = out.inertia.unaryExpr([&](double x) { return std::abs(x) < 1e-12 * scale ? 0.0 : x; });
  out.com = out.com.unaryExpr([&](double x) { return std::abs(x) < 1e-12 * length ? 0.0 : x; });
  return out;
}

class Writer {
 public:
  explicit Writer(const sim::Scene& scene) : scene_(scene), model_(scene.model) {
    sim::body_poses(model_, scene.q0.data(), poses_);
    for (const sim::Loop& loop : scene.loops) {
      image_of_[loop.image] = &loop;
      body_of_[loop.body] = &loop;
      if (model_.joints[loop.image].type != sim::JointType::revolute)
        throw std::runtime_error("cannot export to MJCF: loop '" + loop.name + "' is closed at a " +
                                 sim::joint_type_name(model_.joints[loop.image].type) +
                                 " joint, and a point constraint stands only for a hinge");
      for (int i = 0; i < model_.size(); ++i)
        if (model_.parent[i] == loop.image)
          throw std::runtime_error("cannot export to MJCF: the image '" + model_.bodies[loop.image].name +
                                   "' of loop '" + loop.name + "' carries bodies of its own");
    }
    sim::Dynamics dynamics(scene);
    const std::vector<double> y = dynamics.initial_state();
    sim::Observation o;
    dynamics.observe(0, y.data(), o);
    dq0_ = o.q_dot;
    rates0_ = o.w;
  }

  MjcfModel write() {
    MjcfModel out;
    header();
    out_ << "  <worldbody>\n";
    sites(sim::kBase, "    ");
    for (int i = 0; i < model_.size(); ++i)
      if (model_.parent[i] == sim::kBase && !image_of_.count(i)) body(i, 2);
    out_ << "  </worldbody>\n";
    tendons();
    equalities();
    custom_numerics();
    keyframe();
    out_ << "</mujoco>\n";
    out.xml = out_.str();
    out.not_exported = not_exported_;
    if (deepest_ > kMujocoDeepestBody)
      out.warnings.push_back("bodies nest " + std::to_string(deepest_) + " deep (down to '" + deepest_body_ +
                             "'); MuJoCo's XML parser refuses more than " + std::to_string(kMujocoDeepestBody) +
                             " (\"Element nesting is too deep\"), so MuJoCo will not load this file");
    return out;
  }

 private:
  void header() {
    const sim::Model& m = model_;
    out_ << "<!-- " << comment_text(scene_.name) << ": exported by `unfurl export mjcf` from "
         << comment_text(scene_.source)
         << ".\n     Bodies sit at the scene's initial coordinates and each joint's ref is that\n"
         << "     coordinate, so MuJoCo's qpos is unfurl's q. Closed loops are merged back into\n"
         << "     one body and closed by equality/connect at the split pivot. -->\n";
    out_ << "<mujoco model=\"" << scene_.name << "\">\n";
    out_ << "  <compiler angle=\"radian\" inertiafromgeom=\"false\"/>\n";
    out_ << "  <option timestep=\"1e-4\" integrator=\"RK4\" gravity=\"" << vec(scene_.gravity()) << "\">\n";
    out_ << "    <flag contact=\"disable\" energy=\"enable\"/>\n  </option>\n";
    if (!m.base_velocity.isZero(0))
      unsupported("the base moves (velocity " + vec(m.base_velocity.head<3>()) + ", " + vec(m.base_velocity.tail<3>()) +
                  "): the model's base is fixed");
    for (const auto& e : scene_.elements) {
      if (const auto* load = dynamic_cast<const sim::AppliedForce*>(e.get()))
        unsupported("a constant load on '" + m.bodies[load->body].name + "' (MJCF has no constant body force)");
      else if (!exported(*e))
        unsupported("a " + e->kind() + " (" + e->list() + "): MJCF has no form for it here");
    }
  }

  void body(int i, int depth) {
    const sim::Model& m = model_;
    if (depth - 1 > deepest_) deepest_ = depth - 1, deepest_body_ = m.bodies[i].name;
    const std::string pad(2 * depth, ' ');
    const sim::Joint& joint = m.joints[i];
    const int c = m.first_position[i].value;
    // A ball's or planar joint's body sits at the joint's neutral position,
    // so MuJoCo's qpos for it is unfurl's q; a hinge's or slide's at q0 with
    // ref = q0; a free body where q0 puts it (its qpos is its pose).
    std::vector<double> neutral(std::max(1, joint.positions()));
    joint.neutral_positions(neutral.data());
    const bool at_q0 = joint.is_scalar() || joint.compliant || joint.type == sim::JointType::free;
    const sim::Placement X = joint.placement(c >= 0 && at_q0 ? &scene_.q0[c] : neutral.data());
    const Eigen::Quaterniond quat(X.G.transpose());
    out_ << pad << "<body name=\"" << m.bodies[i].name << "\" pos=\"" << vec(X.rho) << "\" quat=\"" << num(quat.w())
         << " " << num(quat.x()) << " " << num(quat.y()) << " " << num(quat.z()) << "\">\n";
    inertial(i, pad + "  ");
    sites(i, pad + "  ");
    if (joint.type != sim::JointType::fixed) {
      this->joint(i, pad + "  ");
      written_.push_back(i);
    }
    for (int child = 0; child < m.size(); ++child)
      if (m.parent[child] == i && !image_of_.count(child)) body(child, depth + 1);
    out_ << pad << "</body>\n";
  }

  // A lamina's principal moments meet the triangle inequality with
  // equality (a flexible plate's, C = A + B), which MuJoCo checks
  // literally on its own eigenvalues: within round-off of it (1e-12 of C),
  // every moment is raised by the shortfall and 1e-12 of C more (the
  // products unchanged), so that A + B > C whoever rounds.
  static sim::Mat3 within_triangle_inequality(const sim::Mat3& J) {
    const Eigen::Vector3d moments = Eigen::SelfAdjointEigenSolver<sim::Mat3>(J, Eigen::EigenvaluesOnly).eigenvalues();
    const double C = moments[2], shortfall = C - moments[0] - moments[1];
    if (shortfall <= -1e-12 * C) return J;
    return J + (std::max(shortfall, 0.0) + 1e-12 * C) * sim::Mat3::Identity();
  }

  void inertial(int i, const std::string& pad) {
    const sim::Body& b = model_.bodies[i];
    MassProperties mp{b.mass, b.com, b.inertia_com};
    if (const auto loop = body_of_.find(i); loop != body_of_.end()) {
      // The image, seen from the split body at the initial state.
      const sim::Pose &P = poses_[i], &Q = poses_[loop->second->image];
      mp = merged(b, model_.bodies[loop->second->image], P.rotation * Q.rotation.transpose(),
                  P.rotation * (Q.position - P.position));
      out_ << pad << "<!-- with its image '" << model_.bodies[loop->second->image].name << "' merged back -->\n";
    }
    const sim::Mat3 J = within_triangle_inequality(mp.inertia);
    out_ << pad << "<inertial pos=\"" << vec(mp.com) << "\" mass=\"" << num(mp.mass) << "\" fullinertia=\""
         << num(J(0, 0)) << " " << num(J(1, 1)) << " " << num(J(2, 2)) << " " << num(J(0, 1)) << " " << num(J(0, 2))
         << " " << num(J(1, 2)) << "\"/>\n";
  }

  void joint(int i, const std::string& pad) {
    const sim::Joint& j = model_.joints[i];
    const int c = model_.first_position[i].value;
    // Springs on one joint add up to one: stiffness sum k, rest at the
    // stiffness-weighted free position (the same torque for every q).
    double k = 0, k_free = 0, damping = 0;
    for (const sim::JointSpring* s : scene_.elements_of<sim::JointSpring>())
      if (s->joint == i) k += s->stiffness, k_free += s->stiffness * s->free_position, damping += s->damping;
    for (const sim::JointDamper* d : scene_.elements_of<sim::JointDamper>())
      if (d->joint == i) damping += d->damping;
    // Coulomb friction becomes MuJoCo's frictionloss, a dry-friction
    // constraint that sticks exactly where ours (tanh, joint_friction.hpp)
    // creeps.
    for (const sim::JointSpring* s : scene_.elements_of<sim::JointSpring>())
      if (s->joint == i && s->curve)
        unsupported("the measured spring curve of '" + j.name + "' (MJCF joint springs are linear)");
    double frictionloss = 0;
    for (const sim::JointFriction* f : scene_.elements_of<sim::JointFriction>())
      if (f->joint == i) frictionloss += f->coulomb, damping += f->viscous;
    if (j.compliant) compliant_pin(i, pad);
    switch (j.type) {
      case sim::JointType::free:
        out_ << pad << "<freejoint name=\"" << j.name << "\"/>\n";
        return;
      case sim::JointType::spherical:
        out_ << pad << "<joint name=\"" << j.name << "\" type=\"ball\" pos=\"" << vec(j.child_point) << "\"/>\n";
        return;
      case sim::JointType::universal:
        // Two hinges in one body: MuJoCo turns the second axis by the
        // first, as the cross carries it.
        for (int k = 1; k <= 2; ++k)
          out_ << pad << "<joint name=\"" << j.name << "." << k << "\" type=\"hinge\" axis=\""
               << vec(k == 1 ? j.axis : j.axis2) << "\" pos=\"" << vec(j.child_point) << "\"/>\n";
        return;
      case sim::JointType::planar:
        // Two slides along the plane's axes (in the parent's axes: they
        // come before the hinge), then the hinge about the normal.
        out_ << pad << "<joint name=\"" << j.name << ".x1\" type=\"slide\" axis=\"" << vec(j.plane_axis_1()) << "\"/>\n"
             << pad << "<joint name=\"" << j.name << ".x2\" type=\"slide\" axis=\"" << vec(j.plane_axis_2()) << "\"/>\n"
             << pad << "<joint name=\"" << j.name << ".angle\" type=\"hinge\" axis=\"" << vec(j.axis) << "\" pos=\""
             << vec(j.child_point) << "\"/>\n";
        return;
      default:
        break;
    }
    out_ << pad << "<joint name=\"" << j.name << "\" type=\""
         << (j.type == sim::JointType::revolute ? "hinge" : "slide") << "\" axis=\"" << vec(j.axis) << "\" pos=\""
         << vec(j.type == sim::JointType::revolute ? j.child_point : sim::Vec3::Zero()) << "\" ref=\""
         << num(scene_.q0[c]) << "\"";
    if (k > 0) out_ << " stiffness=\"" << num(k) << "\" springref=\"" << num(k_free / k) << "\"";
    if (damping > 0) out_ << " damping=\"" << num(damping) << "\"";
    if (frictionloss > 0) out_ << " frictionloss=\"" << num(frictionloss) << "\"";
    if (const sim::JointLimit* l = limit_of(i))
      out_ << " limited=\"true\" range=\"" << num(end(l->lower)) << " " << num(end(l->upper)) << "\"";
    out_ << "/>\n";
  }

  // The joint's limits (the first, where it has several), or null.
  const sim::JointLimit* limit_of(int i) const {
    for (const sim::JointLimit* l : scene_.elements_of<sim::JointLimit>())
      if (l->joint == i) return l;
    return nullptr;
  }
  // MJCF's range has two finite ends: an open one as far off as kOpenEnd.
  static double end(double x) { return std::isfinite(x) ? x : std::copysign(kOpenEnd, x); }

  // A compliant hinge's pin: three slides and two hinges before the hinge
  // itself, each with its spring and damper, their axes in the body's
  // frame at q0 (MuJoCo composes a body's joints in order, as the pin's
  // coordinates do, joint.hpp).
  void compliant_pin(int i, const std::string& pad) {
    const sim::Joint& j = model_.joints[i];
    const int c = model_.first_position[i].value;
    const sim::Mat3 to_child = j.placement(&scene_.q0[c]).G;  // the tilts and moves are 0 at q0 in scenes
    const sim::JointCompliance* pin = nullptr;
    for (const sim::JointCompliance* e : scene_.elements_of<sim::JointCompliance>())
      if (e->joint == i) pin = e;
    if (!pin) return;
    const sim::Vec3 e1 = j.cross_axis_1(), e2 = j.cross_axis_2();
    const struct {
      const char* name;
      const char* type;
      sim::Vec3 axis;
      double stiffness, damping;
    } parts[] = {{"u1", "slide", e1, pin->radial, pin->radial_damping},
                 {"u2", "slide", e2, pin->radial, pin->radial_damping},
                 {"ua", "slide", j.axis, pin->axial, pin->axial_damping},
                 {"r1", "hinge", e1, pin->tilt, pin->tilt_damping},
                 {"r2", "hinge", e2, pin->tilt, pin->tilt_damping}};
    for (int k = 0; k < 5; ++k) {
      const auto& p = parts[k];
      out_ << pad << "<joint name=\"" << j.name << "." << p.name << "\" type=\"" << p.type << "\" axis=\""
           << vec(to_child * p.axis) << "\"";
      if (std::string(p.type) == "hinge") out_ << " pos=\"" << vec(j.child_point) << "\"";
      out_ << " ref=\"" << num(scene_.q0[c + 1 + k]) << "\" stiffness=\"" << num(p.stiffness) << "\" springref=\"0\"";
      if (p.damping > 0) out_ << " damping=\"" << num(p.damping) << "\"";
      out_ << "/>\n";
    }
  }

  // The body a point is written on (an image is merged into its split
  // body), and the point in that body's frame.
  std::pair<int, sim::Vec3> written_point(int body, const sim::Vec3& r) const {
    const auto loop = image_of_.find(body);
    if (loop == image_of_.end()) return {body, r};
    const sim::Pose &P = poses_[loop->second->body], &Q = poses_[body];
    return {loop->second->body, P.rotation * (Q.to_base(r) - P.position)};
  }

  // The ends of the point springs on body i, as sites NAME_a and NAME_b.
  void sites(int i, const std::string& pad) {
    for (const sim::PointSpring* s : scene_.elements_of<sim::PointSpring>())
      for (const auto& [body, point, end] :
           {std::tuple{s->body_a, s->point_a, "_a"}, std::tuple{s->body_b, s->point_b, "_b"}}) {
        const auto [on, r] = body == sim::kBase ? std::pair{sim::kBase, point} : written_point(body, point);
        if (on == i)
          out_ << pad << "<site name=\"" << s->name << end << "\" pos=\"" << vec(r) << "\" size=\"0.005\"/>\n";
      }
  }

  // Point springs as spatial tendons between their two sites.
  void tendons() {
    const std::vector<const sim::PointSpring*> springs = scene_.elements_of<sim::PointSpring>();
    if (springs.empty()) return;
    out_ << "  <tendon>\n";
    for (const sim::PointSpring* s : springs) {
      out_ << "    <spatial name=\"" << s->name << "\" stiffness=\"" << num(s->stiffness) << "\" springlength=\""
           << num(s->rest_length) << "\" damping=\"" << num(s->damping) << "\" width=\"0.006\">\n"
           << "      <site site=\"" << s->name << "_a\"/>\n      <site site=\"" << s->name
           << "_b\"/>\n    </spatial>\n";
      if (s->tension_only)
        unsupported("cable '" + s->name + "' is tension-only; MJCF's tendon spring also pushes when slack");
    }
    out_ << "  </tendon>\n";
  }

  void equalities() {
    const std::vector<const sim::Bushing*> bushings = scene_.elements_of<sim::Bushing>();
    if (scene_.loops.empty() && bushings.empty()) return;
    out_ << "  <!-- The loops: each image's joint becomes a point constraint at its pivot,\n"
         << "       and each bushing one at its frame b (MJCF has no six-component spring\n"
         << "       between bodies), as stiff as MuJoCo allows: it raises the time constant\n"
         << "       to twice the timestep (refsafe); impedance 0.9999. -->\n  <equality>\n";
    for (const sim::Bushing* b : bushings) bushing(*b);
    for (const sim::Loop& loop : scene_.loops) {
      const sim::Joint& pivot = model_.joints[loop.image];
      // The pivot in the split body's frame: the image's hinge point.
      const sim::Pose &P = poses_[loop.body], &Q = poses_[loop.image];
      const sim::Vec3 anchor = P.rotation * (Q.to_base(pivot.child_point) - P.position);
      const int parent = model_.parent[loop.image];
      out_ << "    <connect name=\"" << loop.name << "\" body1=\"" << model_.bodies[loop.body].name << "\" body2=\""
           << (parent == sim::kBase ? std::string("world") : model_.bodies[parent].name) << "\" anchor=\""
           << vec(anchor) << "\" solref=\"1e-9 1\" solimp=\"0.9999 0.9999 0.001 0.5 2\"/>\n";
      for (const sim::JointElement* e : scene_.elements_of<sim::JointElement>())
        if (e->joint == loop.image)
          unsupported("a " + e->kind() + " on the loop joint '" + pivot.name + "' (it became a connect constraint)");
    }
    out_ << "  </equality>\n";
  }

  // A bushing becomes a point constraint at frame b's origin, as stiff as
  // MuJoCo allows: MJCF has no six-component spring between bodies, and a
  // soft equality's stiffness (solref < 0) is per unit of effective mass,
  // not N/m, so no setting reproduces the bushing's.
  void bushing(const sim::Bushing& b) {
    const auto on = [&](const sim::BushingFrame& f) {
      return f.body == sim::kBase ? std::pair{sim::kBase, f.point} : written_point(f.body, f.point);
    };
    const int body_a = on(b.a).first;
    const auto [body_b, point_b] = on(b.b);
    const auto name = [&](int i) { return i == sim::kBase ? std::string("world") : model_.bodies[i].name; };
    out_ << "    <connect name=\"" << b.name << "\" body1=\"" << name(body_b) << "\" body2=\"" << name(body_a)
         << "\" anchor=\"" << vec(point_b) << "\" solref=\"1e-9 1\" solimp=\"0.9999 0.9999 0.001 0.5 2\"/>\n";
    unsupported("the bushing '" + b.name +
                "' became a rigid point constraint: its stiffness, damping, rotational stiffness and preload are lost");
  }

  // What MJCF cannot say as unfurl does, as custom numerics for a runner to
  // apply through mjcb_passive: the latches, and the limits' own law.
  void custom_numerics() {
    const std::vector<const sim::Latch*> latches = scene_.latches();
    const std::vector<const sim::JointLimit*> limits = scene_.elements_of<sim::JointLimit>();
    if (latches.empty() && limits.empty()) return;
    out_ << "  <custom>\n";
    this->latches(latches);
    this->limits(limits);
    out_ << "  </custom>\n";
  }

  void limits(const std::vector<const sim::JointLimit*>& limits) {
    if (limits.empty()) return;
    out_ << "    <!-- A joint's range is MuJoCo's limit, a soft constraint of MuJoCo's own\n"
         << "         stiffness (solreflimit). unfurl's: beyond an end, -stiffness x - damping dq\n"
         << "         (x past it), never pulling the joint back onto it. limit:JOINT = lower,\n"
         << "         upper (an open end +-" << num(kOpenEnd) << "), stiffness, damping; to reproduce\n"
         << "         unfurl's, clear jnt_limited and apply them through mjcb_passive. -->\n";
    for (const sim::JointLimit* l : limits) {
      const std::string& joint = model_.joints[l->joint].name;
      if (limit_of(l->joint) != l) {
        unsupported("a second limit on '" + joint + "' (MJCF has one range per joint)");
        continue;
      }
      out_ << "    <numeric name=\"limit:" << joint << "\" data=\"" << num(end(l->lower)) << " " << num(end(l->upper))
           << " " << num(l->stiffness) << " " << num(l->damping) << "\"/>\n";
      unsupported("the limits of '" + joint +
                  "' became MuJoCo's joint range, its own soft constraint (unfurl's kept as custom numeric limit:" +
                  joint + ")");
    }
  }

  void latches(const std::vector<const sim::Latch*>& latches) {
    if (latches.empty()) return;
    out_ << "    <!-- Not in MJCF: latches. Joint JOINT latches the first time it reaches its\n"
         << "         position and from then on feels -stiffness (q - position) - damping dq.\n"
         << "         latch:JOINT = position, stiffness, damping, side (sign of q0 - position;\n"
         << "         0: engaged from the start); apply them through mjcb_passive. -->\n";
    for (const sim::Latch* l : latches) {
      const double offset = scene_.q0[model_.position_of(l->joint).value] - l->position;
      const double side = offset > 0 ? 1 : offset < 0 ? -1 : 0;
      out_ << "    <numeric name=\"latch:" << model_.joints[l->joint].name << "\" data=\"" << num(l->position) << " "
           << num(l->stiffness) << " " << num(l->damping) << " " << num(side) << "\"/>\n";
      unsupported("the latch of '" + model_.joints[l->joint].name +
                  "' (kept as custom numeric latch:" + model_.joints[l->joint].name + ")");
      if (l->free_play > 0) unsupported("the free play of the latch of '" + model_.joints[l->joint].name + "'");
    }
  }

  void keyframe() {
    // In the order the joints were written: MuJoCo's qpos order.
    // MuJoCo's qvel: a free joint's linear velocity in the world frame
    // (unfurl's x'), then its angular velocity in the body frame (unfurl's
    // rates, as for a ball); a planar joint's slides and hinge: q'.
    std::string qpos, qvel;
    const auto add = [](std::string& list, double x) { list += (list.empty() ? "" : " ") + num(x); };
    for (int i : written_) {
      const sim::Joint& j = model_.joints[i];
      const int c = model_.first_position[i].value, v = model_.first_velocity[i].value;
      if (j.compliant) {  // the pin's five, then the hinge (compliant_pin)
        for (const int k : {1, 2, 3, 4, 5, 0}) add(qpos, scene_.q0[c + k]), add(qvel, dq0_[c + k]);
        continue;
      }
      for (int k = 0; k < j.positions(); ++k) add(qpos, scene_.q0[c + k]);
      if (j.type == sim::JointType::free) {
        for (int k = 0; k < 3; ++k) add(qvel, dq0_[c + k]);
        for (int k = 3; k < 6; ++k) add(qvel, rates0_[v + k]);
      } else if (j.type == sim::JointType::spherical) {
        for (int k = 0; k < 3; ++k) add(qvel, rates0_[v + k]);
      } else {
        for (int k = 0; k < j.positions(); ++k) add(qvel, dq0_[c + k]);
      }
    }
    out_ << "  <keyframe>\n    <key name=\"initial\" qpos=\"" << qpos << "\" qvel=\"" << qvel
         << "\"/>\n  </keyframe>\n";
  }

  // Whether the writer has a form (or a note) for an element of this kind.
  static bool exported(const sim::ForceElement& e) {
    return dynamic_cast<const sim::JointSpring*>(&e) || dynamic_cast<const sim::JointDamper*>(&e) ||
           dynamic_cast<const sim::JointFriction*>(&e) || dynamic_cast<const sim::Latch*>(&e) ||
           dynamic_cast<const sim::PointSpring*>(&e) || dynamic_cast<const sim::Gravity*>(&e) ||
           dynamic_cast<const sim::AppliedForce*>(&e) || dynamic_cast<const sim::Bushing*>(&e) ||
           dynamic_cast<const sim::JointCompliance*>(&e) || dynamic_cast<const sim::JointLimit*>(&e);
  }

  void unsupported(const std::string& what) {
    not_exported_.push_back(what);
    out_ << "  <!-- Not exported: " << comment_text(what) << " -->\n";
  }

  const sim::Scene& scene_;
  const sim::Model& model_;
  std::vector<sim::Pose> poses_;
  std::vector<double> dq0_, rates0_;  // q' and the rates at t = 0
  std::vector<int> written_;          // bodies whose joints are in the file, in file order
  std::map<int, const sim::Loop*> image_of_, body_of_;
  std::vector<std::string> not_exported_;
  int deepest_ = 0;  // bodies nested below the world
  std::string deepest_body_;
  std::ostringstream out_;
};

}  // namespace

MjcfModel export_mjcf(const sim::Scene& scene) { return Writer(scene).write(); }

}  // namespace unfurl::io
