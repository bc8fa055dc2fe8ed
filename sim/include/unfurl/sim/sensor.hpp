// Sensors: what a point on a body does, at every step the integrator takes,
// computed from the sweep's exact accelerations (not by differencing
// samples): its position, velocity and acceleration, and its body's angular
// rate and angular acceleration, in the body's frame or the inertial one.
// The acceleration is the point's kinematic acceleration (what an
// accelerometer reads less gravity's field, which a spacecraft in orbit
// does not feel); its peak is also given in g (9.80665 m/s^2), the unit a
// latch-up shock is specified in.
//
// "Inertial" is the base's frame: the inertial frame unless the scene gives
// the base a steady motion (velocity:), when it is the base's frame at
// every instant. Velocities and accelerations are absolute either way.
#pragma once

#include <string>
#include <vector>

#include "unfurl/sim/kinematics.hpp"
#include "unfurl/sim/loads.hpp"

namespace unfurl::sim {

enum class SensorQuantity { position, velocity, acceleration, angular_rate, angular_acceleration };
enum class SensorFrame { body, inertial };

const char* sensor_quantity_name(SensorQuantity q);  // "acceleration"
const char* sensor_quantity_unit(SensorQuantity q);  // "m/s^2"
const char* sensor_frame_name(SensorFrame f);        // "body", "inertial"

inline constexpr double kStandardGravity = 9.80665;  // m/s^2 in one g

struct Sensor {
  std::string name;
  int body = 0;
  Vec3 point = Vec3::Zero();  // body frame
  // On a flexible body: the node it sits at (validate() finds it; the
  // reader makes every sensor's point on a flexible body a node). It then
  // moves and turns with the body's deformation: its "body" frame is the
  // node's deformed frame, as an accelerometer mounted there sees it.
  int node = -1;
  SensorFrame frame = SensorFrame::body;
  std::vector<SensorQuantity> measures{SensorQuantity::acceleration};

  // Its columns in sensors.csv: NAME.QUANTITY.x, .y, .z per measure.
  std::vector<LoadColumn> columns() const;
  // Its readings (three per measure, in columns() order) from its body's
  // pose, velocity v and acceleration a (the rate of v in its own frame,
  // Sweep::accelerations).
  void read(const Pose& pose, const Vec6& v, const Vec6& a, double* out) const {
    read_at(pose, v, a, point, point, out);
  }
  // The same for the point r of the frame placed by pose (moving with v,
  // a); `body_position` is what the body frame's position reads.
  void read_at(const Pose& pose, const Vec6& v, const Vec6& a, const Vec3& r, const Vec3& body_position,
               double* out) const;
  // The peaks a run keeps: the magnitude of each measure but the position.
  std::vector<ElementPeak> peaks() const;
};

// Every sensor's columns, one after the other.
std::vector<LoadColumn> sensor_columns(const std::vector<Sensor>& sensors);

}  // namespace unfurl::sim
