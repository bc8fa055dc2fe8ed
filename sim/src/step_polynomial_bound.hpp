// A lower bound on one component of an integrator's interpolant over a
// step, without interpolating the whole state at many times: the
// interpolant is a polynomial of a known degree d in t (CVODE's BDF up to
// 5, Adams up to 12; ARKODE's Hermite up to 5; RK4's cubic), so its values
// at d + 1 nodes of the step determine it, and the least of its Bernstein
// coefficients on the step bounds it from below (the curve lies in the
// convex hull of its Bernstein control points). The latch events use it
// to pass over the steps where a switching function cannot come near zero
// before searching for a graze (latch_events.cpp).
#pragma once

#include <Eigen/Dense>

namespace unfurl::sim {

class StepPolynomialBound {
 public:
  explicit StepPolynomialBound(int degree);

  int degree() const { return degree_; }
  // Node k of the step [0, 1] (Chebyshev-Lobatto: node 0 is the step's
  // start, node d its end).
  double node(int k) const { return nodes_[k]; }
  // The least Bernstein coefficient of the degree-d polynomial whose values
  // at the nodes are `values` (d + 1 of them).
  double lower_bound(const Eigen::VectorXd& values) const;

 private:
  int degree_;
  Eigen::VectorXd nodes_;
  Eigen::MatrixXd to_bernstein_;  // values at the nodes -> Bernstein coefficients
};

}  // namespace unfurl::sim
