// The sparse closure solver. With body velocities v (6 per body), joint
// reactions r (6 - n_i per joint) and loop forces y (one per component),
//
//   [ M    G^T    E^T ] [v]   [0]
//   [ G   -eps I   0  ] [r] = [0]      G: N_i^T (v_i - C_i v_k) = 0, the
//   [ E    0    -delta] [y]   [b]      directions joint i does not move in
//
// eliminating v and r leaves -(E T A Mtilde^-1 A^T T^T E^T + delta) y = b,
// i.e. y = -R^-1 b with W = eps T A Mtilde^-1 (eps T A)^T as in (16): the
// tree's motions are the null space of G, T A. The matrix is sparse with
// the primary graph's pattern, so a fill-reducing ordering factors a chain
// of loops in O(N).
//
// A flexible body's v is its extended velocity (the frame's 6, then eta'),
// its block of M its own mass matrix M^(eta), and a child hanging on its
// node a sees the node's velocity N_a v_k in place of v_k (sweep.hpp).
//
// With eps > 0 the matrix is quasi-definite and LDL^T needs no pivoting for
// any ordering; eps itself is removed by refining against eps = 0, which
// converges in one or two more solves to round-off.
#include <Eigen/OrderingMethods>
#include <Eigen/QR>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <limits>

#include "armature_closure_solver.hpp"

namespace unfurl::sim {

namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

// The joint's 6 - n constrained directions: an orthonormal complement of
// the n columns of A.
using Directions = Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, 6>;

Directions constrained_directions(const Mat6& A, int dof) {
  if (dof == 0) return Mat6::Identity();
  const Eigen::HouseholderQR<Directions> qr(A.leftCols(dof));
  const Mat6 Q = qr.householderQ();
  return Q.rightCols(6 - dof);
}

// C_i of (1) as a matrix: v_child = C v_parent.
Mat6 velocity_transform(const Placement& X) {
  Mat6 C;
  for (int c = 0; c < 6; ++c) C.col(c) = X.transform_velocity(Vec6::Unit(c));
  return C;
}

using OnParent = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, flexible::kMaxExtended>;

class SparseClosureSolver : public ArmatureClosureSolver {
 public:
  // With `armature`, factorize() takes the joints' armature as well.
  SparseClosureSolver(const Model& model, const std::vector<Loop>& loops, const std::vector<LoopComponent>& components,
                      bool armature)
      : model_(model), m_(static_cast<int>(components.size())), armature_(armature) {
    const int N = model.size();
    double total_mass = 0;
    for (const Body& b : model.bodies) total_mass += b.mass;
    eps_ = (armature ? kArmatureEps : kEps) * N / total_mass;

    int rows = 0;
    velocity_row_.resize(N);
    for (int i = 0; i < N; ++i) {
      velocity_row_[i] = rows;
      rows += width(i);
    }
    velocity_rows_ = rows;
    joint_row_.resize(N);
    N_.resize(N);
    for (int i = 0; i < N; ++i) {
      N_[i] = constrained_directions(model.joints[i].motion_axes(), model.joints[i].dof());
      joint_row_[i] = rows;
      rows += static_cast<int>(N_[i].cols());
    }
    loop_row_ = rows;
    rows += m_;

    // The lower triangle: every row index below is >= its column index.
    std::vector<Eigen::Triplet<double>> entries;
    for (int i = 0; i < N; ++i) {
      const int v_i = velocity_row_[i];
      if (model.flexible(i)) {  // M^(eta): set by factorize
        for (int c = 0; c < width(i); ++c)
          for (int r = c; r < width(i); ++r) entries.emplace_back(v_i + r, v_i + c, 0.0);
      } else {
        const Mat6 M = model.bodies[i].spatial_mass();
        for (int c = 0; c < 6; ++c)
          for (int r = c; r < 6; ++r) entries.emplace_back(v_i + r, v_i + c, M(r, c));
      }
      const int k = model.parent[i];
      for (int r = 0; r < N_[i].cols(); ++r) {
        for (int c = 0; c < 6; ++c) entries.emplace_back(joint_row_[i] + r, v_i + c, N_[i](c, r));
        if (k != kBase)
          for (int c = 0; c < width(k); ++c) entries.emplace_back(joint_row_[i] + r, velocity_row_[k] + c, 0.0);
        entries.emplace_back(joint_row_[i] + r, joint_row_[i] + r, -eps_);
      }
      if (armature_ && carries_armature(i) && k != kBase)
        for (int r = 0; r < 6; ++r)
          for (int c = 0; c < width(k); ++c) entries.emplace_back(v_i + r, velocity_row_[k] + c, 0.0);
    }
    for (int c = 0; c < m_; ++c) {
      const LoopComponent& lc = components[c];
      entries.emplace_back(loop_row_ + c, velocity_row_[loops[lc.loop].body] + lc.axis, 1.0);
      entries.emplace_back(loop_row_ + c, velocity_row_[loops[lc.loop].image] + lc.axis, -1.0);
      entries.emplace_back(loop_row_ + c, loop_row_ + c, 0.0);
    }
    K_.resize(rows, rows);
    K_.setFromTriplets(entries.begin(), entries.end());
    K_.makeCompressed();  // the solves read its arrays

    // Where the configuration-dependent values sit: -N_i^T C_i (N_a), -delta
    // and the flexible bodies' M^.
    for (int i = 0; i < N; ++i) {
      const int k = model.parent[i];
      if (k == kBase) continue;
      for (int r = 0; r < N_[i].cols(); ++r)
        for (int c = 0; c < width(k); ++c)
          parent_block_.push_back(&K_.coeffRef(joint_row_[i] + r, velocity_row_[k] + c));
    }
    for (int i = 0; i < N; ++i) {
      if (!model.flexible(i)) continue;
      flexible_.push_back(i);
      for (int c = 0; c < width(i); ++c)
        for (int r = c; r < width(i); ++r)
          mass_block_.push_back(&K_.coeffRef(velocity_row_[i] + r, velocity_row_[i] + c));
    }
    for (int c = 0; c < m_; ++c) delta_slot_.push_back(&K_.coeffRef(loop_row_ + c, loop_row_ + c));
    for (int i = 0; i < N; ++i) {
      if (!model.joints[i].has_varying_axes()) continue;
      varying_.push_back(i);
      for (int r = 0; r < N_[i].cols(); ++r)
        for (int c = 0; c < 6; ++c) varying_block_.push_back(&K_.coeffRef(joint_row_[i] + r, velocity_row_[i] + c));
    }

    if (armature_) find_armature_slots();

    ldlt_.analyzePattern(K_);
  }

  bool factorize(const Sweep& sweep, const double* delta) override { return factor(sweep, delta, nullptr); }
  bool factorize(const Sweep& sweep, const double* delta, const double* armature) override {
    return factor(sweep, delta, armature);
  }

  bool factor(const Sweep& sweep, const double* delta, const double* armature) {
    if (armature) std::copy(mass_only_.begin(), mass_only_.end(), K_.valuePtr());
    double** varying_slot = varying_block_.data();
    for (int i : varying_) {
      N_[i] = constrained_directions(sweep.motion_axes(i), model_.joints[i].dof());
      for (int r = 0; r < N_[i].cols(); ++r)
        for (int c = 0; c < 6; ++c) **varying_slot++ = N_[i](c, r);
    }
    double** slot = parent_block_.data();
    for (int i = 0; i < model_.size(); ++i) {
      const int k = model_.parent[i];
      if (k == kBase) continue;
      const OnParent block = on_parent(sweep, i, -N_[i].transpose());
      for (int r = 0; r < block.rows(); ++r)
        for (int c = 0; c < width(k); ++c) **slot++ = block(r, c);
    }
    double** mass = mass_block_.data();
    for (int i : flexible_) {
      const flexible::ExtendedMatrix& M = sweep.flexible_mass(i);
      for (int c = 0; c < width(i); ++c)
        for (int r = c; r < width(i); ++r) **mass++ = M(r, c);
    }
    for (int c = 0; c < m_; ++c) *delta_slot_[c] = -delta[c];
    if (armature) add_armature(sweep, armature);
    ldlt_.factorize(K_);
    D_ = ldlt_.vectorD();  // a copy: Eigen hands D out by value
    return ldlt_.info() == Eigen::Success;
  }

  void solve(const double* B, double* X, int columns, bool refine) override {
    const int n = static_cast<int>(K_.rows()), v_rows = velocity_rows_, joint_rows = loop_row_ - v_rows;
    const int k = columns;
    for (std::vector<double>* a : {&rhs_, &solution_, &residual_, &work_}) a->resize(static_cast<std::size_t>(n) * k);
    std::fill(rhs_.begin(), rhs_.end(), 0.0);
    for (int r = 0; r < m_; ++r)
      for (int c = 0; c < k; ++c) rhs_[c * n + loop_row_ + r] = B[c * m_ + r];
    apply_inverse(rhs_, solution_, k);
    // Near a branch point R is as ill-conditioned as lambda_max / delta;
    // a few passes reach 1e-12 of the right-hand side there. Where the
    // solution is large (R^-1 amplifies by up to 1 / regularization) the
    // residual's round-off floor, u ||K|| ||x||, lies above that: a pass
    // that does not halve the residual has reached it, and more would
    // only repeat it (on a 30-stage pantograph most solves used to run
    // all five passes for nothing).
    // With armature (a preconditioner's solve) exactly one pass, so that
    // the solve is one fixed linear map, as GMRES needs.
    const double target = 1e-12 * norm(rhs_);
    double previous = std::numeric_limits<double>::infinity();
    const int passes = armature_ ? 1 : refine ? 5 : 0;
    for (int pass = 0; pass < passes; ++pass) {
      // The residual of the unregularized matrix: K_0 = K + eps on the joint rows.
      residual_of_K(k);
      for (int c = 0; c < k; ++c)
        for (int i = v_rows; i < v_rows + joint_rows; ++i) residual_[c * n + i] -= eps_ * solution_[c * n + i];
      const double r = norm(residual_);
      if (!armature_ && (r <= target || r > 0.5 * previous)) break;
      previous = r;
      apply_inverse(residual_, work_, k);
      for (std::size_t i = 0; i < solution_.size(); ++i) solution_[i] += work_[i];
    }
    for (int r = 0; r < m_; ++r)
      for (int c = 0; c < k; ++c) X[c * m_ + r] = -solution_[c * n + loop_row_ + r];
  }

 private:
  const Model& model_;
  int m_;
  double eps_;
  std::vector<int> velocity_row_, joint_row_;
  int velocity_rows_ = 0;
  std::vector<Directions> N_;
  std::vector<int> varying_;            // joints whose A (and N) turn with q: universal
  std::vector<double*> varying_block_;  // their N_i^T entries
  int loop_row_ = 0;
  bool armature_;
  // The joint rows' -eps (per unit of the mechanism's mean mass). The
  // armature system is solved at poles rho delta far below delta (8e-6 and
  // 2.8e-3 of it at gamma v_max = 350), where one pass against 1e-10 left the 20-stage
  // array's preconditioned Newton matrix with eigenvalues out to 4; at
  // 1e-12 they lie within 2 % of 1 (1e-13: one at 0.05, 1e-14: out to 27,
  // the factorization's round-off growing as eps falls).
  static constexpr double kEps = 1e-10, kArmatureEps = 1e-12;
  SparseMatrix K_;
  // With armature: K's values without it (the masses' blocks are written
  // once, so each factorization starts again from these), and the entries
  // it adds to, in add_armature()'s order.
  std::vector<double> mass_only_;
  std::vector<double*> armature_slot_;
  std::vector<double*> parent_block_, delta_slot_;
  std::vector<int> flexible_;        // bodies whose block of M is M^(eta)
  std::vector<double*> mass_block_;  // its lower triangle
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt_;
  // Scratch, n x columns column-major; grown once, never shrunk (the
  // solves allocate nothing after the first).
  std::vector<double> rhs_, solution_, residual_, work_, permuted_;
  Eigen::VectorXd D_;  // the factor's D

  // A body's velocities in v: 6, or a flexible body's 6 + m.
  int width(int i) const { return model_.flexible(i) ? 6 + model_.bodies[i].flexible->modes() : 6; }

  bool carries_armature(int i) const { return model_.joints[i].dof() > 0; }

  // left C_i (N_a): `left` applied to the parent's velocities as body i's
  // joint sees them (width(k) columns; on a flexible parent's node N_a
  // carries its elastic rates, on its frame they do not enter).
  template <class Left>
  OnParent on_parent(const Sweep& sweep, int i, const Left& left) const {
    const int k = model_.parent[i];
    const Eigen::Matrix<double, Eigen::Dynamic, 6, 0, 6, 6> block = left * velocity_transform(sweep.placement(i));
    if (const int a = model_.node_of(i); a >= 0) return block * sweep.node_matrix(k, a);
    OnParent padded = OnParent::Zero(block.rows(), width(k));
    padded.leftCols(6) = block;
    return padded;
  }

  void find_armature_slots() {
    for (int i = 0; i < model_.size(); ++i) {
      if (!carries_armature(i)) continue;
      const int v_i = velocity_row_[i], k = model_.parent[i];
      for (int c = 0; c < 6; ++c)
        for (int r = c; r < 6; ++r) armature_slot_.push_back(&K_.coeffRef(v_i + r, v_i + c));
      if (k == kBase) continue;
      const int v_k = velocity_row_[k];
      for (int c = 0; c < width(k); ++c)
        for (int r = c; r < width(k); ++r) armature_slot_.push_back(&K_.coeffRef(v_k + r, v_k + c));
      for (int r = 0; r < 6; ++r)
        for (int c = 0; c < width(k); ++c) armature_slot_.push_back(&K_.coeffRef(v_i + r, v_k + c));
    }
    for (int i : flexible_)
      for (int e = 6; e < width(i); ++e)
        armature_slot_.push_back(&K_.coeffRef(velocity_row_[i] + e, velocity_row_[i] + e));
    mass_only_.assign(K_.valuePtr(), K_.valuePtr() + K_.nonZeros());
  }

  // Joint i's armature E acts on its rates w = P (v_i - C_i v_k), P = (A^T
  // A)^-1 A^T the left inverse of its motion axes (the joint rows hold the
  // relative velocity to A's span): the quadratic form w^T E w in the
  // bodies' velocities, H = P^T E P on v_i, C^T H C on v_k, -H C between.
  void add_armature(const Sweep& sweep, const double* armature) {
    double** slot = armature_slot_.data();
    for (int i = 0; i < model_.size(); ++i) {
      if (!carries_armature(i)) continue;
      const int dof = model_.joints[i].dof(), k = model_.parent[i];
      const Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, 6> A = sweep.motion_axes(i).leftCols(dof);
      const Eigen::Matrix<double, Eigen::Dynamic, 6, 0, 6, 6> P = (A.transpose() * A).ldlt().solve(A.transpose());
      const Eigen::Map<const Eigen::VectorXd> E(armature + model_.first_velocity[i].value, dof);
      const Mat6 H = P.transpose() * E.asDiagonal() * P;
      for (int c = 0; c < 6; ++c)
        for (int r = c; r < 6; ++r) **slot++ += H(r, c);
      if (k == kBase) continue;
      const OnParent HC = on_parent(sweep, i, H);
      const OnParent C = on_parent(sweep, i, Mat6::Identity());
      const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, flexible::kMaxExtended, flexible::kMaxExtended>
          CHC = C.transpose() * HC;
      for (int c = 0; c < width(k); ++c)
        for (int r = c; r < width(k); ++r) **slot++ += CHC(r, c);
      for (int r = 0; r < 6; ++r)
        for (int c = 0; c < width(k); ++c) **slot++ -= HC(r, c);
    }
    for (int i : flexible_)
      for (int e = 0; e < width(i) - 6; ++e) **slot++ += armature[model_.first_elastic_velocity[i] + e];
  }

  static double norm(const std::vector<double>& x) {
    return Eigen::Map<const Eigen::VectorXd>(x.data(), static_cast<Eigen::Index>(x.size())).norm();
  }

  // x = K^-1 b by the factor P^T L D L^T P, on the factor's arrays (Eigen's
  // own solve makes temporaries on every call). The control law's two
  // columns go through L together, so each of its entries is read once.
  void apply_inverse(const std::vector<double>& b, std::vector<double>& x, int k) {
    if (k == 2) return apply_inverse_to<2>(b.data(), x.data());
    for (int c = 0; c < k; ++c) apply_inverse_to<1>(b.data() + c * K_.rows(), x.data() + c * K_.rows());
  }

  // K^-1 on k columns of b, interleaved while in the factor's order.
  template <int k>
  void apply_inverse_to(const double* b, double* x) {
    const SparseMatrix& L = ldlt_.matrixL().nestedExpression();
    const int n = static_cast<int>(L.rows());
    const int* Lp = L.outerIndexPtr();
    const int* Li = L.innerIndexPtr();
    const double* Lx = L.valuePtr();
    const auto& P = ldlt_.permutationP().indices();
    const double* D = D_.data();
    permuted_.resize(static_cast<std::size_t>(n) * k);
    double* w = permuted_.data();  // w[i * k + c]
    for (int c = 0; c < k; ++c)
      for (int i = 0; i < n; ++i) w[P[i] * k + c] = b[c * n + i];
    for (int j = 0; j < n; ++j) {  // L (unit diagonal)
      const double* wj = w + j * k;
      for (int p = Lp[j]; p < Lp[j + 1]; ++p) {
        double* wi = w + Li[p] * k;
        for (int c = 0; c < k; ++c) wi[c] -= Lx[p] * wj[c];
      }
    }
    for (int j = n - 1; j >= 0; --j) {  // D, then L^T
      double* wj = w + j * k;
      for (int c = 0; c < k; ++c) wj[c] /= D[j];
      for (int p = Lp[j]; p < Lp[j + 1]; ++p) {
        const double* wi = w + Li[p] * k;
        for (int c = 0; c < k; ++c) wj[c] -= Lx[p] * wi[c];
      }
    }
    for (int c = 0; c < k; ++c)
      for (int i = 0; i < n; ++i) x[c * n + i] = w[P[i] * k + c];
  }

  // residual = rhs - K solution, K stored as its lower triangle.
  void residual_of_K(int k) {
    const Eigen::Index n = K_.rows();
    Eigen::Map<Eigen::MatrixXd> r(residual_.data(), n, k);
    r = Eigen::Map<const Eigen::MatrixXd>(rhs_.data(), n, k);
    r.noalias() -= K_.selfadjointView<Eigen::Lower>() * Eigen::Map<const Eigen::MatrixXd>(solution_.data(), n, k);
  }
};

}  // namespace

std::unique_ptr<ClosureSolver> make_sparse_closure_solver(const Model& model, const std::vector<Loop>& loops,
                                                          const std::vector<LoopComponent>& components) {
  return std::make_unique<SparseClosureSolver>(model, loops, components, false);
}

std::unique_ptr<ArmatureClosureSolver> make_armature_closure_solver(const Model& model, const std::vector<Loop>& loops,
                                                                    const std::vector<LoopComponent>& components) {
  return std::make_unique<SparseClosureSolver>(model, loops, components, true);
}

}  // namespace unfurl::sim
