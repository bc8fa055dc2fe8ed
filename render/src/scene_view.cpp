#include "unfurl/render/scene_view.hpp"

#include "gl.hpp"
#include "node_resampling.hpp"
#include "shader.hpp"
#include "unfurl/sim/flexible/flexible_body.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

namespace unfurl::render {

namespace {

const char* kVertex = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
uniform mat4 model;
uniform mat4 view_projection;
uniform mat3 normal_matrix;
// A flexible body's mesh bends: each vertex moves with the section at its
// station along the axis (bend_axis from bend_root, body frame), by its
// displacement and small rotation interpolated between stations
// bend_spacing apart; a plate's stations are a grid, bend_rows rows
// bend_row_spacing apart along bend_across, interpolated in both.
uniform int bend_count;
uniform int bend_rows;
uniform float bend_spacing;
uniform float bend_row_spacing;
uniform vec3 bend_root;
uniform vec3 bend_axis;
uniform vec3 bend_across;
uniform mat4 body_from_mesh;
uniform mat4 world_from_body;
uniform vec3 bend[BEND_STATIONS];
uniform vec3 bend_turn[BEND_STATIONS];
out vec3 world_normal;
out vec3 world_position;
void main() {
  vec4 p = model * vec4(position, 1.0);
  world_normal = normal_matrix * normal;
  if (bend_count > 1) {
    vec4 b = body_from_mesh * vec4(position, 1.0);
    float along = dot(b.xyz - bend_root, bend_axis);
    float s = clamp(along / bend_spacing, 0.0, float(bend_count - 1));
    int k = min(int(s), bend_count - 2);
    float across = 0.0, t = 0.0;
    int r = 0, r1 = 0;
    if (bend_rows > 1) {
      across = dot(b.xyz - bend_root, bend_across);
      t = clamp(across / bend_row_spacing, 0.0, float(bend_rows - 1));
      r = min(int(t), bend_rows - 2);
      r1 = r + 1;
    }
    int a0 = r * bend_count + k, a1 = r1 * bend_count + k;
    float f = s - float(k), g = t - float(r);
    vec3 turn = mix(mix(bend_turn[a0], bend_turn[a0 + 1], f), mix(bend_turn[a1], bend_turn[a1 + 1], f), g);
    vec3 arm = b.xyz - (bend_root + along * bend_axis + across * bend_across);
    b.xyz += mix(mix(bend[a0], bend[a0 + 1], f), mix(bend[a1], bend[a1 + 1], f), g) + cross(turn, arm);
    p = world_from_body * b;
    mat3 turn_world = mat3(world_from_body);
    world_normal += turn_world * cross(turn, transpose(turn_world) * world_normal);
  }
  world_position = p.xyz;
  gl_Position = view_projection * p;
}
)";

// A sun (directional, warm white) with a sky/ground ambient, a soft
// specular highlight, and a dim light from the eye on what the sun leaves
// dark (a view from below would otherwise show ambient only).
const char* kFragment = R"(#version 330 core
in vec3 world_normal;
in vec3 world_position;
uniform vec3 color;
uniform vec3 sun_direction;
uniform vec3 eye;
out vec4 fragment;
void main() {
  vec3 n = normalize(world_normal);
  vec3 v = normalize(eye - world_position);
  if (dot(n, v) < 0.0) n = -n;
  float sun = max(dot(n, sun_direction), 0.0);
  vec3 h = normalize(sun_direction + v);
  float specular = pow(max(dot(n, h), 0.0), 48.0) * step(0.0, dot(n, sun_direction));
  vec3 ambient = mix(vec3(0.16, 0.15, 0.14), vec3(0.30, 0.33, 0.40), 0.5 + 0.5 * n.z);
  float fill = 0.35 * max(dot(n, v), 0.0) * (1.0 - sun);
  vec3 lit = color * (ambient + 0.85 * sun * vec3(1.0, 0.97, 0.92) + fill) + 0.35 * specular * vec3(1.0);
  fragment = vec4(pow(lit, vec3(1.0 / 1.1)), 1.0);
}
)";

const char* kBackgroundVertex = R"(#version 330 core
out float height;
void main() {
  vec2 corners[3] = vec2[3](vec2(-1.0, -1.0), vec2(3.0, -1.0), vec2(-1.0, 3.0));
  gl_Position = vec4(corners[gl_VertexID], 0.0, 1.0);
  height = 0.5 * (corners[gl_VertexID].y + 1.0);
}
)";

const char* kBackgroundFragment = R"(#version 330 core
in float height;
out vec4 fragment;
void main() {
  vec3 bottom = vec3(0.30, 0.34, 0.42);
  vec3 top = vec3(0.02, 0.03, 0.08);
  fragment = vec4(mix(bottom, top, smoothstep(0.0, 1.0, height)), 1.0);
}
)";

constexpr float kPinRadius = 0.008f, kPinLength = 0.05f;
constexpr float kLinkRadius = 0.006f;

Eigen::Affine3f pose_transform(const sim::Pose& pose) {
  Eigen::Affine3f T = Eigen::Affine3f::Identity();
  T.linear() = pose.rotation.transpose().cast<float>();
  T.translation() = pose.position.cast<float>();
  return T;
}

Eigen::Affine3f visual_transform(const sim::Visual& v) {
  Eigen::Affine3f T = Eigen::Affine3f::Identity();
  T.translate(v.offset.cast<float>());
  if (v.rotation_deg != 0)
    T.rotate(Eigen::AngleAxisf(static_cast<float>(v.rotation_deg * M_PI / 180), v.rotation_axis.cast<float>()));
  T.scale(v.scale.cast<float>());
  return T;
}

std::string vertex_shader() {
  std::string text = kVertex;
  const std::string key = "BEND_STATIONS";
  for (std::size_t at = text.find(key); at != std::string::npos; at = text.find(key))
    text.replace(at, key.size(), std::to_string(SceneView::kBendStations));
  return text;
}

}  // namespace

SceneView::SceneView(const sim::Scene& scene, const sim::SceneVisuals& visuals, MeshLibrary& meshes)
    : shader_(std::make_unique<Shader>(vertex_shader().c_str(), kFragment)),
      background_(std::make_unique<Shader>(kBackgroundVertex, kBackgroundFragment)) {
  glGenVertexArrays(1, &background_vao_);
  std::set<int> images;
  for (const sim::Loop& loop : scene.loops) images.insert(loop.image);
  if (!visuals.base.mesh.empty())
    items_.push_back({sim::kBase, &meshes.get(visuals.base.mesh), visual_transform(visuals.base)});
  for (int i = 0; i < scene.model.size(); ++i) {
    const sim::Visual& v = visuals.bodies[i];
    if (v.mesh.empty() || images.count(i)) continue;
    items_.push_back({i, &meshes.get(v.mesh), visual_transform(v)});
  }
  add_pins(scene, visuals, meshes);
  bends_.resize(scene.model.size());
  for (const auto& element : scene.elements)
    for (const sim::ElementLink& link : element->links()) links_.push_back(link);
  if (!links_.empty()) link_mesh_ = &meshes.get("pin");
  shaft_mesh_ = &meshes.get("pin");
  head_mesh_ = &meshes.get("cone");
}

SceneView::~SceneView() = default;

void SceneView::deform(const sim::Model& model, const double* q, double exaggeration) {
  for (int i = 0; i < model.size(); ++i) {
    const auto& flexible = model.bodies[i].flexible;
    if (!flexible) continue;
    const Eigen::VectorXd eta = Eigen::Map<const Eigen::VectorXd>(q + model.first_elastic_position[i], flexible->modes());
    if (flexible->fem)
      bend_fem(*flexible, eta, exaggeration, bends_[i]);
    else if (flexible->plate)
      bend_plate(*flexible, eta, exaggeration, bends_[i]);
    else
      bend_beam(*flexible, eta, exaggeration, bends_[i]);
  }
}

void SceneView::bend_beam(const sim::flexible::FlexibleBody& flexible, const Eigen::VectorXd& eta, double exaggeration,
                          Bend& bend) {
  const std::vector<sim::flexible::FlexibleNode>& nodes = flexible.mesh_nodes;
  const double length = flexible.station(nodes.back().point);
  bend.rows = 1;
  bend.spacing = static_cast<float>(length / (kBendStations - 1));
  bend.root = flexible.beam.root.cast<float>();
  bend.axis = flexible.axis().cast<float>();
  std::vector<StationMotion> stations;
  for (const sim::flexible::FlexibleNode& node : nodes) stations.push_back({flexible.station(node.point), node.shape * eta});
  set_bend(resample_along(stations, 0, length, kBendStations), kBendStations, exaggeration, bend);
}

void SceneView::bend_plate(const sim::flexible::FlexibleBody& flexible, const Eigen::VectorXd& eta,
                           double exaggeration, Bend& bend) {
  static_assert(kPlateStations * kPlateStations <= kBendStations, "the plate's grid fits the shader's stations");
  const sim::flexible::PlateBodySpec& spec = *flexible.plate;
  const sim::flexible::PlateSpec& p = spec.plate;
  const std::vector<sim::flexible::FlexibleNode>& nodes = flexible.mesh_nodes;
  const int n = kPlateStations;
  bend.count = bend.rows = n;
  bend.spacing = static_cast<float>(p.length_x / (n - 1));
  bend.row_spacing = static_cast<float>(p.length_y / (n - 1));
  bend.root = spec.corner.cast<float>();
  bend.axis = Eigen::Vector3f::Unit((spec.normal + 1) % 3);
  bend.across = Eigen::Vector3f::Unit((spec.normal + 2) % 3);
  bend.displacement.resize(n * n);
  bend.turn.resize(n * n);
  // The mesh nodes' motions, resampled on the grid (bilinear in each
  // element).
  const auto cell = [](double x, int elements, int& e) {
    e = std::min(static_cast<int>(x * elements), elements - 1);
    return x * elements - e;
  };
  for (int r = 0; r < n; ++r)
    for (int k = 0; k < n; ++k) {
      int ex = 0, ey = 0;
      const double f = cell(static_cast<double>(k) / (n - 1), p.elements_x, ex);
      const double g = cell(static_cast<double>(r) / (n - 1), p.elements_y, ey);
      const auto u = [&](int i, int j) -> Eigen::Matrix<double, 6, 1> {
        return nodes[(ex + i) + (ey + j) * (p.elements_x + 1)].shape * eta;
      };
      const Eigen::Matrix<double, 6, 1> w =
          (1 - g) * ((1 - f) * u(0, 0) + f * u(1, 0)) + g * ((1 - f) * u(0, 1) + f * u(1, 1));
      bend.displacement[r * n + k] = (exaggeration * w.head<3>()).cast<float>();
      bend.turn[r * n + k] = (exaggeration * w.tail<3>()).cast<float>();
    }
}

void SceneView::bend_fem(const sim::flexible::FlexibleBody& flexible, const Eigen::VectorXd& eta, double exaggeration,
                         Bend& bend) {
  Eigen::AlignedBox3d box;
  for (const sim::flexible::FlexibleNode& node : flexible.mesh_nodes) box.extend(node.point);
  // Along the nodes' two largest extents: one row along a boom, a grid
  // over a panel; a model without extent is drawn unbent.
  const Eigen::Vector3d extent = box.sizes();
  int a = 0;
  extent.maxCoeff(&a);
  const int b = extent[(a + 1) % 3] >= extent[(a + 2) % 3] ? (a + 1) % 3 : (a + 2) % 3;
  if (!(extent[a] > 0)) {
    bend.displacement.clear();
    bend.turn.clear();
    return;
  }
  const bool boom = extent[b] < 0.05 * extent[a];
  const int n = boom ? kBendStations : kPlateStations;
  bend.rows = boom ? 1 : kPlateStations;
  bend.spacing = static_cast<float>(extent[a] / (n - 1));
  bend.row_spacing = boom ? 0.0f : static_cast<float>(extent[b] / (n - 1));
  bend.root = box.min().cast<float>();
  bend.axis = Eigen::Vector3f::Unit(a);
  bend.across = Eigen::Vector3f::Unit(b);
  if (boom) {
    std::vector<StationMotion> stations;
    for (const sim::flexible::FlexibleNode& node : flexible.mesh_nodes)
      stations.push_back({node.point[a], node.shape * eta});
    set_bend(resample_along(stations, box.min()[a], extent[a], n), n, exaggeration, bend);
  } else {
    std::vector<ScatteredMotion> nodes;
    for (const sim::flexible::FlexibleNode& node : flexible.mesh_nodes)
      nodes.push_back({Eigen::Vector2d(node.point[a], node.point[b]), node.shape * eta});
    set_bend(resample_over(nodes, Eigen::Vector2d(box.min()[a], box.min()[b]), Eigen::Vector2d(extent[a], extent[b]), n),
             n, exaggeration, bend);
  }
}

void SceneView::set_bend(const std::vector<NodeMotion>& motions, int count, double exaggeration, Bend& bend) {
  bend.count = count;
  bend.displacement.resize(motions.size());
  bend.turn.resize(motions.size());
  for (std::size_t k = 0; k < motions.size(); ++k) {
    bend.displacement[k] = (exaggeration * motions[k].head<3>()).cast<float>();
    bend.turn[k] = (exaggeration * motions[k].tail<3>()).cast<float>();
  }
}

void SceneView::add_pins(const sim::Scene& scene, const sim::SceneVisuals& visuals, MeshLibrary& meshes) {
  // Two short pins near the ends of a hinge line as wide as the child's
  // mesh; one pin where the child is not drawn (a cross pivot to an image).
  const MeshModel& pin = meshes.get("pin");
  std::set<int> images;
  for (const sim::Loop& loop : scene.loops) images.insert(loop.image);
  for (int i = 0; i < scene.model.size(); ++i) {
    const sim::Joint& joint = scene.model.joints[i];
    if (joint.type != sim::JointType::revolute) continue;
    const Eigen::Vector3f axis = joint.axis.cast<float>();
    const Eigen::Quaternionf turn = Eigen::Quaternionf::FromTwoVectors(Eigen::Vector3f::UnitZ(), axis);
    std::vector<float> stations{0.0f};
    const sim::Visual& v = visuals.bodies[i];
    if (!v.mesh.empty() && !images.count(i)) {
      const Eigen::Vector3f size = meshes.get(v.mesh).bounds.sizes().cwiseProduct(v.scale.cast<float>());
      const float width = size.dot(axis.cwiseAbs());
      if (width > 8 * kPinLength) stations = {-0.4f * width, 0.4f * width};
    }
    for (float s : stations) {
      Eigen::Affine3f T = Eigen::Affine3f::Identity();
      T.translate(joint.parent_point.cast<float>() + s * axis);
      T.rotate(turn);
      T.scale(Eigen::Vector3f(2 * kPinRadius, 2 * kPinRadius, kPinLength));
      items_.push_back({scene.model.parent[i], &pin, T});
    }
  }
}

Eigen::Affine3f SceneView::placement(const Item& item, const std::vector<sim::Pose>& poses) const {
  return (item.body == sim::kBase ? Eigen::Affine3f::Identity() : pose_transform(poses[item.body])) * item.local;
}

Eigen::AlignedBox3f SceneView::bounds(const std::vector<sim::Pose>& poses) const {
  Eigen::AlignedBox3f box;
  for (const Item& item : items_) {
    const Eigen::Affine3f T = placement(item, poses);
    for (int corner = 0; corner < 8; ++corner)
      box.extend(T * item.mesh->bounds.corner(static_cast<Eigen::AlignedBox3f::CornerType>(corner)));
  }
  return box;
}

void SceneView::draw(const std::vector<sim::Pose>& poses, const Camera& camera, int width, int height,
                     const std::vector<LoadArrow>& arrows) const {
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  background_->use();
  glBindVertexArray(background_vao_);
  glDrawArrays(GL_TRIANGLES, 0, 3);

  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  shader_->use();
  const Eigen::Matrix4f view_projection = camera.projection(static_cast<float>(width) / height) * camera.view();
  glUniformMatrix4fv(shader_->uniform("view_projection"), 1, GL_FALSE, view_projection.data());
  const Eigen::Vector3f sun = Eigen::Vector3f(0.35f, -0.45f, 0.82f).normalized();
  glUniform3fv(shader_->uniform("sun_direction"), 1, sun.data());
  const Eigen::Vector3f eye = camera.eye();
  glUniform3fv(shader_->uniform("eye"), 1, eye.data());
  for (const Item& item : items_) {
    const Bend* bend = item.body == sim::kBase || bends_[item.body].displacement.empty() ? nullptr : &bends_[item.body];
    if (bend) {
      const Eigen::Affine3f body = pose_transform(poses[item.body]);
      glUniformMatrix4fv(shader_->uniform("body_from_mesh"), 1, GL_FALSE, item.local.matrix().data());
      glUniformMatrix4fv(shader_->uniform("world_from_body"), 1, GL_FALSE, body.matrix().data());
      glUniform1f(shader_->uniform("bend_spacing"), bend->spacing);
      glUniform1f(shader_->uniform("bend_row_spacing"), bend->row_spacing);
      glUniform1i(shader_->uniform("bend_rows"), bend->rows);
      glUniform3fv(shader_->uniform("bend_root"), 1, bend->root.data());
      glUniform3fv(shader_->uniform("bend_axis"), 1, bend->axis.data());
      glUniform3fv(shader_->uniform("bend_across"), 1, bend->across.data());
      const int stations = static_cast<int>(bend->displacement.size());
      glUniform3fv(shader_->uniform("bend"), stations, bend->displacement.front().data());
      glUniform3fv(shader_->uniform("bend_turn"), stations, bend->turn.front().data());
    }
    glUniform1i(shader_->uniform("bend_count"), bend ? bend->count : 0);
    draw_mesh(*item.mesh, placement(item, poses), nullptr);
  }
  glUniform1i(shader_->uniform("bend_count"), 0);
  // Springs orange, cables pale grey, bushings teal.
  const Eigen::Vector3f spring(0.95f, 0.55f, 0.15f), cable(0.85f, 0.85f, 0.8f), bushing(0.15f, 0.7f, 0.7f);
  for (const sim::ElementLink& link : links_) {
    const bool sleeve = link.style == sim::ElementLink::Style::bushing;
    draw_mesh(*link_mesh_, sleeve ? sleeve_placement(link, poses) : link_placement(link, poses),
              sleeve ? &bushing : link.style == sim::ElementLink::Style::cable ? &cable : &spring);
  }
  if (!arrows.empty()) {
    glClear(GL_DEPTH_BUFFER_BIT);
    for (const LoadArrow& arrow : arrows) draw_arrow(arrow);
  }
  glBindVertexArray(0);
}

void SceneView::draw_arrow(const LoadArrow& arrow) const {
  // Forces green, torques violet (hues no built-in mesh or element has),
  // forces rigid mechanics leaves undetermined grey.
  static const Eigen::Vector3f kForce(0.2f, 0.88f, 0.3f), kTorque(0.72f, 0.35f, 0.98f), kGrey(0.62f, 0.62f, 0.62f);
  const Eigen::Vector3f& colour = arrow.kind == LoadArrow::Kind::force ? kForce
                                  : arrow.kind == LoadArrow::Kind::torque ? kTorque
                                                                          : kGrey;
  const float length = arrow.vector.norm();
  if (!(length > 0) || !(arrow.radius > 0)) return;
  const Eigen::Vector3f u = arrow.vector / length;
  const Eigen::Quaternionf turn = Eigen::Quaternionf::FromTwoVectors(Eigen::Vector3f::UnitZ(), u);
  const int heads = arrow.kind == LoadArrow::Kind::torque ? 2 : 1;
  const float head = std::min(5 * arrow.radius, length / (heads + 1));
  const float shaft = length - heads * head;
  Eigen::Affine3f T = Eigen::Affine3f::Identity();
  T.translate(arrow.from + 0.5f * shaft * u);
  T.rotate(turn);
  T.scale(Eigen::Vector3f(2 * arrow.radius, 2 * arrow.radius, shaft));
  draw_mesh(*shaft_mesh_, T, &colour);
  for (int k = 0; k < heads; ++k) {
    Eigen::Affine3f H = Eigen::Affine3f::Identity();
    H.translate(arrow.from + (shaft + k * head) * u);
    H.rotate(turn);
    H.scale(Eigen::Vector3f(5 * arrow.radius, 5 * arrow.radius, head));
    draw_mesh(*head_mesh_, H, &colour);
  }
}

void SceneView::draw_mesh(const MeshModel& mesh, const Eigen::Affine3f& T, const Eigen::Vector3f* colour) const {
  const Eigen::Matrix4f model = T.matrix();
  const Eigen::Matrix3f normal = T.linear().inverse().transpose();
  glUniformMatrix4fv(shader_->uniform("model"), 1, GL_FALSE, model.data());
  glUniformMatrix3fv(shader_->uniform("normal_matrix"), 1, GL_FALSE, normal.data());
  for (const MeshPart& part : mesh.parts) {
    glUniform3fv(shader_->uniform("color"), 1, colour ? colour->data() : part.color.data());
    glBindVertexArray(part.vao);
    glDrawElements(GL_TRIANGLES, part.index_count, GL_UNSIGNED_INT, nullptr);
  }
}

Eigen::Affine3f SceneView::link_placement(const sim::ElementLink& link, const std::vector<sim::Pose>& poses) const {
  const auto at = [&](int body, const sim::Vec3& r) { return body == sim::kBase ? r : poses[body].to_base(r); };
  const Eigen::Vector3f a = at(link.body_a, link.point_a).cast<float>(), b = at(link.body_b, link.point_b).cast<float>();
  const float length = std::max((b - a).norm(), 1e-6f);  // a singular scale would spoil the normals
  Eigen::Affine3f T = Eigen::Affine3f::Identity();
  T.translate(0.5f * (a + b));
  if ((b - a).norm() > 0) T.rotate(Eigen::Quaternionf::FromTwoVectors(Eigen::Vector3f::UnitZ(), b - a));
  T.scale(Eigen::Vector3f(2 * kLinkRadius, 2 * kLinkRadius, length));
  return T;
}

Eigen::Affine3f SceneView::sleeve_placement(const sim::ElementLink& link, const std::vector<sim::Pose>& poses) const {
  const bool on_base = link.body_a == sim::kBase;
  const sim::Vec3 at = on_base ? link.point_a : poses[link.body_a].to_base(link.point_a);
  const sim::Vec3 axis = on_base ? link.axis_a : poses[link.body_a].rotation.transpose() * link.axis_a;
  Eigen::Affine3f T = Eigen::Affine3f::Identity();
  T.translate(at.cast<float>());
  T.rotate(Eigen::Quaternionf::FromTwoVectors(Eigen::Vector3f::UnitZ(), axis.cast<float>()));
  T.scale(Eigen::Vector3f(3 * kPinRadius, 3 * kPinRadius, 1.5f * kPinLength));
  return T;
}

}  // namespace unfurl::render
