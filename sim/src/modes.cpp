#include "unfurl/sim/modes.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "closure_rank.hpp"
#include "unfurl/sim/dynamics.hpp"
#include "unfurl/sim/kinematics.hpp"

namespace unfurl::sim {

namespace {

// The differences' step: 1e-6 rad (or of the mechanism's length), and 1e-6
// of its rate: the truncation error (step^2) and the round-off (1e-16 /
// step) both near 1e-10 of what they measure.
constexpr double kStep = 1e-6;
// Settled when the equilibrium is this near (rad, or over the length).
constexpr double kSettled = 1e-11;
constexpr int kMostSettleIterations = 30;
// The largest settling step, in the state's own scale (a hinge's radians).
// Within it the settle takes Newton's steps to the equilibrium nearby,
// whatever its kind; from farther (a pendulum mid-swing) it goes downhill
// by this much at a time, so that it neither jumps past the equilibrium
// sought nor climbs to a potential's maximum.
constexpr double kLargestSettleStep = 0.3;
// A displaced state is put back on its loops to this gap (closure metric).
constexpr double kClosed = 1e-13;
constexpr int kMostClosingIterations = 20;
// A frequency below this fraction of the highest is zero to first order:
// the differences' round-off (1e-16 of the largest force over the step)
// alone gives frequencies near 1e-8 of it.
constexpr double kZeroFrequency = 1e-6;
// The rank of the loops' Jacobian (in the mass metric) that the
// linearization keeps: every direction with a first-order gap is
// constrained, down to round-off. Directions whose singular value lies
// below sqrt(kRankTolerance) of the largest (an eigenvalue of S W S below
// kRankTolerance, where the loads are indeterminate, closure_rank.hpp) are
// counted as weak: near a branch point, constrained only by its distance.
constexpr double kRankNumerical = 1e-9;
const double kWeakSingular = std::sqrt(ClosureRank::kRankTolerance);

// The linearized equations z'' = f(z, z') at positions q: the basis, the
// mass matrix there, and K and C.
struct Linear {
  Eigen::MatrixXd T, M, K, C;
  Eigen::VectorXd f0;  // z'' at z = z' = 0
  int loop_rank = 0;
  int weak_loop_directions = 0;
};

class Linearizer {
 public:
  Linearizer(const Scene& scene, const std::vector<bool>& engaged) : dynamics_(scene), model_(scene.model) {
    for (int l = 0; l < dynamics_.latch_count() && l < static_cast<int>(engaged.size()); ++l)
      if (engaged[l]) dynamics_.latch_state().engage(l);
    size_.resize(model_.nv);
    for (int c = 0; c < model_.nv; ++c)
      size_[c] = model_.velocity_unit(c) == "m/s" ? dynamics_.scales().length : 1.0;
    // The drivers hold their joints: the motions are those of the other
    // coordinates.
    std::vector<int> free;
    for (int c = 0; c < model_.nv; ++c)
      if (model_.joint_of_velocity[c] < 0 || !model_.joints[model_.joint_of_velocity[c]].driven) free.push_back(c);
    if (static_cast<int>(free.size()) < model_.nv) {
      held_ = Eigen::MatrixXd::Zero(model_.nv, static_cast<Eigen::Index>(free.size()));
      for (std::size_t k = 0; k < free.size(); ++k) held_(free[k], static_cast<Eigen::Index>(k)) = 1;
    }
  }

  // How many coordinates move (the driven ones are held).
  int free_coordinates() const { return held_.size() ? static_cast<int>(held_.cols()) : model_.nv; }

  Dynamics& dynamics() { return dynamics_; }
  const Eigen::VectorXd& size() const { return size_; }

  // The largest entry of x in the coordinates' own sizes.
  double scaled_norm(const Eigen::VectorXd& x) const { return x.cwiseQuotient(size_).cwiseAbs().maxCoeff(); }

  // q put back on its loops: the minimum-norm correction in the mass metric.
  std::vector<double> closed(std::vector<double> q) {
    if (scene().loops.empty()) return q;
    for (int k = 0; k < kMostClosingIterations; ++k) {
      const Eigen::VectorXd g = dynamics_.loop_gap(q.data());
      if (g.cwiseAbs().maxCoeff() < kClosed) return q;
      const Eigen::MatrixXd Linv_T = inverse_factor(q);
      Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(dynamics_.loop_jacobian(q.data()) * Linv_T);
      cod.setThreshold(kRankNumerical);
      q = displaced_positions(model_, q, -(Linv_T * cod.solve(g)));
    }
    throw std::runtime_error("the loops could not be closed at the state (gap left " +
                             std::to_string(dynamics_.loop_gap(q.data()).cwiseAbs().maxCoeff()) + ")");
  }

  Linear linearize(const std::vector<double>& q, bool with_damping) {
    Linear lin;
    lin.M = dynamics_.mass_matrix(q.data());
    basis(q, lin);
    const int d = static_cast<int>(lin.T.cols());
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(d);
    lin.f0 = reduced(q, lin, zero, zero);
    lin.K.resize(d, d);
    lin.C = Eigen::MatrixXd::Zero(d, d);
    for (int i = 0; i < d; ++i) {
      const double h = kStep / scaled_norm(lin.T.col(i));
      Eigen::VectorXd z = zero;
      z[i] = h;
      lin.K.col(i) = -(reduced(q, lin, z, zero) - reduced(q, lin, -z, zero)) / (2 * h);
      if (!with_damping) continue;
      z[i] = h * dynamics_.scales().rate;
      lin.C.col(i) = -(reduced(q, lin, zero, z) - reduced(q, lin, zero, -z)) / (2 * z[i]);
    }
    return lin;
  }

 private:
  const Scene& scene() const { return dynamics_.scene(); }

  // L^-T for M = L L^T at q (on the free coordinates, S L_f^-T with M_f =
  // S^T M S, where drivers hold some).
  Eigen::MatrixXd inverse_factor(const std::vector<double>& q) {
    return inverse_factor_of(dynamics_.mass_matrix(q.data()));
  }
  Eigen::MatrixXd inverse_factor_of(const Eigen::MatrixXd& M) const {
    const int n = free_coordinates();
    const Eigen::LLT<Eigen::MatrixXd> llt(held_.size() ? Eigen::MatrixXd(held_.transpose() * M * held_) : M);
    if (llt.info() != Eigen::Success) throw std::runtime_error("the mass matrix is not positive definite at the state");
    const Eigen::MatrixXd Linv_T = llt.matrixU().solve(Eigen::MatrixXd::Identity(n, n));
    return held_.size() ? Eigen::MatrixXd(held_ * Linv_T) : Linv_T;
  }

  // T: the admissible motions, T^T M T = I.
  void basis(const std::vector<double>& q, Linear& lin) {
    const Eigen::MatrixXd Linv_T = inverse_factor_of(lin.M);
    if (scene().loops.empty()) {
      lin.T = Linv_T;
      return;
    }
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(dynamics_.loop_jacobian(q.data()) * Linv_T, Eigen::ComputeFullV);
    const Eigen::VectorXd& sigma = svd.singularValues();
    lin.loop_rank = lin.weak_loop_directions = 0;
    for (int k = 0; k < sigma.size(); ++k) {
      if (sigma[k] > kRankNumerical * sigma[0]) ++lin.loop_rank;
      if (sigma[k] > kRankNumerical * sigma[0] && sigma[k] <= kWeakSingular * sigma[0]) ++lin.weak_loop_directions;
    }
    lin.T = Linv_T * svd.matrixV().rightCols(free_coordinates() - lin.loop_rank);
  }

  // z'' at z, z' about q: the rigid accelerations at the displaced state,
  // back on its loops, in the basis (T^T M w'' with T^T M T = I).
  Eigen::VectorXd reduced(const std::vector<double>& q, const Linear& lin, const Eigen::VectorXd& z,
                          const Eigen::VectorXd& z_dot) {
    const std::vector<double> at = z.isZero(0) ? q : closed(displaced_positions(model_, q, lin.T * z));
    const Eigen::VectorXd w = lin.T * z_dot;
    Eigen::VectorXd a(model_.nv);
    if (!dynamics_.rigid_accelerations(at.data(), w.data(), a.data()))
      throw std::runtime_error("the accelerations could not be evaluated at the state");
    return lin.T.transpose() * (lin.M * a);
  }

  Dynamics dynamics_;
  const Model& model_;
  Eigen::VectorXd size_;
  Eigen::MatrixXd held_;  // S: the free coordinates' columns of I, empty without drivers
};

// The symmetric part of K, its eigen-decomposition (omega^2 ascending).
Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> stiffness_modes(const Linear& lin) {
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(0.5 * (lin.K + lin.K.transpose()));
}

// The kinds of the modes of omega^2 values mu (ascending): a free base's
// six smallest are rigid-body modes, those near zero mechanism modes.
std::vector<ModeKind> mode_kinds(const Eigen::VectorXd& mu, bool free_floating) {
  const int d = static_cast<int>(mu.size());
  std::vector<int> by_size(d);
  for (int i = 0; i < d; ++i) by_size[i] = i;
  std::sort(by_size.begin(), by_size.end(), [&](int a, int b) { return std::abs(mu[a]) < std::abs(mu[b]); });
  const double largest = d > 0 ? mu.cwiseAbs().maxCoeff() : 0;
  std::vector<ModeKind> kind(d, ModeKind::elastic);
  for (int r = 0; r < d; ++r) {
    const int i = by_size[r];
    if (free_floating && r < 6)
      kind[i] = ModeKind::rigid_body;
    else if (std::abs(mu[i]) <= kZeroFrequency * kZeroFrequency * largest)
      kind[i] = ModeKind::mechanism;
    else if (mu[i] < 0)
      kind[i] = ModeKind::unstable;
  }
  return kind;
}

// The step to the static equilibrium, K dz = f0, along the modes with
// stiffness (rigid-body and mechanism modes stay). Along an unstable mode
// Newton's step climbs towards the potential's maximum (an inverted
// pendulum); `downhill`, it goes the other way by as much.
Eigen::VectorXd equilibrium_step(const Linear& lin, const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>& eig,
                                 const std::vector<ModeKind>& kind, bool downhill) {
  Eigen::VectorXd dz = Eigen::VectorXd::Zero(lin.T.cols());
  for (int i = 0; i < static_cast<int>(kind.size()); ++i) {
    if (kind[i] == ModeKind::rigid_body || kind[i] == ModeKind::mechanism) continue;
    const Eigen::VectorXd phi = eig.eigenvectors().col(i);
    const double mu = eig.eigenvalues()[i];
    dz += phi * (phi.dot(lin.f0) / (downhill ? std::abs(mu) : mu));
  }
  return dz;
}

}  // namespace

const char* mode_kind_name(ModeKind kind) {
  switch (kind) {
    case ModeKind::elastic:
      return "elastic";
    case ModeKind::rigid_body:
      return "rigid body";
    case ModeKind::mechanism:
      return "mechanism";
    case ModeKind::unstable:
      return "unstable";
  }
  return "?";
}

LinearizationState state_of_run(const Scene& scene, const Trajectory& tr, double t) {
  if (tr.empty()) throw std::runtime_error("the run recorded no state");
  LinearizationState state;
  state.t = std::min(t, tr.t_end());
  tr.coordinates_at(state.t, state.q);
  for (const JointDriver* d : scene.elements_of<JointDriver>())
    if (const double rate = d->at(state.t).rate; rate != 0)
      throw std::runtime_error("joint '" + scene.model.joints[d->joint].name + "' is still driven at t = " +
                               std::to_string(state.t) + " s (rate " + std::to_string(rate) +
                               "): the modes are about a state at rest, the drivers holding their joints");
  state.engaged.assign(scene.latches().size(), false);
  for (const LatchEvent& e : tr.events)
    if (e.t <= state.t) state.engaged[e.latch] = true;
  return state;
}

LinearizationState given_state(const Scene& scene, const std::vector<double>& q) {
  LinearizationState state;
  state.q = q;
  const std::vector<const Latch*> latches = scene.latches();
  for (const Latch* latch : latches) {
    const double start = scene.q0[scene.model.position_of(latch->joint).value] - latch->position;
    const double now = q[scene.model.position_of(latch->joint).value] - latch->position;
    state.engaged.push_back(start * now <= 0);
  }
  return state;
}

Trajectory mode_animation(const Scene& scene, const ModesResult& modes, int k, double amplitude, double period,
                          int samples) {
  const Model& model = scene.model;
  if (k < 0 || k >= static_cast<int>(modes.modes.size())) throw std::runtime_error("no such mode");
  Linearizer closer(scene, modes.engaged);
  Trajectory tr;
  tr.layout = closer.dynamics().layout();
  const Eigen::VectorXd& shape = modes.modes[k].shape;
  for (int s = 0; s <= samples; ++s) {
    Sample sample;
    sample.t = period * s / samples;
    const double phase = 2 * M_PI * sample.t / period;
    const std::vector<double> q = closer.closed(displaced_positions(model, modes.q, amplitude * std::sin(phase) * shape));
    sample.y.assign(tr.layout.size(), 0.0);
    std::copy(q.begin(), q.end(), sample.y.begin() + tr.layout.q());
    const Eigen::VectorXd rate = amplitude * (2 * M_PI / period) * std::cos(phase) * shape;
    sample.q_dot.resize(model.nq);
    position_rates(model, q.data(), rate.data(), sample.q_dot.data());
    tr.samples.push_back(std::move(sample));
  }
  return tr;
}

std::vector<double> displaced_positions(const Model& model, const std::vector<double>& q, const Eigen::VectorXd& x) {
  std::vector<double> dq(model.nq), out(q);
  position_rates(model, q.data(), x.data(), dq.data());
  for (int c = 0; c < model.nq; ++c) out[c] += dq[c];
  for (int j = 0; j < model.size(); ++j) {
    if (!model.joints[j].has_quaternion()) continue;
    double* quaternion = out.data() + model.first_position[j].value + model.joints[j].quaternion_offset();
    Eigen::Map<Eigen::Vector4d>(quaternion).normalize();
  }
  return out;
}

ModesResult linear_modes(const Scene& scene, const std::vector<double>& q0, const std::vector<bool>& engaged,
                         const ModesSettings& settings) {
  const Model& model = scene.model;
  if (static_cast<int>(q0.size()) != model.nq) throw std::runtime_error("the state has the wrong number of positions");
  Linearizer lin(scene, engaged);
  ModesResult result;
  result.engaged = engaged;
  result.coordinates = lin.free_coordinates();
  result.length = lin.dynamics().scales().length;
  std::vector<double> q = lin.closed(q0);
  for (int iteration = 0;; ++iteration) {
    const Linear at = lin.linearize(q, false);
    const auto eig = stiffness_modes(at);
    const std::vector<ModeKind> kinds = mode_kinds(eig.eigenvalues(), model.free_floating());
    Eigen::VectorXd dz = equilibrium_step(at, eig, kinds, false);
    result.equilibrium_offset = lin.scaled_norm(at.T * dz);
    result.settle_iterations = iteration;
    if (!settings.settle || result.equilibrium_offset < kSettled || iteration == kMostSettleIterations) break;
    if (result.equilibrium_offset > kLargestSettleStep) {
      dz = equilibrium_step(at, eig, kinds, true);
      dz *= kLargestSettleStep / lin.scaled_norm(at.T * dz);
    }
    q = lin.closed(displaced_positions(model, q, at.T * dz));
  }
  const Linear at = lin.linearize(q, true);
  const auto eig = stiffness_modes(at);
  const std::vector<ModeKind> kind = mode_kinds(eig.eigenvalues(), model.free_floating());
  result.q = q;
  result.loop_rank = at.loop_rank;
  result.weak_loop_directions = at.weak_loop_directions;
  const double symmetric = (at.K + at.K.transpose()).norm();
  result.stiffness_asymmetry = symmetric > 0 ? (at.K - at.K.transpose()).norm() / symmetric : 0;
  for (int i = 0; i < static_cast<int>(kind.size()); ++i) {
    Mode mode;
    mode.kind = kind[i];
    const Eigen::VectorXd phi = eig.eigenvectors().col(i);  // unit: mass-normalized, T^T M T = I
    const double mu = eig.eigenvalues()[i];
    if (kind[i] == ModeKind::elastic) {
      const double omega = std::sqrt(mu);
      mode.frequency_hz = omega / (2 * M_PI);
      mode.damping_ratio = phi.dot(at.C * phi) / (2 * omega);
      if (mode.damping_ratio < 1) mode.damped_frequency_hz = mode.frequency_hz * std::sqrt(1 - std::pow(mode.damping_ratio, 2));
    } else if (kind[i] == ModeKind::unstable) {
      mode.frequency_hz = -std::sqrt(-mu) / (2 * M_PI);  // the growth rate over 2 pi
    }
    mode.shape = at.T * phi;
    const Eigen::VectorXd scaled = mode.shape.cwiseQuotient(lin.size());
    Eigen::Index largest = 0;
    scaled.cwiseAbs().maxCoeff(&largest);
    mode.shape /= scaled[largest];
    result.modes.push_back(std::move(mode));
  }
  // Rigid-body and mechanism modes first, then by frequency.
  std::stable_sort(result.modes.begin(), result.modes.end(), [](const Mode& a, const Mode& b) {
    const auto rank = [](const Mode& m) { return m.kind == ModeKind::rigid_body ? 0 : m.kind == ModeKind::mechanism ? 1 : 2; };
    if (rank(a) != rank(b)) return rank(a) < rank(b);
    return a.frequency_hz < b.frequency_hz;
  });
  return result;
}

}  // namespace unfurl::sim
