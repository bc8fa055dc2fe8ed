#include "unfurl/sim/sensor.hpp"

namespace unfurl::sim {

const char* sensor_quantity_name(SensorQuantity q) {
  switch (q) {
    case SensorQuantity::position:
      return "position";
    case SensorQuantity::velocity:
      return "velocity";
    case SensorQuantity::acceleration:
      return "acceleration";
    case SensorQuantity::angular_rate:
      return "angular_rate";
    case SensorQuantity::angular_acceleration:
      return "angular_acceleration";
  }
  return "?";
}

const char* sensor_quantity_unit(SensorQuantity q) {
  switch (q) {
    case SensorQuantity::position:
      return "m";
    case SensorQuantity::velocity:
      return "m/s";
    case SensorQuantity::acceleration:
      return "m/s^2";
    case SensorQuantity::angular_rate:
      return "rad/s";
    case SensorQuantity::angular_acceleration:
      return "rad/s^2";
  }
  return "?";
}

const char* sensor_frame_name(SensorFrame f) { return f == SensorFrame::body ? "body" : "inertial"; }

std::vector<LoadColumn> Sensor::columns() const {
  static const char* axes[] = {"x", "y", "z"};
  std::vector<LoadColumn> out;
  const std::string frame_text = frame == SensorFrame::body ? "body frame" : "inertial frame";
  for (const SensorQuantity q : measures)
    for (const char* axis : axes)
      out.push_back({name + "." + sensor_quantity_name(q) + "." + axis, sensor_quantity_unit(q), frame_text, -1});
  return out;
}

void Sensor::read_at(const Pose& pose, const Vec6& v, const Vec6& a, const Vec3& r, const Vec3& body_position,
                     double* out) const {
  // The frame's v = (velocity of its origin, angular velocity), and a the
  // rate of those components; the point's acceleration adds the frame's
  // turning: a_o + w x v_o + alpha x r + w x (w x r), alpha = the rate of w.
  const Vec3 w = v.tail<3>(), alpha = a.tail<3>();
  const Vec3 velocity = v.head<3>() + w.cross(r);
  const Vec3 acceleration = a.head<3>() + w.cross(v.head<3>()) + alpha.cross(r) + w.cross(w.cross(r));
  const Mat3 to_base = pose.rotation.transpose();
  const bool inertial = frame == SensorFrame::inertial;
  for (const SensorQuantity q : measures) {
    Vec3 x = Vec3::Zero();
    switch (q) {
      case SensorQuantity::position:
        x = inertial ? pose.to_base(r) : body_position;
        break;
      case SensorQuantity::velocity:
        x = inertial ? Vec3(to_base * velocity) : velocity;
        break;
      case SensorQuantity::acceleration:
        x = inertial ? Vec3(to_base * acceleration) : acceleration;
        break;
      case SensorQuantity::angular_rate:
        x = inertial ? Vec3(to_base * w) : w;
        break;
      case SensorQuantity::angular_acceleration:
        x = inertial ? Vec3(to_base * alpha) : alpha;
        break;
    }
    for (int k = 0; k < 3; ++k) *out++ = x[k];
  }
}

std::vector<ElementPeak> Sensor::peaks() const {
  std::vector<ElementPeak> out;
  for (int m = 0; m < static_cast<int>(measures.size()); ++m)
    if (measures[m] != SensorQuantity::position)
      out.push_back({std::string("peak_") + sensor_quantity_name(measures[m]), 3 * m, 3});
  return out;
}

std::vector<LoadColumn> sensor_columns(const std::vector<Sensor>& sensors) {
  std::vector<LoadColumn> out;
  for (const Sensor& s : sensors)
    for (const LoadColumn& c : s.columns()) out.push_back(c);
  return out;
}

}  // namespace unfurl::sim
