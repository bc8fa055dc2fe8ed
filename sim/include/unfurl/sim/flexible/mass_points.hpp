// A flexible body's mass as quadrature points. The consistent mass
// integrals of the plate and beam meshes are Gauss sums (4 points per
// element direction are exact for them), so the kinetic energy of the
// interpolated continuum is exactly that of point masses m_g at r_g moved
// by N_g u (u the structure's degrees of freedom), plus, for the beam's
// twist, point inertias turned by the interpolated rotation. What the
// floating frame's inertia invariants (inertia_invariants.hpp) are summed
// from.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "unfurl/sim/flexible/beam_structure.hpp"
#include "unfurl/sim/flexible/plate_structure.hpp"

namespace unfurl::sim::flexible {

struct MassPoint {
  double m = 0;                  // kg
  Eigen::Vector3d r;             // undeformed, body frame
  std::vector<int> dofs;         // the structure's degrees of freedom that move it
  Eigen::Matrix<double, 3, Eigen::Dynamic> N;  // its displacement per unit of each, 3 x dofs
  // A point inertia (body axes) and its small rotation per unit of each
  // degree of freedom: the beam's twist; zero for a Kirchhoff plate.
  Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
  Eigen::Matrix<double, 3, Eigen::Dynamic> R;
};

std::vector<MassPoint> plate_mass_points(const PlateSpec& spec);
std::vector<MassPoint> beam_mass_points(const BeamSection& section);

// A mass point's second-order displacement in modal coordinates eta:
// -(1/2) (eta^T G eta) axis, the foreshortening of a bent beam (its point at
// x draws back along the axis by half the integral of the squared slopes
// from the root). It is what gives a spinning beam its centrifugal
// stiffening through the kinetic energy (inertia_invariants.hpp), so the
// stiffening conserves energy, where a geometric stiffness computed from
// the current inertia loads would not.
struct Shortening {
  Eigen::Vector3d axis = Eigen::Vector3d::Zero();
  Eigen::MatrixXd G;  // m x m
};

// For each of beam_mass_points(section), in order: G(x_g) = integral from
// the root (x = 0) to x_g of v'^T v' + w'^T w' for the modes `shape` (the
// structure's degrees of freedom x m), along the beam's axis x. A plate
// has none: its foreshortening is a membrane problem, and its stiffening
// by in-plane inertia loads is negligible at deployment speeds.
std::vector<Shortening> beam_shortening(const BeamSection& section, const Eigen::MatrixXd& shape);

// sum_g m_g N_g^T N_g + R_g^T J_g R_g over the structure's degrees of
// freedom: the consistent mass matrix again (a check that the points hold
// all of it).
Eigen::MatrixXd mass_matrix(const std::vector<MassPoint>& points, int size);

}  // namespace unfurl::sim::flexible
