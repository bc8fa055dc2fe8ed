#include "unfurl/sim/flexible/flexible_body.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "unfurl/sim/flexible/mass_points.hpp"
#include "unfurl/sim/flexible/modal_body.hpp"

namespace unfurl::sim::flexible {

namespace {

// The body frame's axes of the beam's own (x along the beam, y and z its
// section's): the next axes in cyclic order.
Eigen::Matrix3d body_from_beam(int axis) {
  Eigen::Matrix3d R;
  for (int c = 0; c < 3; ++c) R.col(c) = Eigen::Vector3d::Unit((axis + c) % 3);
  return R;
}

// The mass points and shortening of a beam built along its own x, turned
// and moved into the body frame.
std::vector<MassPoint> placed(std::vector<MassPoint> points, const Eigen::Matrix3d& R, const Eigen::Vector3d& root) {
  for (MassPoint& p : points) {
    p.r = root + R * p.r;
    p.N = R * p.N;
    p.J = R * p.J * R.transpose();
    if (p.R.size() > 0) p.R = R * p.R;
  }
  return points;
}

std::vector<Shortening> placed(std::vector<Shortening> shortening, const Eigen::Matrix3d& R) {
  for (Shortening& s : shortening) s.axis = R * s.axis;
  return shortening;
}

FlexibleNode placed(const Eigen::Vector3d& point, Eigen::MatrixXd shape, const Eigen::Matrix3d& R,
                    const Eigen::Vector3d& root) {
  shape.topRows<3>() = R * shape.topRows<3>();
  shape.bottomRows<3>() = R * shape.bottomRows<3>();
  return {root + R * point, shape};
}

}  // namespace

FlexibleBody beam_body(const BeamBodySpec& spec) {
  const BeamSection& section = spec.section;
  if (spec.axis < 0 || spec.axis > 2) throw std::invalid_argument("flexible beam: the axis is x, y or z");
  const Eigen::Matrix3d R = body_from_beam(spec.axis);
  const Structure beam = beam_structure(section);
  const double h = section.length / section.elements;
  std::vector<int> nodes, interface;
  for (const Eigen::Vector3d& p : spec.attachments) {
    const double x = R.col(0).dot(p - spec.root);
    if (x < -0.5 * h || x > section.length + 0.5 * h)
      throw std::invalid_argument("flexible beam: an attachment point lies beyond the beam's ends");
    const int node = static_cast<int>(std::lround(x / h));
    nodes.push_back(node);
    if (node == 0) continue;  // the frame's own attachment: held
    bool seen = false;
    for (int d : interface) seen = seen || d == beam.dof(node, 0);
    if (!seen)
      for (int d : node_dofs(beam, node)) interface.push_back(d);
  }
  const ModalBody reduced = reduce(beam, {node_dofs(beam, 0), interface, spec.normal_modes});
  if (reduced.coordinates() > kMaxModes)
    throw std::invalid_argument("flexible beam: " + std::to_string(reduced.coordinates()) +
                                " elastic coordinates, more than " + std::to_string(kMaxModes) +
                                " (the normal modes, and six for each mesh node where a child's joint, a sensor or "
                                "an element's point attaches)");
  FlexibleBody body{
      InertiaInvariants(placed(beam_mass_points(section), R, spec.root), reduced.shape,
                        spec.geometric_stiffening ? placed(beam_shortening(section, reduced.shape), R)
                                                  : std::vector<Shortening>{}),
      reduced.frequency_hz, {}, {}, {}, {}, spec};
  const Eigen::VectorXd omega = 2 * M_PI * reduced.frequency_hz;
  body.stiffness = omega.array().square();
  if (!spec.damping.per_coordinate.empty() && static_cast<int>(spec.damping.per_coordinate.size()) != body.modes())
    throw std::invalid_argument("flexible beam: " + std::to_string(spec.damping.per_coordinate.size()) +
                                " damping ratios given, one for each of its " + std::to_string(body.modes()) +
                                " elastic coordinates expected");
  body.damping.resize(body.modes());
  for (int k = 0; k < body.modes(); ++k) body.damping[k] = 2 * spec.damping.ratio(k, reduced.frequency_hz[k]) * omega[k];
  for (int node : nodes) body.nodes.push_back(placed(beam.nodes[node], reduced.node_shape(beam, node), R, spec.root));
  for (int node = 0; node < static_cast<int>(beam.nodes.size()); ++node)
    body.mesh_nodes.push_back(placed(beam.nodes[node], reduced.node_shape(beam, node), R, spec.root));
  return body;
}

BeamBodySpec scaled(const BeamBodySpec& spec, double L, double M) {
  BeamBodySpec out = spec;
  BeamSection& s = out.section;
  s.length *= L;
  s.axial_stiffness *= M * L;                      // a force
  s.bending_stiffness_y *= M * L * L * L;          // a force by a length squared
  s.bending_stiffness_z *= M * L * L * L;
  s.torsional_stiffness *= M * L * L * L;
  s.mass_per_length *= M / L;
  s.polar_inertia_per_length *= M * L;
  out.root *= L;
  for (Eigen::Vector3d& p : out.attachments) p *= L;
  return out;
}

double ModalDamping::ratio(int k, double f_hz) const {
  if (!per_coordinate.empty()) return per_coordinate.at(k);
  for (const DampingBand& band : bands)
    if (f_hz <= band.up_to_hz) return band.ratio;
  return bands.back().ratio;
}

int FlexibleBody::node_of(const Eigen::Vector3d& point) const {
  const double tolerance = 1e-9 * std::max(beam.section.length, point.norm());
  for (std::size_t a = 0; a < beam.attachments.size(); ++a)
    if ((beam.attachments[a] - point).norm() <= tolerance) return static_cast<int>(a);
  return -1;
}

double FlexibleBody::largest_deflection(const double* eta) const {
  const Eigen::Map<const Eigen::VectorXd> e(eta, modes());
  double largest = 0;
  for (const FlexibleNode& node : mesh_nodes) largest = std::max(largest, (node.shape.topRows<3>() * e).norm());
  return largest;
}

}  // namespace unfurl::sim::flexible
