#include "unfurl/sim/flexible/structural_modes.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <stdexcept>

namespace unfurl::sim::flexible {

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
  const double largest = m ? omega2.cwiseAbs().maxCoeff() : 0.0;
  for (int k = 0; k < m; ++k) {
    // A rigid motion's omega^2 comes out at round-off of the largest
    // (~1e-15 of it); a panel's first bending mode can lie 1e-9 below its
    // in-plane stretching, so the cut sits between the two.
    const bool rigid = omega2[k] < 1e-12 * largest;
    if (rigid) ++modes.rigid;
    modes.frequency_hz[k] = rigid ? 0.0 : std::sqrt(omega2[k]) / (2 * M_PI);
    for (int a = 0; a < m; ++a) modes.shape(free[a], k) = solver.eigenvectors()(a, k);
  }
  return modes;
}

}  // namespace unfurl::sim::flexible
