#include "unfurl/sim/flexible/flexible_body.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "unfurl/sim/flexible/mass_points.hpp"
#include "unfurl/sim/flexible/modal_body.hpp"

namespace unfurl::sim::flexible {

FlexibleBody beam_body(const BeamBodySpec& spec) {
  const BeamSection& section = spec.section;
  const Structure beam = beam_structure(section);
  const double h = section.length / section.elements;
  std::vector<int> nodes, interface;
  for (const Eigen::Vector3d& p : spec.attachments) {
    if (p.tail<2>().norm() > 1e-9 * section.length || p.x() < -0.5 * h || p.x() > section.length + 0.5 * h)
      throw std::invalid_argument("flexible beam: an attachment point lies off the beam's axis");
    const int node = static_cast<int>(std::lround(p.x() / h));
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
                                " elastic coordinates, more than " + std::to_string(kMaxModes));
  FlexibleBody body{InertiaInvariants(beam_mass_points(section), reduced.shape,
                                      spec.geometric_stiffening ? beam_shortening(section, reduced.shape)
                                                                : std::vector<Shortening>{}),
                    reduced.frequency_hz, {}, {}, {}, {}, spec};
  const Eigen::VectorXd omega = 2 * M_PI * reduced.frequency_hz;
  body.stiffness = omega.array().square();
  body.damping = 2 * spec.damping_ratio * omega;
  for (int node : nodes) body.nodes.push_back({beam.nodes[node], reduced.node_shape(beam, node)});
  for (int node = 0; node < static_cast<int>(beam.nodes.size()); ++node)
    body.mesh_nodes.push_back({beam.nodes[node], reduced.node_shape(beam, node)});
  return body;
}

double FlexibleBody::largest_deflection(const double* eta) const {
  const Eigen::Map<const Eigen::VectorXd> e(eta, modes());
  double largest = 0;
  for (const FlexibleNode& node : mesh_nodes) largest = std::max(largest, (node.shape.topRows<3>() * e).norm());
  return largest;
}

}  // namespace unfurl::sim::flexible
