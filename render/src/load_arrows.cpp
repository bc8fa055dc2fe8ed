#include "unfurl/render/load_arrows.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace unfurl::render {

namespace {

// The share of the scene's size the largest load is drawn at, and a
// shaft's radius as a share of it: long enough to read against a panel,
// short enough not to cross the array.
constexpr float kReach = 0.25f, kThickness = 0.006f;

// Joints whose reaction is a hinge's: a free joint transmits nothing.
bool carries_load(const sim::Joint& joint) { return joint.type != sim::JointType::free; }

int latch_column(const sim::Trajectory& trajectory, const sim::Model& model, int joint) {
  return sim::find_load_column(trajectory.load_columns, "latch_torque." + model.joints[joint].name);
}

}  // namespace

LoadArrowScale load_arrow_scale(const sim::Scene& scene, const sim::Trajectory& trajectory, float scene_size,
                                float factor) {
  LoadArrowScale scale;
  scale.reach = kReach * scene_size * factor;
  scale.thickness = kThickness * scene_size;
  const sim::Model& model = scene.model;
  std::vector<int> latch_columns;
  for (const sim::Latch* latch : scene.latches()) {
    const int c = latch_column(trajectory, model, latch->joint);
    if (c >= 0) latch_columns.push_back(c);
  }
  for (const sim::Sample& s : trajectory.samples) {
    for (int j = 0; j < model.size() && j < static_cast<int>(s.loads.reaction.size()); ++j)
      if (carries_load(model.joints[j]))
        scale.peak_force = std::max(scale.peak_force, s.loads.reaction[j].head<3>().norm());
    for (int c : latch_columns) scale.peak_torque = std::max(scale.peak_torque, std::abs(s.loads.element[c]));
  }
  return scale;
}

std::vector<LoadArrow> load_arrows(const sim::Scene& scene, const sim::Trajectory& trajectory,
                                   const sim::Sample& sample, const std::vector<sim::Pose>& poses,
                                   const LoadArrowScale& scale) {
  std::vector<LoadArrow> arrows;
  const sim::Model& model = scene.model;
  const sim::Loads& loads = sample.loads;
  // A load below this share of the largest would be a dot.
  constexpr double kVisible = 0.02;
  if (scale.peak_force > 0 && static_cast<int>(loads.reaction.size()) == model.size()) {
    const LoadArrow::Kind kind = loads.determinacy == sim::Determinacy::indeterminate
                                     ? LoadArrow::Kind::indeterminate_force
                                     : LoadArrow::Kind::force;
    for (int j = 0; j < model.size(); ++j) {
      const sim::Vec3 f = loads.reaction[j].head<3>();  // the child's frame
      if (!carries_load(model.joints[j]) || f.norm() < kVisible * scale.peak_force) continue;
      const sim::Pose& child = poses[j];
      arrows.push_back({kind, child.to_base(model.joints[j].child_point).cast<float>(),
                        (child.rotation.transpose() * f * (scale.reach / scale.peak_force)).cast<float>(),
                        scale.thickness});
    }
  }
  if (scale.peak_torque > 0) {
    for (const sim::Latch* latch : scene.latches()) {
      const int c = latch_column(trajectory, model, latch->joint);
      if (c < 0) continue;
      const double tau = loads.element[c];
      if (std::abs(tau) < kVisible * scale.peak_torque) continue;
      const sim::Joint& joint = model.joints[latch->joint];
      const sim::Pose& child = poses[latch->joint];
      // The hinge axis is the same in the parent's and the child's frames.
      const sim::Vec3 along = child.rotation.transpose() * joint.axis * (tau * scale.reach / scale.peak_torque);
      const LoadArrow::Kind kind =
          joint.type == sim::JointType::revolute ? LoadArrow::Kind::torque : LoadArrow::Kind::force;
      arrows.push_back({kind, child.to_base(joint.child_point).cast<float>(), along.cast<float>(), scale.thickness});
    }
  }
  return arrows;
}

std::string load_arrow_legend(const LoadArrowScale& scale) {
  char text[160];
  if (scale.peak_torque > 0)
    std::snprintf(text, sizeof text, "arrows: hinge force %.3g N (green), latch torque %.3g N m (violet) at full length",
                  scale.peak_force, scale.peak_torque);
  else
    std::snprintf(text, sizeof text, "arrows: hinge force %.3g N at full length", scale.peak_force);
  return text;
}

}  // namespace unfurl::render
