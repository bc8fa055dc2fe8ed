// The frame a point where an element pushes rides on (docs/FLEXIBLE.md):
// a rigid body's own frame; on a flexible body, the frame of the node the
// point sits at (or beside, on a rigid bracket), so that the point moves
// with the deformation and its force reaches the elastic coordinates
// through the node's shape, N_a^T f, as a child's joint does. On the base:
// the base frame, fixed or moving with the base's velocity.
#pragma once

#include <string>

#include "unfurl/sim/force_element.hpp"

namespace unfurl::sim {

struct PointFrame {
  int body = kBase, node = -1;
  Pose pose;              // the frame's, in the base frame
  Vec6 v = Vec6::Zero();  // its velocity, in its own axes
  Vec3 r = Vec3::Zero();  // the point, in the frame

  // The point and its velocity, the frame's axes and angular velocity, in
  // the base frame.
  Vec3 position() const { return body == kBase ? r : pose.to_base(r); }
  Vec3 velocity() const {
    return body == kBase ? Vec3(v.head<3>() + v.tail<3>().cross(r))
                         : Vec3(pose.rotation.transpose() * (v.head<3>() + v.tail<3>().cross(r)));
  }
  Mat3 to_base() const { return body == kBase ? Mat3::Identity() : Mat3(pose.rotation.transpose()); }
  Vec3 angular_velocity() const { return body == kBase ? Vec3(v.tail<3>()) : Vec3(to_base() * v.tail<3>()); }
};

// Where `point` (the body's frame, undeformed) of `body` is at the state.
// Reads the poses and velocities (the element needs_poses()).
PointFrame point_frame(const ElementState& s, int body, const Vec3& point);

// Adds a wrench about the frame's origin, in its axes, to what the body
// feels: a rigid body's wrench at its origin, or on a flexible body its
// frame's share and its elastic coordinates' forces.
void add_frame_wrench(const ElementState& s, int body, int node, const Vec6& wrench, ElementForces& out);

// A force (base frame) at the frame's point.
void add_point_force(const ElementState& s, const PointFrame& at, const Vec3& f_base, ElementForces& out);
// A force and a moment (base frame) at the frame's point.
void add_point_wrench(const ElementState& s, const PointFrame& at, const Vec3& f_base, const Vec3& m_base,
                      ElementForces& out);

// On a flexible body, the node `point` rides on (-1 on a rigid body, the
// base, or a flexible body's root, which is held to its frame). Throws
// SceneInvalid at `field` when a flexible body has no node there (the
// scene reader makes one at every point an element names).
int node_of_point(const Scene& scene, int body, const Vec3& point, const std::string& field);

}  // namespace unfurl::sim
