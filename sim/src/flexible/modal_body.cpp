#include "unfurl/sim/flexible/modal_body.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <cmath>
#include <stdexcept>
#include <string>

#include "unfurl/sim/flexible/structural_modes.hpp"

namespace unfurl::sim::flexible {
namespace {

[[noreturn]] void throw_rigid_motion_free() {
  throw std::invalid_argument("flexible body: the frame's attachment leaves a rigid motion of the body free");
}

// The rows and columns of x at the listed indices.
Eigen::MatrixXd block(const Eigen::MatrixXd& x, const std::vector<int>& rows, const std::vector<int>& cols) {
  Eigen::MatrixXd out(rows.size(), cols.size());
  for (size_t a = 0; a < rows.size(); ++a)
    for (size_t b = 0; b < cols.size(); ++b) out(a, b) = x(rows[a], cols[b]);
  return out;
}

// The interior's stiffness K_II factored, once for every constraint mode;
// singular where the held degrees of freedom leave a rigid motion free.
Eigen::LDLT<Eigen::MatrixXd> interior_stiffness(const Structure& s, const std::vector<int>& interior) {
  const Eigen::LDLT<Eigen::MatrixXd> K_II(block(s.K, interior, interior));
  if (K_II.info() != Eigen::Success || !K_II.isPositive()) throw_rigid_motion_free();
  return K_II;
}

// The constraint modes: for each interface degree of freedom c, the static
// shape with u_c = 1, the other interface and frame ones 0, the interior
// free of load (K_II psi_I = -K_Ic).
Eigen::MatrixXd constraint_modes(const Structure& s, const std::vector<int>& interface,
                                 const std::vector<int>& interior, const Eigen::LDLT<Eigen::MatrixXd>& K_II) {
  if (interface.empty()) return Eigen::MatrixXd::Zero(s.size(), 0);
  const Eigen::MatrixXd psi_I = K_II.solve(-block(s.K, interior, interface));
  if (!psi_I.allFinite()) throw_rigid_motion_free();
  Eigen::MatrixXd psi = Eigen::MatrixXd::Zero(s.size(), interface.size());
  for (size_t c = 0; c < interface.size(); ++c) psi(interface[c], c) = 1;
  for (size_t a = 0; a < interior.size(); ++a) psi.row(interior[a]) = psi_I.row(a);
  return psi;
}

// The rigid motions (columns of s.rigid) the structure models.
std::vector<int> modelled_motions(const Structure& s) {
  std::vector<int> motions;
  for (int j = 0; j < 6; ++j)
    if (s.rigid.col(j).squaredNorm() > 0) motions.push_back(j);
  return motions;
}

// A tied set's constraint modes: for each rigid motion the structure
// models, the static shape with the set moving by it, every other held
// degree of freedom at 0 and the interior free of load.
Eigen::MatrixXd tied_modes(const Structure& s, const std::vector<int>& tied, const std::vector<int>& interior,
                           const Eigen::LDLT<Eigen::MatrixXd>& K_II) {
  const std::vector<int> set = s.dofs_of(tied), motions = modelled_motions(s);
  const Eigen::MatrixXd u_S = block(s.rigid, set, motions);
  const Eigen::MatrixXd psi_I = K_II.solve(-block(s.K, interior, set) * u_S);
  if (!psi_I.allFinite()) throw_rigid_motion_free();
  Eigen::MatrixXd psi = Eigen::MatrixXd::Zero(s.size(), motions.size());
  for (size_t a = 0; a < set.size(); ++a) psi.row(set[a]) = u_S.row(a);
  for (size_t a = 0; a < interior.size(); ++a) psi.row(interior[a]) = psi_I.row(a);
  return psi;
}

}  // namespace

ModalBody reduce(const Structure& s, const ModalReduction& reduction) {
  std::vector<char> role(s.size(), 0);  // 1 frame, 2 interface, 3 tied
  for (int d : reduction.frame_dofs) role.at(d) = 1;
  for (int d : reduction.interface_dofs) role.at(d) = 2;
  // A tie that shares a node with the frame, an interface node or another
  // tie would move it in one's constraint modes and hold it in the other's:
  // neither rigid nor held.
  for (const std::vector<int>& tied : reduction.tied_nodes)
    for (int d : s.dofs_of(tied)) {
      if (role.at(d) != 0)
        throw std::invalid_argument("flexible body: tied nodes share a node with the frame's attachment, an "
                                    "interface node or another tie");
      role[d] = 3;
    }
  std::vector<int> held, interior;
  for (int d = 0; d < s.size(); ++d) (role[d] ? held : interior).push_back(d);

  const StructuralModes fixed = structural_modes(s, held);
  if (fixed.rigid > 0) throw_rigid_motion_free();
  int normal_modes = reduction.normal_modes;
  if (reduction.normal_modes_up_to_hz > 0)
    normal_modes = static_cast<int>((fixed.frequency_hz.array() <= reduction.normal_modes_up_to_hz).count());
  if (fixed.frequency_hz.size() < normal_modes)
    throw std::invalid_argument("flexible body: " + std::to_string(normal_modes) + " modes asked, the mesh has " +
                                std::to_string(fixed.frequency_hz.size()));
  const int tied_columns = static_cast<int>(reduction.tied_nodes.size() * modelled_motions(s).size());
  Eigen::MatrixXd T(s.size(), normal_modes + reduction.interface_dofs.size() + tied_columns);
  T.leftCols(normal_modes) = fixed.shape.leftCols(normal_modes);
  const Eigen::LDLT<Eigen::MatrixXd> K_II = T.cols() > normal_modes ? interior_stiffness(s, interior)
                                                                    : Eigen::LDLT<Eigen::MatrixXd>();
  T.middleCols(normal_modes, reduction.interface_dofs.size()) =
      constraint_modes(s, reduction.interface_dofs, interior, K_II);
  int c = static_cast<int>(T.cols()) - tied_columns;
  for (const std::vector<int>& tied : reduction.tied_nodes) {
    const Eigen::MatrixXd psi = tied_modes(s, tied, interior, K_II);
    T.middleCols(c, psi.cols()) = psi;
    c += static_cast<int>(psi.cols());
  }

  // Orthonormalized: the eigenvectors of the reduced pair, the frame held.
  const Eigen::MatrixXd M_T = s.M * T;
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(T.transpose() * s.K * T,
                                                                         T.transpose() * M_T);
  if (solver.info() != Eigen::Success) throw std::invalid_argument("flexible body: the reduced mass is singular");
  ModalBody body;
  body.shape = T * solver.eigenvectors();
  body.frequency_hz = solver.eigenvalues().cwiseMax(0.0).cwiseSqrt() / (2 * M_PI);
  body.coupling = s.rigid.transpose() * s.M * body.shape;
  return body;
}

Eigen::MatrixXd ModalBody::node_shape(const Structure& structure, int node) const {
  return structure.node_motion * shape.middleRows(structure.dof(node, 0), structure.dofs_per_node);
}

Eigen::MatrixXd ModalBody::tie_shape(const Structure& structure, const std::vector<int>& tied,
                                     const Eigen::Vector3d& point) const {
  const std::vector<int> set = structure.dofs_of(tied), motions = modelled_motions(structure);
  std::vector<int> all(shape.cols());
  for (int k = 0; k < coordinates(); ++k) all[k] = k;
  // The set moves rigidly: its degrees of freedom are the rigid fields'
  // combination c (exactly, so the least-squares fit is exact).
  const Eigen::MatrixXd c_modelled =
      block(structure.rigid, set, motions).colPivHouseholderQr().solve(block(shape, set, all));
  Eigen::MatrixXd c = Eigen::MatrixXd::Zero(6, coordinates());
  for (size_t j = 0; j < motions.size(); ++j) c.row(motions[j]) = c_modelled.row(j);
  Eigen::MatrixXd out(6, coordinates());
  for (int k = 0; k < coordinates(); ++k) {
    const Eigen::Vector3d v = c.col(k).head<3>(), w = c.col(k).tail<3>();
    out.col(k) << v + w.cross(point), w;
  }
  return out;
}

}  // namespace unfurl::sim::flexible
