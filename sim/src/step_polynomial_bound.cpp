#include "step_polynomial_bound.hpp"

#include <cmath>

namespace unfurl::sim {

namespace {

double binomial(int n, int k) {
  double c = 1;
  for (int j = 1; j <= k; ++j) c = c * (n - k + j) / j;
  return c;
}

}  // namespace

StepPolynomialBound::StepPolynomialBound(int degree) : degree_(degree), nodes_(degree + 1) {
  const int d = degree;
  for (int k = 0; k <= d; ++k) nodes_[k] = d == 0 ? 0.0 : 0.5 * (1 - std::cos(M_PI * k / d));
  // B(k, j): Bernstein basis polynomial j at node k. The Lobatto nodes keep
  // it well conditioned (about 1e3 at d = 12).
  Eigen::MatrixXd B(d + 1, d + 1);
  for (int k = 0; k <= d; ++k)
    for (int j = 0; j <= d; ++j) B(k, j) = binomial(d, j) * std::pow(nodes_[k], j) * std::pow(1 - nodes_[k], d - j);
  to_bernstein_ = B.fullPivLu().inverse();
}

double StepPolynomialBound::lower_bound(const Eigen::VectorXd& values) const {
  return (to_bernstein_ * values).minCoeff();
}

}  // namespace unfurl::sim
