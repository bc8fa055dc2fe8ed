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
// With eps > 0 the matrix is quasi-definite and LDL^T needs no pivoting for
// any ordering; eps itself is removed by refining against eps = 0, which
// converges in one or two more solves to round-off.
#include <Eigen/OrderingMethods>
#include <Eigen/QR>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include "unfurl/sim/closure_solver.hpp"

namespace unfurl {

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

class SparseClosureSolver : public ClosureSolver {
 public:
  SparseClosureSolver(const Model& model, const std::vector<Loop>& loops, const std::vector<LoopComponent>& components)
      : model_(model), m_(static_cast<int>(components.size())) {
    const int N = model.size();
    double total_mass = 0;
    for (const Body& b : model.bodies) total_mass += b.mass;
    eps_ = 1e-10 * N / total_mass;

    int rows = 6 * N;
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
      const Mat6 M = model.bodies[i].spatial_mass();
      for (int c = 0; c < 6; ++c)
        for (int r = c; r < 6; ++r) entries.emplace_back(6 * i + r, 6 * i + c, M(r, c));
      const int k = model.parent[i];
      for (int r = 0; r < N_[i].cols(); ++r) {
        for (int c = 0; c < 6; ++c) {
          entries.emplace_back(joint_row_[i] + r, 6 * i + c, N_[i](c, r));
          if (k != kBase) entries.emplace_back(joint_row_[i] + r, 6 * k + c, 0.0);
        }
        entries.emplace_back(joint_row_[i] + r, joint_row_[i] + r, -eps_);
      }
    }
    for (int c = 0; c < m_; ++c) {
      const LoopComponent& lc = components[c];
      entries.emplace_back(loop_row_ + c, 6 * loops[lc.loop].body + lc.axis, 1.0);
      entries.emplace_back(loop_row_ + c, 6 * loops[lc.loop].image + lc.axis, -1.0);
      entries.emplace_back(loop_row_ + c, loop_row_ + c, 0.0);
    }
    K_.resize(rows, rows);
    K_.setFromTriplets(entries.begin(), entries.end());

    // Where the configuration-dependent values sit: -N_i^T C_i, and -delta.
    for (int i = 0; i < N; ++i) {
      if (model.parent[i] == kBase) continue;
      for (int r = 0; r < N_[i].cols(); ++r)
        for (int c = 0; c < 6; ++c) parent_block_.push_back(&K_.coeffRef(joint_row_[i] + r, 6 * model.parent[i] + c));
    }
    for (int c = 0; c < m_; ++c) delta_slot_.push_back(&K_.coeffRef(loop_row_ + c, loop_row_ + c));
    for (int i = 0; i < N; ++i) {
      if (!model.joints[i].has_varying_axes()) continue;
      varying_.push_back(i);
      for (int r = 0; r < N_[i].cols(); ++r)
        for (int c = 0; c < 6; ++c) varying_block_.push_back(&K_.coeffRef(joint_row_[i] + r, 6 * i + c));
    }

    ldlt_.analyzePattern(K_);
  }

  bool factorize(const Sweep& sweep, double delta) override {
    double** varying_slot = varying_block_.data();
    for (int i : varying_) {
      N_[i] = constrained_directions(sweep.motion_axes(i), model_.joints[i].dof());
      for (int r = 0; r < N_[i].cols(); ++r)
        for (int c = 0; c < 6; ++c) **varying_slot++ = N_[i](c, r);
    }
    double** slot = parent_block_.data();
    for (int i = 0; i < model_.size(); ++i) {
      if (model_.parent[i] == kBase) continue;
      const Eigen::Matrix<double, Eigen::Dynamic, 6, 0, 6, 6> block =
          -N_[i].transpose() * velocity_transform(sweep.placement(i));
      for (int r = 0; r < block.rows(); ++r)
        for (int c = 0; c < 6; ++c) **slot++ = block(r, c);
    }
    for (double* d : delta_slot_) *d = -delta;
    ldlt_.factorize(K_);
    return ldlt_.info() == Eigen::Success;
  }

  void solve(const double* B, double* X, int columns) override {
    const int n = static_cast<int>(K_.rows()), v_rows = 6 * model_.size(), joint_rows = loop_row_ - v_rows;
    rhs_.setZero(n, columns);
    rhs_.bottomRows(m_) = Eigen::Map<const Eigen::MatrixXd>(B, m_, columns);
    solution_ = ldlt_.solve(rhs_);
    // Near a branch point R is as ill-conditioned as lambda_max / delta;
    // a few passes reach 1e-12 of the right-hand side there.
    const double target = 1e-12 * rhs_.norm();
    for (int pass = 0; pass < 5; ++pass) {
      // The residual of the unregularized matrix: K_0 = K + eps on the joint rows.
      residual_.noalias() = rhs_ - K_.selfadjointView<Eigen::Lower>() * solution_;
      residual_.middleRows(v_rows, joint_rows) -= eps_ * solution_.middleRows(v_rows, joint_rows);
      if (residual_.norm() <= target) break;
      solution_ += ldlt_.solve(residual_);
    }
    Eigen::Map<Eigen::MatrixXd>(X, m_, columns) = -solution_.bottomRows(m_);
  }

 private:
  const Model& model_;
  int m_;
  double eps_;
  std::vector<int> joint_row_;
  std::vector<Directions> N_;
  std::vector<int> varying_;            // joints whose A (and N) turn with q: universal
  std::vector<double*> varying_block_;  // their N_i^T entries
  int loop_row_ = 0;
  SparseMatrix K_;
  std::vector<double*> parent_block_, delta_slot_;
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt_;
  Eigen::MatrixXd rhs_, solution_, residual_;
};

}  // namespace

std::unique_ptr<ClosureSolver> make_sparse_closure_solver(const Model& model, const std::vector<Loop>& loops,
                                                          const std::vector<LoopComponent>& components) {
  return std::make_unique<SparseClosureSolver>(model, loops, components);
}

}  // namespace unfurl
