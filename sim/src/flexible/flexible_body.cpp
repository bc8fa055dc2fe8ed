#include "unfurl/sim/flexible/flexible_body.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "unfurl/sim/flexible/mass_points.hpp"
#include "unfurl/sim/flexible/modal_body.hpp"
#include "unfurl/sim/flexible/plate_point.hpp"

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

// Refuses more elastic coordinates than the sweep's fixed-size blocks hold.
void check_coordinates(const ModalBody& reduced, const std::string& what, const std::string& per_attachment) {
  if (reduced.coordinates() > kMaxModes)
    throw std::invalid_argument(what + ": " + std::to_string(reduced.coordinates()) + " elastic coordinates, more than " +
                                std::to_string(kMaxModes) + " (the normal modes, and " + per_attachment +
                                " where a child's joint, a sensor or an element's point attaches)");
}

// Each coordinate's stiffness omega_k^2 and damping 2 zeta_k omega_k (unit
// modal masses).
void set_modal_stiffness(FlexibleBody& body) { body.stiffness = (2 * M_PI * body.frequency_hz).array().square(); }

void set_modal_terms(FlexibleBody& body, const ModalDamping& damping, const std::string& what) {
  const Eigen::VectorXd omega = 2 * M_PI * body.frequency_hz;
  set_modal_stiffness(body);
  if (!damping.per_coordinate.empty() && static_cast<int>(damping.per_coordinate.size()) != body.modes())
    throw std::invalid_argument(what + ": " + std::to_string(damping.per_coordinate.size()) +
                                " damping ratios given, one for each of its " + std::to_string(body.modes()) +
                                " elastic coordinates expected");
  body.damping.resize(body.modes());
  for (int k = 0; k < body.modes(); ++k) body.damping[k] = 2 * damping.ratio(k, body.frequency_hz[k]) * omega[k];
}

// The body frame's axes of the plate's own (x and y in its plane, z its
// normal): the normal's next axes in cyclic order, then the normal.
Eigen::Matrix3d body_from_plate(int normal) {
  Eigen::Matrix3d R;
  R << Eigen::Vector3d::Unit((normal + 1) % 3), Eigen::Vector3d::Unit((normal + 2) % 3), Eigen::Vector3d::Unit(normal);
  return R;
}

// The mesh nodes along a plate's edge.
std::vector<int> edge_nodes(const PlateSpec& p, PlateEdge edge) {
  std::vector<int> nodes;
  const bool along_x = edge == PlateEdge::y0 || edge == PlateEdge::y1;
  const int n = along_x ? p.elements_x : p.elements_y;
  for (int k = 0; k <= n; ++k) {
    if (edge == PlateEdge::y0) nodes.push_back(k);
    if (edge == PlateEdge::y1) nodes.push_back(k + p.elements_y * (p.elements_x + 1));
    if (edge == PlateEdge::x0) nodes.push_back(k * (p.elements_x + 1));
    if (edge == PlateEdge::x1) nodes.push_back(p.elements_x + k * (p.elements_x + 1));
  }
  return nodes;
}

PlateEdge opposite(PlateEdge e) {
  switch (e) {
    case PlateEdge::x0: return PlateEdge::x1;
    case PlateEdge::x1: return PlateEdge::x0;
    case PlateEdge::y0: return PlateEdge::y1;
    case PlateEdge::y1: return PlateEdge::y0;
  }
  return e;
}

// Whether plate coordinates u lie over the edge's line.
bool over_edge(const PlateSpec& p, PlateEdge edge, const Eigen::Vector3d& u, double tolerance) {
  switch (edge) {
    case PlateEdge::x0: return std::abs(u.x()) <= tolerance;
    case PlateEdge::x1: return std::abs(u.x() - p.length_x) <= tolerance;
    case PlateEdge::y0: return std::abs(u.y()) <= tolerance;
    case PlateEdge::y1: return std::abs(u.y() - p.length_y) <= tolerance;
  }
  return false;
}

double plate_size(const PlateSpec& p) { return std::max(p.length_x, p.length_y); }

// The nodes of an edge that the plate's brackets fasten to its pin: all of
// them without brackets.
std::vector<int> fastened_nodes(const PlateBodySpec& spec, PlateEdge edge) {
  const PlateSpec& p = spec.plate;
  const std::vector<int> nodes = edge_nodes(p, edge);
  if (spec.brackets.empty()) return nodes;
  const bool along_x = edge == PlateEdge::y0 || edge == PlateEdge::y1;
  const double h = along_x ? p.length_x / p.elements_x : p.length_y / p.elements_y;
  const double tolerance = 1e-9 * plate_size(p);
  std::vector<int> out;
  std::vector<bool> used(spec.brackets.size(), false);
  for (std::size_t k = 0; k < nodes.size(); ++k)
    for (std::size_t b = 0; b < spec.brackets.size(); ++b)
      if (k * h >= spec.brackets[b][0] - tolerance && k * h <= spec.brackets[b][1] + tolerance) {
        if (out.empty() || out.back() != nodes[k]) out.push_back(nodes[k]);
        used[b] = true;
      }
  for (std::size_t b = 0; b < spec.brackets.size(); ++b)
    if (!used[b])
      throw std::invalid_argument("flexible plate: the bracket [" + std::to_string(spec.brackets[b][0]) + ", " +
                                  std::to_string(spec.brackets[b][1]) + "] fastens no mesh node (they lie " +
                                  std::to_string(h) + " m apart along the edge): widen it or refine the mesh");
  return out;
}

// Refuses a modal mass or stiffness that is not a symmetric one.
void check_modal_matrices(const FemModel& f) {
  const auto symmetric = [](const Eigen::MatrixXd& A) {
    return (A - A.transpose()).norm() <= 1e-9 * std::max(A.norm(), 1e-300);
  };
  if (!symmetric(f.mass)) throw std::invalid_argument("flexible FE model: its modal mass matrix is not symmetric");
  if (!symmetric(f.stiffness))
    throw std::invalid_argument("flexible FE model: its modal stiffness matrix is not symmetric");
  if (Eigen::LLT<Eigen::MatrixXd>(f.mass).info() != Eigen::Success)
    throw std::invalid_argument("flexible FE model: its modal mass matrix is not positive definite");
}

// The modal mass of the lumped masses, sum m_g Phi_g^T Phi_g + Psi_g^T J_g
// Psi_g over the file's modes: the one the body's inertia invariants sum
// from the same points, so that its kinetic energy is one body's (the
// file's own modal mass, from its consistent masses, would pair with
// couplings the lumped points do not have, and can make the whole
// indefinite).
Eigen::MatrixXd lumped_modal_mass(const std::vector<MassPoint>& points, const Eigen::MatrixXd& shapes) {
  const int m = static_cast<int>(shapes.cols());
  return InertiaInvariants(points, shapes).mass_matrix(Eigen::VectorXd::Zero(m)).bottomRightCorner(m, m);
}

// The coordinates orthonormalized (unit modal masses, ascending
// frequencies): the eigenvectors of the file's modal stiffness and the
// lumped masses' modal mass.
Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> orthonormal_coordinates(const FemModel& f,
                                                                                  const Eigen::MatrixXd& Me) {
  if (Eigen::LLT<Eigen::MatrixXd>(Me).info() != Eigen::Success)
    throw std::invalid_argument("flexible FE model: a combination of its modes moves none of its lumped masses");
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(f.stiffness, Me);
  if (solver.info() != Eigen::Success) throw std::invalid_argument("flexible FE model: its modes do not solve");
  const Eigen::VectorXd& lambda = solver.eigenvalues();
  // A coordinate without stiffness is a rigid motion, which the floating
  // frame already carries: the modes were not held where the frame attaches.
  if (lambda[0] <= 1e-10 * lambda[lambda.size() - 1])
    throw std::invalid_argument("flexible FE model: a combination of its modes has no stiffness (a rigid motion, " +
                                std::to_string(std::sqrt(std::max(lambda[0], 0.0)) / (2 * M_PI)) +
                                " Hz): give modes of the body held where its frame attaches (Craig-Bampton's, the "
                                "inboard hinge's nodes held)");
  return solver;
}

// How many of the orthonormalized coordinates the spec keeps.
int kept_coordinates(const FemBodySpec& spec, const Eigen::VectorXd& frequency_hz) {
  const int available = static_cast<int>(frequency_hz.size());
  int kept = available;
  if (spec.modes_up_to_hz > 0) kept = static_cast<int>((frequency_hz.array() <= spec.modes_up_to_hz).count());
  else if (spec.normal_modes > 0) kept = spec.normal_modes;
  if (kept > available)
    throw std::invalid_argument("flexible FE model: " + std::to_string(kept) + " modes asked, the file has " +
                                std::to_string(available));
  if (kept == 0)
    throw std::invalid_argument("flexible FE model: no mode lies below " + std::to_string(spec.modes_up_to_hz) +
                                " Hz (the lowest is at " + std::to_string(frequency_hz[0]) + " Hz)");
  if (kept > kMaxModes)
    throw std::invalid_argument("flexible FE model: " + std::to_string(kept) + " elastic coordinates, more than " +
                                std::to_string(kMaxModes) + " (keep fewer with `modes`)");
  return kept;
}

// Each node a mass point: its lumped mass moving with its translation, its
// moments of inertia turning with its rotation.
std::vector<MassPoint> lumped_mass_points(const FemModel& f) {
  std::vector<MassPoint> points;
  Eigen::Matrix<double, 3, 6> translation = Eigen::Matrix<double, 3, 6>::Zero(), rotation = translation;
  translation.leftCols<3>().setIdentity();
  rotation.rightCols<3>().setIdentity();
  for (int k = 0; k < f.nodes(); ++k) {
    const Eigen::Matrix<double, 6, 1> m = f.lumped.col(k);  // one mass: read_fem checked
    if (m.isZero()) continue;
    MassPoint p;
    p.m = m[0];
    p.r = f.points.col(k);
    for (int c = 0; c < 6; ++c) p.dofs.push_back(6 * k + c);
    p.N = translation;
    p.J = m.tail<3>().asDiagonal();
    p.R = rotation;
    points.push_back(p);
  }
  return points;
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
      for (int d : beam.dofs_of({node})) interface.push_back(d);
  }
  ModalReduction reduction;
  reduction.frame_dofs = beam.dofs_of({0});
  reduction.interface_dofs = interface;
  reduction.normal_modes = spec.normal_modes;
  reduction.normal_modes_up_to_hz = spec.modes_up_to_hz;
  const ModalBody reduced = reduce(beam, reduction);
  check_coordinates(reduced, "flexible beam", "six for each mesh node");
  FlexibleBody body{
      InertiaInvariants(placed(beam_mass_points(section), R, spec.root), reduced.shape,
                        spec.geometric_stiffening ? placed(beam_shortening(section, reduced.shape), R)
                                                  : std::vector<Shortening>{}),
      reduced.frequency_hz, {}, {}, {}, {}, spec, {}, {}};
  set_modal_terms(body, spec.damping, "flexible beam");
  for (int node : nodes) body.nodes.push_back(placed(beam.nodes[node], reduced.node_shape(beam, node), R, spec.root));
  for (int node = 0; node < static_cast<int>(beam.nodes.size()); ++node)
    body.mesh_nodes.push_back(placed(beam.nodes[node], reduced.node_shape(beam, node), R, spec.root));
  return body;
}

Eigen::Vector3d plate_coordinates(const PlateBodySpec& spec, const Eigen::Vector3d& point) {
  return body_from_plate(spec.normal).transpose() * (point - spec.corner);
}

FlexibleBody plate_body(const PlateBodySpec& spec) {
  if (spec.normal < 0 || spec.normal > 2) throw std::invalid_argument("flexible plate: the normal is x, y or z");
  const PlateSpec& p = spec.plate;
  const Eigen::Matrix3d R = body_from_plate(spec.normal);
  const Structure plate = plate_structure(p);
  for (const auto& [from, to] : spec.brackets) {
    const double edge = spec.root_edge == PlateEdge::y0 || spec.root_edge == PlateEdge::y1 ? p.length_x : p.length_y;
    if (!(from >= 0 && from <= to && to <= edge * (1 + 1e-12)))
      throw std::invalid_argument("flexible plate: a bracket is a span [from, to] along the edge, within its length");
  }
  ModalReduction reduction;
  reduction.frame_dofs = plate.dofs_of(fastened_nodes(spec, spec.root_edge));
  reduction.normal_modes = spec.normal_modes;
  reduction.normal_modes_up_to_hz = spec.modes_up_to_hz;
  // The hinge line, the one edge a plate ties.
  for (PlateEdge edge : spec.hinge_lines)
    if (edge != opposite(spec.root_edge))
      throw std::invalid_argument("flexible plate: a hinge line is the edge opposite the root edge");
  if (!spec.hinge_lines.empty()) reduction.tied_nodes.push_back(fastened_nodes(spec, opposite(spec.root_edge)));
  std::vector<PlatePoint> attachments;
  for (const Eigen::Vector3d& point : spec.attachments) {
    const PlatePoint where = locate(spec, point);
    if (where.on == PlatePoint::On::outside)
      throw std::invalid_argument("flexible plate: an attachment point lies beyond the plate's edges");
    if (where.on == PlatePoint::On::between_nodes)
      throw std::invalid_argument("flexible plate: an attachment point is neither on a hinge line nor over a mesh node");
    attachments.push_back(where);
    if (where.on == PlatePoint::On::node &&
        std::find(reduction.interface_dofs.begin(), reduction.interface_dofs.end(), plate.dof(where.node, 0)) ==
            reduction.interface_dofs.end())
      for (int d : plate.dofs_of({where.node})) reduction.interface_dofs.push_back(d);
  }
  const ModalBody reduced = reduce(plate, reduction);
  check_coordinates(reduced, "flexible plate", "three for each hinge line and four for each mesh node");
  FlexibleBody body{InertiaInvariants(placed(plate_mass_points(p), R, spec.corner), reduced.shape),
                    reduced.frequency_hz, {}, {}, {}, {}, {}, spec, {}};
  set_modal_terms(body, spec.damping, "flexible plate");
  const int m = reduced.coordinates();
  for (const PlatePoint& a : attachments) {
    Eigen::MatrixXd shape = Eigen::MatrixXd::Zero(6, m);  // on the held edge
    if (a.on == PlatePoint::On::node) shape = reduced.node_shape(plate, a.node);
    if (a.on == PlatePoint::On::hinge_line) shape = reduced.tie_shape(plate, reduction.tied_nodes.front(), a.at);
    body.nodes.push_back(placed(a.at, shape, R, spec.corner));
  }
  for (int node = 0; node < static_cast<int>(plate.nodes.size()); ++node)
    body.mesh_nodes.push_back(placed(plate.nodes[node], reduced.node_shape(plate, node), R, spec.corner));
  return body;
}

FlexibleBody fem_body(const FemBodySpec& spec) {
  const FemModel& f = *spec.model;
  check_modal_matrices(f);
  const std::vector<MassPoint> points = lumped_mass_points(f);
  const auto solver = orthonormal_coordinates(f, lumped_modal_mass(points, f.shapes));
  const Eigen::VectorXd all_hz = solver.eigenvalues().cwiseSqrt() / (2 * M_PI);
  const int m = kept_coordinates(spec, all_hz);
  const Eigen::MatrixXd X = solver.eigenvectors().leftCols(m);
  const Eigen::MatrixXd shape = f.shapes * X;
  FlexibleBody body{InertiaInvariants(points, shape), all_hz.head(m), {}, {}, {}, {}, {}, {}, spec};
  if (spec.damping_from_file) {
    if (f.damping.rows() != f.modes())
      throw std::invalid_argument("flexible FE model: its damping is the file's, which has no damping matrix");
    set_modal_stiffness(body);
    body.damping = (X.transpose() * f.damping * X).diagonal();
  } else {
    set_modal_terms(body, spec.damping, "flexible FE model");
  }
  const auto node_shape = [&](int k) -> Eigen::MatrixXd { return shape.middleRows(6 * k, 6); };
  for (const Eigen::Vector3d& point : spec.attachments) {
    if (!f.attaches(point))
      throw std::invalid_argument("flexible FE model: an attachment point is at no node of the model");
    const int k = f.node_at(point);
    if (k >= 0) body.nodes.push_back({f.points.col(k), node_shape(k)});
    else body.nodes.push_back({point, Eigen::MatrixXd::Zero(6, m)});  // the frame's own point
  }
  for (int k = 0; k < f.nodes(); ++k) body.mesh_nodes.push_back({f.points.col(k), node_shape(k)});
  return body;
}

// Each mode shape's translations keep their numbers, so the coordinates
// grow by L (and by sqrt(M) from the unit modal masses the body makes of
// them); rotations, by L less; the matrices carry the masses.
FemBodySpec scaled(const FemBodySpec& spec, double L, double M) {
  FemBodySpec out = spec;
  FemModel f = *spec.model;
  f.points *= L;
  for (int k = 0; k < f.nodes(); ++k) f.shapes.middleRows(6 * k + 3, 3) /= L;
  f.mass *= M;
  f.stiffness *= M;
  f.damping *= M;
  f.lumped.topRows<3>() *= M;
  f.lumped.bottomRows<3>() *= M * L * L;
  out.model = std::make_shared<const FemModel>(std::move(f));
  for (Eigen::Vector3d& a : out.attachments) a *= L;
  return out;
}

PlateBodySpec scaled(const PlateBodySpec& spec, double L, double M) {
  PlateBodySpec out = spec;
  PlateSpec& p = out.plate;
  p.length_x *= L;
  p.length_y *= L;
  p.bending_stiffness *= M * L * L;  // a moment: a force by a length
  p.mass_per_area *= M / (L * L);
  out.youngs_modulus *= M / L;  // a force per area
  out.thickness *= L;
  out.corner *= L;
  for (Eigen::Vector3d& a : out.attachments) a *= L;
  for (auto& bracket : out.brackets)
    for (double& s : bracket) s *= L;
  return out;
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
  const double tolerance = 1e-9 * std::max(size(), point.norm());
  const std::vector<Eigen::Vector3d>& attachments =
      fem ? fem->attachments : plate ? plate->attachments : beam.attachments;
  for (std::size_t a = 0; a < attachments.size(); ++a)
    if ((attachments[a] - point).norm() <= tolerance) return static_cast<int>(a);
  return -1;
}

bool FlexibleBody::on_frame(const Eigen::Vector3d& point) const {
  if (fem) return point.norm() <= 1e-6 * size();  // the held attachment's own point
  if (plate) return locate(*plate, point).on == PlatePoint::On::root_edge;
  return (point - beam.root).norm() <= 1e-9 * size();
}

PlatePoint locate(const PlateBodySpec& spec, const Eigen::Vector3d& point) {
  const PlateSpec& p = spec.plate;
  const Eigen::Vector3d u = plate_coordinates(spec, point);
  const double tolerance = 1e-9 * plate_size(p), hx = p.length_x / p.elements_x, hy = p.length_y / p.elements_y;
  PlatePoint where;
  where.at = Eigen::Vector3d(u.x(), u.y(), 0);
  if (u.x() < -tolerance || u.x() > p.length_x + tolerance || u.y() < -tolerance || u.y() > p.length_y + tolerance)
    return where;
  const auto over_line = [&](PlateEdge e) { return over_edge(p, e, u, tolerance); };
  if (over_line(spec.root_edge)) {
    where.on = PlatePoint::On::root_edge;
  } else if (std::any_of(spec.hinge_lines.begin(), spec.hinge_lines.end(), over_line)) {
    where.on = PlatePoint::On::hinge_line;
  } else {
    const int i = static_cast<int>(std::lround(u.x() / hx)), j = static_cast<int>(std::lround(u.y() / hy));
    const bool over_node = std::abs(u.x() - i * hx) <= tolerance && std::abs(u.y() - j * hy) <= tolerance;
    where.on = over_node ? PlatePoint::On::node : PlatePoint::On::between_nodes;
    if (over_node) {
      where.node = i + j * (p.elements_x + 1);
      where.at = Eigen::Vector3d(i * hx, j * hy, 0);
    }
  }
  return where;
}

double FlexibleBody::size() const {
  if (fem) return fem->model->size();
  return plate ? plate_size(plate->plate) : beam.section.length;
}

double FlexibleBody::largest_deflection(const double* eta) const {
  const Eigen::Map<const Eigen::VectorXd> e(eta, modes());
  double largest = 0;
  for (const FlexibleNode& node : mesh_nodes) largest = std::max(largest, (node.shape.topRows<3>() * e).norm());
  return largest;
}

}  // namespace unfurl::sim::flexible
