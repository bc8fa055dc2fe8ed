#include "unfurl/sim/flexible/structural_modes.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace unfurl::sim::flexible {

namespace {

// How many of the structure's rigid motions the holds leave free: those of
// its rigid-motion fields that vanish at every held degree of freedom,
// rank(rigid) - rank(rigid at the held ones). Counted from the geometry,
// not from the eigenvalues: a panel's first bending omega^2 can lie 1e-10
// below its in-plane bending's highest mesh mode, and lower as the mesh
// refines, where no cut on the eigenvalues tells them apart.
int free_rigid_motions(const Structure& structure, const std::vector<int>& held) {
  const int all = static_cast<int>(Eigen::FullPivLU<Eigen::MatrixXd>(structure.rigid).rank());
  if (held.empty()) return all;
  Eigen::MatrixXd at_held(held.size(), structure.rigid.cols());
  for (std::size_t a = 0; a < held.size(); ++a) at_held.row(a) = structure.rigid.row(held[a]);
  return all - static_cast<int>(Eigen::FullPivLU<Eigen::MatrixXd>(at_held).rank());
}

}  // namespace

StructuralModes structural_modes(const Structure& structure, const std::vector<int>& held) {
  const int n = structure.size();
  std::vector<char> is_held(n, 0);
  for (int d : held) is_held.at(d) = 1;
  std::vector<int> free;
  for (int d = 0; d < n; ++d)
    if (!is_held[d]) free.push_back(d);
  const int m = static_cast<int>(free.size());
  Eigen::MatrixXd K(m, m), M(m, m);
  for (int a = 0; a < m; ++a)
    for (int b = 0; b < m; ++b) K(a, b) = structure.K(free[a], free[b]), M(a, b) = structure.M(free[a], free[b]);

  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(K, M);
  if (solver.info() != Eigen::Success)
    throw std::invalid_argument("structural modes: the mass matrix is not positive definite on the free degrees of freedom");

  StructuralModes modes;
  const Eigen::VectorXd& omega2 = solver.eigenvalues();
  modes.frequency_hz.resize(m);
  modes.shape.setZero(n, m);
  modes.rigid = std::min(free_rigid_motions(structure, held), m);
  for (int k = 0; k < m; ++k) {
    const bool rigid = k < modes.rigid;
    modes.frequency_hz[k] = rigid ? 0.0 : std::sqrt(omega2[k]) / (2 * M_PI);
    for (int a = 0; a < m; ++a) modes.shape(free[a], k) = solver.eigenvectors()(a, k);
  }
  return modes;
}

}  // namespace unfurl::sim::flexible
