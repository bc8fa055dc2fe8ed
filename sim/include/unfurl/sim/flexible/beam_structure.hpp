// A straight beam along its own x-axis (beam_body places it in its body),
// for a yoke, a boom or a panel between its hinge lines:
// Euler-Bernoulli elements (cubic Hermite in bending about y and z, linear
// in stretch and twist), consistent masses, six degrees of freedom at each
// node (u_x, u_y, u_z, theta_x, theta_y, theta_z), nodes from x = 0.
// Shear deformation is left out: it matters where the section's depth is
// not small against a bending half-wave, which is not a deploying boom's
// first modes.
#pragma once

#include <functional>
#include <vector>

#include "unfurl/sim/flexible/structure.hpp"

namespace unfurl::sim::flexible {

struct BeamSection {
  double length = 1;               // m
  double axial_stiffness = 1;      // EA, N
  double bending_stiffness_y = 1;  // EI_y, N m^2: bending in the xz-plane
  double bending_stiffness_z = 1;  // EI_z, N m^2: bending in the xy-plane
  double torsional_stiffness = 1;  // GJ, N m^2
  double mass_per_length = 1;      // rho A, kg/m
  double polar_inertia_per_length = 1;  // rho (I_y + I_z), kg m: the twist's inertia
  int elements = 8;
};

enum BeamDof { beam_u_x = 0, beam_u_y, beam_u_z, beam_theta_x, beam_theta_y, beam_theta_z };

Structure beam_structure(const BeamSection& section);

// The geometric stiffness of an axial force N(x) along the beam (tension
// positive, N): the second-order work (1/2) N (v'^2 + w'^2) of the bending
// slopes, the stiffening a spinning beam's centrifugal tension gives it
// (Kane, Ryan and Banerjee, 1987). Exact for N up to cubic in x.
Eigen::MatrixXd geometric_stiffness(const BeamSection& section, const std::function<double(double)>& axial_force);

}  // namespace unfurl::sim::flexible
