// An O(N) approximate inverse of the implicit integrators' Newton matrix
// I - gamma df/dy, for their Krylov (GMRES) linear solver: with it a step
// costs a few right-hand sides and sweeps instead of a dense Jacobian of
// n right-hand sides and an O(n^3) factorization.
//
// It solves the linear model in which the joints' springs, dampers,
// friction (its slope at the current rate) and engaged latches are the
// stiff terms and the mass matrix is frozen:
//   q' = x,  Mtilde x = p,  p' = -K q - D x - J^T lambda,
//   lambda and u' of the regulator (12), (13) (regulator.hpp), with
//   J = eps T A and g' = J q' where the loops are closed,
// by passes of the sweep with B = Mtilde + gamma D + gamma^2 K (the joint
// terms enter the articulated inertia like armature). The full tuning's
// loop rows are eliminated exactly: with the impulse mu = gamma lambda,
// B x = r - J^T mu and, mode by mode of the loops' mobility (w, and
// delta = Delta in the closure's metric),
//   mu, du = (each input) N(w) / (A w^2 + (2 + a1) delta w + delta^2),
// A = 1 + a1 + a2, a1 = gamma v (gamma v + p0 + 2 p1), a2 = (gamma v)^2
// (gamma k_pi + k_v), the inputs J B^-1 r, J rq, ru and (with the
// feedforward, whose J Mtilde^-1 carries the springs' share) J Mtilde^-1
// rp, each with its own first- or second-degree N. The regulator's
// a = w / (w + delta) cancels, so the two roots -rho_k delta of the
// denominator are the only poles, and each is one sparse factorization of
// J B^-1 J^T + rho_k Delta (armature_closure_solver.hpp), O(N): W taken as
// J B^-1 J^T is the one approximation in the loops, and with the
// feedforward it bites only in the integral's W R^-1 (d carries W mu,
// which cancels R's W in the force rows). Where the joints' gamma^2 K
// outweighs the inertia along the loops (engaged latches, compliant pins)
// J B^-1 J^T lies far below W, and the integral's modes spread with gamma
// v_max (README, "Newton systems"). On the generated
// 20-stage array at its start every eigenvalue of P^-1 N lies within 2 %
// of 1 at gamma = 0.04 s; with the loops left to GMRES 60 lay at 1e7.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "armature_closure_solver.hpp"
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
  Sweep plain_;  // at Mtilde, for the feedforward's J Mtilde^-1 rp
  double gamma_ = 0;
  std::vector<double> stiffness_, damping_, diagonal_;  // per velocity coordinate

  // Scratch, sized once.
  std::vector<double> r_, x_, rates_, w_, g_dot_;
  std::vector<double> q_;  // the positions of the last setup
  // Per velocity coordinate whose rate is its position's q', that position
  // (else -1): where the joint's K and D act.
  std::vector<int> spring_position_;
  std::vector<Vec6> phi_, v_;

  // The loops' share (full tuning only, else null): R_B's factorizations
  // at the poles rho_k delta (one, or two where they are apart), and
  // scratch for mu, its inputs and its forces.
  // Poles closer than 1 % of themselves (the discriminant below this
  // share of (2 + a1)^2; short steps, h v_max below about 0.1) are taken as
  // one double pole: the partial fractions' 1 / (rho_j - rho_k) would
  // amplify round-off.
  static constexpr double kSeparatePoles = 1e-4;
  std::array<std::unique_ptr<ArmatureClosureSolver>, 2> closure_;
  bool closed_ = false;  // the loops are in: closure_ made and factored at the last setup
  int poles_ = 0;
  double a1_ = 0, a2_ = 0, rho_[2] = {0, 0};
  std::vector<double> Delta_;  // the regulator's, per component
  std::vector<double> delta_, t0_, g_r_, t_p_, mu_, du_, Q_, dx_;
  std::vector<double> pair_in_, pair_tmp_, pair_out_;  // m x 2
  std::vector<Vec6> F_, dv_;

  void set_up_loops(const double* q);
  // A polynomial n2 w^2 + n1 delta w + n0 delta^2 (delta = 1).
  struct Numerator {
    double n2, n1, n0;
  };
  // pair_out_ = the sums over the poles of (n1 w + n0) / den(w) applied to
  // the inputs: column 0 with `first`'s numerators, column 1 with `second`'s.
  void pole_sums(const std::array<const double*, 4>& in, const std::array<Numerator, 4>& first,
                 const std::array<Numerator, 4>& second);
  // x (and v_, its body velocities) less B^-1 J^T mu, and Q_ = -J^T mu.
  void close_loops(const double* r);
};

}  // namespace unfurl::sim
