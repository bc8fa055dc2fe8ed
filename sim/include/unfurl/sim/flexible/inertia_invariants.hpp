// The floating frame's inertia invariants of a flexible body: its kinetic
// energy T = (1/2) V^T M^(eta) V, V = (v, w, eta') (the frame's velocity,
// linear first, and the elastic rates), as sums over its mass points
// (mass_points.hpp) precomputed once, so that M^(eta) and dT/d eta cost
// O(m^2) an evaluation, whatever the mesh. With rho_g = r_g + Phi_g eta:
//   M^ = [ m E        -S(eta)~   S1          ]   S(eta) = S0 + S1 eta
//        [ S(eta)~     J(eta)    C(eta)      ]   J(eta) = J0 + eta_k J1_k + eta_k eta_l J2_kl
//        [ S1^T        C(eta)^T  Me          ]   C(eta) = C0 + eta_k C1_k
// (sums over repeated k, l), the terms in eta being what turns a spinning
// body's centrifugal load into its spin softening. The point inertias
// (the beam's twist) turn with the modes' rotations Psi_g: they add
// J_g to J0, J_g Psi_g to C0 and Psi_g^T J_g Psi_g to Me; their own
// turning with the deformation is left out (second order in small
// rotations, against a section's already small inertia).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "unfurl/sim/flexible/mass_points.hpp"

namespace unfurl::sim::flexible {

class InertiaInvariants {
 public:
  // shape: the modes over the structure's degrees of freedom (size x m).
  InertiaInvariants(const std::vector<MassPoint>& points, const Eigen::MatrixXd& shape);

  int coordinates() const { return m_; }
  double mass() const { return mass_; }

  // M^(eta), (6 + m) square.
  Eigen::MatrixXd mass_matrix(const Eigen::VectorXd& eta) const;
  // dT/d eta at fixed V = (v, w, eta').
  Eigen::VectorXd kinetic_gradient(const Eigen::VectorXd& eta, const Eigen::VectorXd& V) const;

 private:
  int m_ = 0;
  double mass_ = 0;
  Eigen::Vector3d S0_;
  Eigen::Matrix3Xd S1_, C0_;
  Eigen::Matrix3d J0_;
  std::vector<Eigen::Matrix3d> J1_;  // k
  std::vector<Eigen::Matrix3d> J2_;  // k * m + l
  std::vector<Eigen::Matrix3Xd> C1_;  // k
  Eigen::MatrixXd Me_;
};

}  // namespace unfurl::sim::flexible
