// The floating frame's inertia invariants of a flexible body: its kinetic
// energy T = (1/2) V^T M^(eta) V, V = (v, w, eta') (the frame's velocity,
// linear first, and the elastic rates), as sums over its mass points
// (mass_points.hpp) precomputed once, so that M^(eta) and dT/d eta cost
// O(m^2) an evaluation, whatever the mesh. A point is at
// rho_g = r_g + Phi_g eta - (1/2) (eta^T G_g eta) e_g (the last term the
// foreshortening, mass_points.hpp; zero for a plate), moving at
// v + w x rho_g + B_g eta', B_g = Phi_g - e_g eta^T G_g:
//   M^ = [ m E        -S(eta)~   B(eta)      ]   S(eta) = sum m_g rho_g, B(eta) = sum m_g B_g
//        [ S(eta)~     J(eta)    C(eta)      ]   J(eta) = sum m_g rho_g~^T rho_g~
//        [ B(eta)^T    C(eta)^T  Me          ]   C(eta) = sum m_g rho_g~ B_g, Me = sum m_g Phi_g^T Phi_g
// The kinetic energy is kept to second order in the deformation, eta and
// eta' counted alike (S and J to eta^2, B and C to eta, Me constant): the
// order of linear elasticity, whose stiffening terms it holds, and the
// equations of motion stay linear in eta at a given frame motion. dT/d eta
// is that energy's derivative, so the mechanics stays Lagrangian (energy
// is conserved). The terms in eta are what turn a spinning body's
// centrifugal load into its spin softening and, through the foreshortening,
// its stiffening (Kane, Ryan and Banerjee, 1987). The point inertias
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
  // shape: the modes over the structure's degrees of freedom (size x m);
  // shortening: per point (beam_shortening), or none.
  InertiaInvariants(const std::vector<MassPoint>& points, const Eigen::MatrixXd& shape,
                    const std::vector<Shortening>& shortening = {});

  int coordinates() const { return m_; }
  double mass() const { return mass_; }

  // M^(eta), (6 + m) square.
  Eigen::MatrixXd mass_matrix(const Eigen::VectorXd& eta) const;
  // dM^/dt = sum_k eta'_k dM^/d eta_k.
  Eigen::MatrixXd mass_matrix_rate(const Eigen::VectorXd& eta, const Eigen::VectorXd& eta_dot) const;
  // dT/d eta at fixed V = (v, w, eta').
  Eigen::VectorXd kinetic_gradient(const Eigen::VectorXd& eta, const Eigen::VectorXd& V) const;
  // The same into M ((6 + m) square) and g (m), allocating nothing: the
  // sweep's right-hand side.
  void mass_matrix(const double* eta, Eigen::Ref<Eigen::MatrixXd> M) const;
  void mass_matrix_rate(const double* eta, const double* eta_dot, Eigen::Ref<Eigen::MatrixXd> M) const;
  void kinetic_gradient(const double* eta, const double* V, Eigen::Ref<Eigen::VectorXd> g) const;
  // S(eta): the first moment of mass about the frame's origin (frame
  // axes), the deformed centre of mass times the mass.
  Eigen::Vector3d first_moment(const double* eta) const;
  // Adds B(eta)^T f to Q (m entries): what a uniform field of f per unit
  // mass (gravity, frame axes) does on the elastic coordinates, d(f .
  // S(eta))/d eta. Allocates nothing.
  void add_field_force(const double* eta, const Eigen::Vector3d& f, double* Q) const;

 private:
  int m_ = 0;
  double mass_ = 0;
  Eigen::Vector3d S0_;
  Eigen::Matrix3Xd S1_, C0_;
  Eigen::Matrix3d J0_;
  // S(eta) = S0 + S1 eta - (1/2) eta_k eta_l S2_kl, B(eta) = S1 - eta_k E_k,
  // J(eta) = J0 + eta_k J1_k + eta_k eta_l J2_kl, C(eta) = C0 + eta_k C1_k
  // (sums over k, l).
  std::vector<Eigen::Vector3d> S2_;   // k * m + l
  std::vector<Eigen::Matrix3Xd> E_;   // k
  std::vector<Eigen::Matrix3d> J1_;   // k
  std::vector<Eigen::Matrix3d> J2_;   // k * m + l
  std::vector<Eigen::Matrix3Xd> C1_;  // k
  Eigen::MatrixXd Me_;
};

}  // namespace unfurl::sim::flexible
