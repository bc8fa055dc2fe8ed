#include "unfurl/sim/elements/spring_curve.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace unfurl::sim {

namespace {

// The cubic Hermite segment on [0, h] with end values y0, y1 and slopes
// m0, m1, at s = x / h.
struct Hermite {
  double h, y0, y1, m0, m1;
  double value(double s) const {
    const double s2 = s * s, s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * y0 + (s3 - 2 * s2 + s) * h * m0 + (-2 * s3 + 3 * s2) * y1 + (s3 - s2) * h * m1;
  }
  double slope(double s) const {
    const double s2 = s * s;
    return ((6 * s2 - 6 * s) * y0 + (3 * s2 - 4 * s + 1) * h * m0 + (-6 * s2 + 6 * s) * y1 +
            (3 * s2 - 2 * s) * h * m1) /
           h;
  }
  // Integral of the value from 0 to s h.
  double integral(double s) const {
    const double s2 = s * s, s3 = s2 * s, s4 = s3 * s;
    return h * ((0.5 * s4 - s3 + s) * y0 + (0.25 * s4 - 2.0 / 3 * s3 + 0.5 * s2) * h * m0 + (-0.5 * s4 + s3) * y1 +
                (0.25 * s4 - 1.0 / 3 * s3) * h * m1);
  }
};

}  // namespace

SpringCurve::SpringCurve(std::vector<double> q, std::vector<double> tau) : q_(std::move(q)), tau_(std::move(tau)) {
  const std::size_t n = q_.size();
  if (n < 2 || tau_.size() != n)
    throw std::invalid_argument("a spring curve needs at least two (angle, torque) points");
  for (std::size_t k = 0; k + 1 < n; ++k)
    if (!(q_[k + 1] > q_[k])) throw std::invalid_argument("the angles of a spring curve must increase");
  // Fritsch-Carlson: secant slopes d_k; interior slopes their harmonic-type
  // mean where neighbours agree in sign, 0 where they do not; then limited
  // so the segment stays monotone (alpha^2 + beta^2 <= 9).
  std::vector<double> d(n - 1);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    d[k] = (tau_[k + 1] - tau_[k]) / (q_[k + 1] - q_[k]);
    if (!std::isfinite(d[k])) throw std::invalid_argument("two angles of a spring curve are too close together");
  }
  m_.assign(n, 0.0);
  m_[0] = d[0];
  m_[n - 1] = d[n - 2];
  for (std::size_t k = 1; k + 1 < n; ++k) m_[k] = d[k - 1] * d[k] > 0 ? 0.5 * (d[k - 1] + d[k]) : 0.0;
  for (std::size_t k = 0; k + 1 < n; ++k) {
    if (d[k] == 0) {
      m_[k] = m_[k + 1] = 0;
      continue;
    }
    const double a = m_[k] / d[k], b = m_[k + 1] / d[k], r = a * a + b * b;
    if (r > 9) {
      const double t = 3 / std::sqrt(r);
      m_[k] = t * a * d[k];
      m_[k + 1] = t * b * d[k];
    }
  }
  work_.assign(n, 0.0);
  for (std::size_t k = 0; k + 1 < n; ++k)
    work_[k + 1] = work_[k] + Hermite{q_[k + 1] - q_[k], tau_[k], tau_[k + 1], m_[k], m_[k + 1]}.integral(1.0);
}

int SpringCurve::segment(double q) const {
  const auto it = std::upper_bound(q_.begin(), q_.end(), q);
  return std::clamp(static_cast<int>(it - q_.begin()) - 1, 0, static_cast<int>(q_.size()) - 2);
}

double SpringCurve::torque(double q) const {
  if (q <= q_.front()) return tau_.front() + m_.front() * (q - q_.front());
  if (q >= q_.back()) return tau_.back() + m_.back() * (q - q_.back());
  const int k = segment(q);
  const double h = q_[k + 1] - q_[k];
  return Hermite{h, tau_[k], tau_[k + 1], m_[k], m_[k + 1]}.value((q - q_[k]) / h);
}

double SpringCurve::slope(double q) const {
  if (q <= q_.front()) return m_.front();
  if (q >= q_.back()) return m_.back();
  const int k = segment(q);
  const double h = q_[k + 1] - q_[k];
  return Hermite{h, tau_[k], tau_[k + 1], m_[k], m_[k + 1]}.slope((q - q_[k]) / h);
}

double SpringCurve::energy(double q) const {
  double W = 0;  // integral of tau from q_0 to q
  if (q <= q_.front()) {
    const double x = q - q_.front();
    W = tau_.front() * x + 0.5 * m_.front() * x * x;
  } else if (q >= q_.back()) {
    const double x = q - q_.back();
    W = work_.back() + tau_.back() * x + 0.5 * m_.back() * x * x;
  } else {
    const int k = segment(q);
    const double h = q_[k + 1] - q_[k];
    W = work_[k] + Hermite{h, tau_[k], tau_[k + 1], m_[k], m_[k + 1]}.integral((q - q_[k]) / h);
  }
  return -W;
}

}  // namespace unfurl::sim
