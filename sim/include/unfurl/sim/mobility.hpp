// The loop components' mobility W = eps T A Mtilde^-1 (eps T A)^T of (16):
// the residual rates eps v that loop forces cause on the system at rest.
// Every product is a pass of the sweep (O(N)); no mass matrix is formed.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "unfurl/sim/loop_components.hpp"
#include "unfurl/sim/sweep.hpp"

namespace unfurl::sim {

// Forming all of W costs O(N m) and the dense solver O(m^3); beyond this
// many components only the sparse solver is used. Bounding the size keeps
// the dense matrices on the stack (no allocation in the right-hand side).
inline constexpr int kMaxDenseComponents = 48;
using LoopMatrix =
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxDenseComponents, kMaxDenseComponents>;

class Mobility {
 public:
  Mobility(const Model& model, const std::vector<Loop>& loops, const std::vector<LoopComponent>& components);

  int size() const { return static_cast<int>(components_.size()); }

  // Wx = W x at the sweep's configuration: one load case through the passes.
  void product(const Sweep& sweep, const double* x, double* Wx);

  // All of W: the passes on the m unit loads at once. Throws
  // std::invalid_argument beyond kMaxDenseComponents.
  const LoopMatrix& matrix(const Sweep& sweep);

  // The largest eigenvalue of S W S for a diagonal S (`scale`, one entry
  // per component), by power iteration on products: the scale the
  // regulator's regularization is measured against.
  double largest_eigenvalue(const Sweep& sweep, const Eigen::VectorXd& scale);
  // The same from the unit vector x, which it leaves at the last iterate
  // (a warm start for the next configuration): at least `least` iterations,
  // then until the estimate moves less than `tolerance` of itself.
  double largest_eigenvalue(const Sweep& sweep, const Eigen::VectorXd& scale, Eigen::VectorXd& x, int least,
                            double tolerance);

  // Every eigenvalue of S W S, ascending: W formed from m products (O(N m))
  // and decomposed densely (O(m^3)), so for analysis at the start only.
  Eigen::VectorXd spectrum(const Sweep& sweep, const Eigen::VectorXd& scale);

 private:
  using Spatial = Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, kMaxDenseComponents>;
  using Coordinates = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, Eigen::Dynamic, kMaxDenseComponents>;

  std::vector<Loop> loops_;
  std::vector<LoopComponent> components_;

  // Scratch, sized once.
  std::vector<Vec6> F_, phi_, v_;
  Eigen::VectorXd x_, dq_;
  Eigen::VectorXd Sx_, Wx_;  // the power iteration's, per component (it runs every step in the sparse analysis)
  LoopMatrix W_;
  std::vector<Spatial> loads_, phi_m_, v_m_;
  Coordinates x_m_, dq_m_;
};

}  // namespace unfurl::sim
