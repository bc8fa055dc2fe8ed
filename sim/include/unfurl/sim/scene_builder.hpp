// Builds a scene in code, naming bodies and joints as a scene file does:
// the way the file reader, the generators and the Python binding make
// scenes. build() validates (scene_validation.hpp), so a scene built here
// keeps every rule a file's does, with errors by field path.
//
//   SceneBuilder b("pendulum");
//   b.fixed_base("ground").gravity({0, 0, -9.81});
//   b.body(rod, "ground", Joint::revolute("hinge", Vec3::UnitX(), {0, 0, 0}, {0, 0, 0.5}));
//   b.initial_position("hinge", {0.3});
//   SceneFile scene = b.build();
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/visuals.hpp"

namespace unfurl::sim {

class SceneBuilder {
 public:
  explicit SceneBuilder(std::string name, std::string description = "");

  // Where the scene came from (a file's path; "code" by default).
  SceneBuilder& source(std::string source);
  // The base: fixed, possibly moving steadily (v, w in its own frame), or
  // free-floating with its own mass properties (a spacecraft bus). The
  // name is what bodies give as their parent.
  SceneBuilder& fixed_base(std::string name, const Vec6& velocity = Vec6::Zero(), Visual visual = {});
  SceneBuilder& free_base(const Body& bus, Visual visual = {});
  // A body on its joint to `parent` (a body added before, or the base). An
  // unnamed joint takes the body's name.
  SceneBuilder& body(const Body& body, const std::string& parent, Joint joint, Visual visual = {});

  // The index of a body or joint by name; throws SceneInvalid at `field`
  // when there is none (the base is kBase for body()).
  int body_index(const std::string& name, const std::string& field) const;
  int joint_index(const std::string& name, const std::string& field) const;
  // Whether a body (or the base) of this name was added.
  bool has_body(const std::string& name) const;

  // A force element; its bodies and joints by index (body_index, joint_index).
  SceneBuilder& element(std::shared_ptr<const ForceElement> element);
  SceneBuilder& gravity(const Vec3& g);
  // A loop opened by splitting `body`; its image hangs on another branch.
  SceneBuilder& loop(std::string name, const std::string& body, const std::string& image);
  SceneBuilder& regulator(const RegulatorSettings& settings);
  // A sensor on a body (by name, not the base).
  SceneBuilder& sensor(Sensor sensor, const std::string& body);
  SceneBuilder& closure_tolerance(double tolerance);
  SceneBuilder& run(const RunSettings& settings);
  SceneBuilder& torque_margin(const TorqueMarginFactors& factors);

  // Initial values of a joint's coordinates (its positions, its rates or
  // its momenta); the rest start at the joint's neutral position, at rest.
  SceneBuilder& initial_position(const std::string& joint, std::vector<double> q);
  SceneBuilder& initial_rate(const std::string& joint, std::vector<double> w);
  SceneBuilder& initial_momentum(const std::string& joint, std::vector<double> p);

  // The scene and its visuals, validated. Throws SceneInvalid.
  SceneFile build();

  // What is built so far (for a reader that resolves names as it goes).
  const Scene& scene() const { return scene_; }

 private:
  void set_initial(const std::string& joint, std::vector<double> values, int which);
  int node_at(int body, const Vec3& point, const std::string& field) const;
  static Body undeformed(Body body);
  // The body, its joint to `parent` and its drawing; a flexible body's
  // mass properties its undeformed shape's, its elasticity an element.
  void append(const Body& body, int parent, Joint joint, Visual visual);

  Scene scene_;
  SceneVisuals visuals_;
  Vec3 gravity_ = Vec3::Zero();
  struct Initial {
    std::string joint;
    std::vector<double> values;
    int which;  // 0 positions, 1 rates, 2 momenta
  };
  std::vector<Initial> initial_;
};

// Joints as code names them.
namespace joints {
Joint revolute(std::string name, const Vec3& axis, const Vec3& parent_point, const Vec3& child_point);
Joint prismatic(std::string name, const Vec3& axis, const Vec3& parent_point, const Vec3& child_point);
}  // namespace joints

}  // namespace unfurl::sim
