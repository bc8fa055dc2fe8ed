// The natural modes of a structure with some degrees of freedom held:
// K phi = omega^2 M phi on the others, a dense generalized symmetric
// eigenproblem (Eigen's GeneralizedSelfAdjointEigenSolver; a structure of
// a few thousand degrees of freedom takes seconds, which is a panel's
// mesh, not a spacecraft's).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "unfurl/sim/flexible/structure.hpp"

namespace unfurl::sim::flexible {

struct StructuralModes {
  Eigen::VectorXd frequency_hz;  // ascending
  // One column per mode over all the structure's degrees of freedom,
  // mass-normalized (phi^T M phi = 1), zero on the held ones.
  Eigen::MatrixXd shape;
  // The leading modes that are rigid motions (what the holds leave free),
  // counted from the structure's rigid-motion fields, not from omega^2.
  int rigid = 0;
};

// Throws std::invalid_argument when M is not positive definite on the free
// degrees of freedom (a massless rotation, say).
StructuralModes structural_modes(const Structure& structure, const std::vector<int>& held);

}  // namespace unfurl::sim::flexible
