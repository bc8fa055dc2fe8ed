// An O(N) approximate inverse of the implicit integrators' Newton matrix
// I - gamma df/dy, for their Krylov (GMRES) linear solver: with it a step
// costs a few right-hand sides and sweeps instead of a dense Jacobian of
// n right-hand sides and an O(n^3) factorization.
//
// It solves the linear model in which the joints' springs, dampers,
// friction (its slope at the current rate) and engaged latches are the
// stiff terms and the mass matrix is frozen:
//   q' = x,  Mtilde x = p,  p' = -K q - D x,
//   u' = k_pi J q + k_v J x   (J = eps T A, g' = J q' where the loops are
//   closed; the full tuning's W R^-1 taken as I),
// by one pass of the sweep with Mtilde + gamma D + gamma^2 K (the joint
// terms enter the articulated inertia like armature). The loop forces are
// left to the Krylov iterations: the full-matrix gains put every strong
// residual mode on the same cubic, so they form a tight cluster GMRES
// resolves in a few iterations.
#pragma once

#include <vector>

#include "unfurl/sim/sweep.hpp"

namespace unfurl::sim {

class Dynamics;

class NewtonPreconditioner {
 public:
  explicit NewtonPreconditioner(Dynamics& dynamics);

  // Linearizes at the state y (its q) and its rate ydot (the joint rates,
  // where friction's slope is taken) for the Newton matrix I - gamma J.
  void setup(const double* y, const double* ydot, double gamma);
  // z = P^-1 r with the last setup.
  void solve(const double* r, double* z);

 private:
  Dynamics& dynamics_;
  Sweep sweep_;
  double gamma_ = 0;
  std::vector<double> stiffness_, damping_, diagonal_;  // per velocity coordinate

  // Scratch, sized once.
  std::vector<double> r_, x_, rates_, w_, g_dot_;
  std::vector<double> q_;  // the positions of the last setup
  // Per velocity coordinate of a one-coordinate joint, its position (else
  // -1): where the joint's K and D act.
  std::vector<int> spring_position_;
  std::vector<Vec6> phi_, v_;
};

}  // namespace unfurl::sim
