#include "unfurl/sim/regulator.hpp"

#include <limits>

namespace unfurl::sim {

Regulator::Regulator(const Model& model, const std::vector<Loop>& loops, std::vector<LoopComponent> components,
                     const RegulatorSettings& settings, double v_max, double length)
    : loops_(loops),
      components_(std::move(components)),
      settings_(settings),
      v_max_(v_max),
      length_(length),
      mobility_(model, loops_, components_),
      Delta_(Eigen::VectorXd::Zero(size())),
      diagonal_W0_(Eigen::VectorXd::Ones(size())),
      rhs_(size(), 2),
      solved_(size(), 2) {
  if (settings_.gains == GainTuning::full)
    solver_ = make_closure_solver(settings_.solver, model, loops_, components_);
}

bool Regulator::factorize(const Sweep& sweep, long configuration) {
  if (settings_.gains != GainTuning::full) return true;
  if (configuration == factorized_configuration_) return factorized_ok_;
  factorized_ok_ = solver_->factorize(sweep, Delta_.data());
  ++factorizations_;
  factorized_configuration_ = configuration;
  return factorized_ok_;
}

const LoopMatrix& Regulator::mobility(const Sweep& sweep, long configuration) {
  if (solver_ && configuration == factorized_configuration_)
    if (const LoopMatrix* W = solver_->mobility()) return *W;
  return mobility_.matrix(sweep);
}

void Regulator::calibrate(const Sweep& sweep) {
  factorized_configuration_ = -1;  // delta changes
  regularization_ = 0;  // the paper's gains use none
  if (settings_.gains == GainTuning::full) {
    Eigen::VectorXd scale(size());
    for (int c = 0; c < size(); ++c) scale[c] = 1 / component_scale(c);
    regularization_ = settings_.regularization ? *settings_.regularization
                                               : automatic_regularization(weakest_mode(sweep, scale));
    delta_ = regularization_ * mobility_.largest_eigenvalue(sweep, scale);
    for (int c = 0; c < size(); ++c) Delta_[c] = delta_ * component_scale(c) * component_scale(c);
    return;
  }
  Eigen::VectorXd unit = Eigen::VectorXd::Zero(size()), column(size());
  for (int c = 0; c < size(); ++c) {
    unit[c] = 1;
    mobility_.product(sweep, unit.data(), column.data());
    diagonal_W0_[c] = column[c];
    unit[c] = 0;
  }
}

double Regulator::weakest_mode(const Sweep& sweep, const Eigen::VectorXd& scale) {
  if (size() == 0) return 1;
  if (size() > kMaxSpectrumComponents) return 0;
  const Eigen::VectorXd w = mobility_.spectrum(sweep, scale);
  const double largest = w[size() - 1];
  for (const double w_i : w)
    if (w_i > kRedundantMode * largest) return w_i / largest;
  return 1;  // W = 0: nothing to close
}

void Regulator::residual_rate(const std::vector<Vec6>& v, double* g_dot) const {
  sim::residual_rate(loops_, components_, v, g_dot);
}

void Regulator::gap(const std::vector<Pose>& poses, double* g) const {
  geometric_gap(loops_, components_, poses, g);
}

void Regulator::control(const double* g, const double* u, const double* g_dot, const double* d, Gains gains,
                        double* lambda, double* u_dot) {
  const double v = v_max_, p0 = settings_.p0, p1 = settings_.p1;
  const double k_pi = this->k_pi(), k_v = this->k_v();  // (16)
  const int m = size();
  Eigen::Map<const Eigen::VectorXd> g_(g, m), u_(u, m), gd_(g_dot, m);
  Eigen::Map<Eigen::VectorXd> lambda_(lambda, m), ud_(u_dot, m);
  auto a = rhs_.col(0), b = rhs_.col(1);
  a = (v * v) * (g_ + u_) + ((p0 + 2 * p1) * v) * gd_;
  if (uses_feedforward()) a += Eigen::Map<const Eigen::VectorXd>(d, m);
  b = k_pi * g_ + k_v * gd_;
  if (settings_.gains == GainTuning::paper) {
    // C_j = v^2 / W_jj, D_j = (p0 + 2 p1) v / W_jj (16), u' of (13)
    lambda_ = a.cwiseQuotient(diagonal_W0_);
    ud_ = b;
    return;
  }
  solver_->solve(rhs_.data(), solved_.data(), 2, gains == Gains::current);
  lambda_ = solved_.col(0);               // R^-1 (v^2 (g + u) + (p0 + 2 p1) v g' + d)
  ud_ = b - Delta_.cwiseProduct(solved_.col(1));  // W R^-1 b = b - Delta R^-1 b
}

void Regulator::integral_at_rest(const double* W_lambda, const double* lambda, const double* d, double* u) const {
  const int m = size();
  Eigen::Map<const Eigen::VectorXd> W_lambda_(W_lambda, m), lambda_(lambda, m), d_(d, m);
  Eigen::Map<Eigen::VectorXd>(u, m) =
      (W_lambda_ + Delta_.cwiseProduct(lambda_) - d_) / (v_max_ * v_max_);  // (12) with R = W + Delta
}

void Regulator::mobility_product(const Sweep& sweep, const double* x, double* Wx) { mobility_.product(sweep, x, Wx); }

void Regulator::apply(const double* lambda, std::vector<Vec6>& F) const {
  add_loop_forces(loops_, components_, lambda, -1.0, F);
}

double Regulator::energy(const double* g, const double* u) {
  const int m = size();
  const double v2 = v_max_ * v_max_;
  Eigen::Map<const Eigen::VectorXd> g_(g, m), u_(u, m);
  auto s = rhs_.col(0);
  s = g_ + u_;
  if (settings_.gains == GainTuning::paper) return 0.5 * v2 * s.cwiseAbs2().cwiseQuotient(diagonal_W0_).sum();
  solver_->solve(rhs_.data(), solved_.data(), 1);
  return 0.5 * v2 * s.dot(solved_.col(0));
}

}  // namespace unfurl::sim
