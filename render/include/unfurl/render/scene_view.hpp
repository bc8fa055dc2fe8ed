// Draws a scene's bodies at given poses: each body's mesh (scaled, offset,
// turned as the scene's visuals say) placed by its pose, hinge pins at the joints, a
// sun-like light with ambient fill, over a gradient background. Images of
// split bodies are not drawn (they coincide with their originals).
#pragma once

#include <Eigen/Geometry>
#include <memory>
#include <vector>

#include "unfurl/render/camera.hpp"
#include "unfurl/render/load_arrows.hpp"
#include "unfurl/sim/kinematics.hpp"
#include "unfurl/render/mesh_library.hpp"
#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/visuals.hpp"

namespace unfurl::render {

class Shader;

class SceneView {
 public:
  // Loads the meshes the scene names (throws std::runtime_error when one is
  // missing). Needs a current GL context.
  SceneView(const sim::Scene& scene, const sim::SceneVisuals& visuals, MeshLibrary& meshes);
  ~SceneView();

  // Draws into the bound framebuffer of size width x height, with `arrows`
  // over the bodies (never hidden inside a panel).
  void draw(const std::vector<sim::Pose>& poses, const Camera& camera, int width, int height,
            const std::vector<LoadArrow>& arrows = {}) const;

  // Flexible bodies drawn bent as at q, their displacements times
  // `exaggeration` (until the next call; rigid bodies are unaffected).
  void deform(const sim::Model& model, const double* q, double exaggeration);

  // Stations along a flexible beam at which its drawn bending is given.
  static constexpr int kBendStations = 65;

  // The base-frame bounds of everything drawn at these poses.
  Eigen::AlignedBox3f bounds(const std::vector<sim::Pose>& poses) const;

 private:
  struct Item {
    int body = sim::kBase;  // whose pose places it (kBase: body 0)
    const MeshModel* mesh = nullptr;
    Eigen::Affine3f local;      // mesh units -> body frame
  };

  Eigen::Affine3f placement(const Item& item, const std::vector<sim::Pose>& poses) const;
  void add_pins(const sim::Scene& scene, const sim::SceneVisuals& visuals, MeshLibrary& meshes);
  // A mesh placed by T; `colour` replaces its materials' when given.
  void draw_mesh(const MeshModel& mesh, const Eigen::Affine3f& T, const Eigen::Vector3f* colour) const;
  // An element's link (a point spring) as a thin rod between its two points.
  Eigen::Affine3f link_placement(const sim::ElementLink& link, const std::vector<sim::Pose>& poses) const;
  // A bushing: a sleeve at its frame a, along the frame's x axis.
  Eigen::Affine3f sleeve_placement(const sim::ElementLink& link, const std::vector<sim::Pose>& poses) const;

  // A shaft and a head (two stacked heads for a torque), the head's length
  // taken from the shaft when the arrow is short.
  void draw_arrow(const LoadArrow& arrow) const;

  // Stations `spacing` apart along `axis` from `root` (a beam's), in
  // `rows` rows `row_spacing` apart along `across` (a plate's grid; one row
  // for a beam), the first row first.
  struct Bend {
    int count = kBendStations, rows = 1;
    float spacing = 0, row_spacing = 0;
    Eigen::Vector3f root = Eigen::Vector3f::Zero(), axis = Eigen::Vector3f::UnitX(), across = Eigen::Vector3f::UnitY();
    std::vector<Eigen::Vector3f> displacement;  // body frame, per station; empty: rigid
    std::vector<Eigen::Vector3f> turn;          // small rotations, likewise
  };
  // The plate's grid of stations: kPlateStations square.
  static constexpr int kPlateStations = 8;
  static void bend_beam(const sim::flexible::FlexibleBody& flexible, const Eigen::VectorXd& eta, double exaggeration,
                        Bend& bend);
  static void bend_plate(const sim::flexible::FlexibleBody& flexible, const Eigen::VectorXd& eta, double exaggeration,
                         Bend& bend);
  // An FE model's nodes resampled on a beam's row or a plate's grid.
  static void bend_fem(const sim::flexible::FlexibleBody& flexible, const Eigen::VectorXd& eta, double exaggeration,
                       Bend& bend);
  // The stations' displacements and turns, times `exaggeration`.
  static void set_bend(const std::vector<Eigen::Matrix<double, 6, 1>>& motions, int count, double exaggeration,
                       Bend& bend);

  std::vector<Item> items_;
  std::vector<Bend> bends_;  // per body
  std::vector<sim::ElementLink> links_;
  const MeshModel* link_mesh_ = nullptr;
  const MeshModel* shaft_mesh_ = nullptr;
  const MeshModel* head_mesh_ = nullptr;
  std::unique_ptr<Shader> shader_, background_;
  unsigned background_vao_ = 0;
};

}  // namespace unfurl::render
