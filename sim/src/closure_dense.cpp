// The dense closure solver: W formed by the sweep's batched passes, then
// R = W + delta I by Cholesky. Everything lives in fixed-capacity matrices.
#include <Eigen/Cholesky>
#include <stdexcept>
#include <string>

#include "unfurl/sim/closure_solver.hpp"
#include "unfurl/sim/mobility.hpp"

namespace unfurl::sim {

namespace {

class DenseClosureSolver : public ClosureSolver {
 public:
  DenseClosureSolver(const Model& model, const std::vector<Loop>& loops, const std::vector<LoopComponent>& components)
      : mobility_(model, loops, components), m_(static_cast<int>(components.size())) {
    if (m_ > kMaxDenseComponents)
      throw std::invalid_argument("the dense loop-closure solver handles at most " +
                                  std::to_string(kMaxDenseComponents) + " loop components; this scene has " +
                                  std::to_string(m_) + " (use regulator.solver: sparse)");
    R_.resize(m_, m_);
  }

  bool factorize(const Sweep& sweep, const double* delta) override {
    W_ = &mobility_.matrix(sweep);
    R_ = *W_;
    R_.diagonal() += Eigen::Map<const Eigen::VectorXd>(delta, m_);
    llt_.compute(R_);
    return llt_.info() == Eigen::Success;
  }

  const LoopMatrix* mobility() const override { return W_; }

  void solve(const double* B, double* X, int columns, bool) override {
    for (int c = 0; c < columns; ++c)
      Eigen::Map<Eigen::VectorXd>(X + c * m_, m_) = llt_.solve(Eigen::Map<const Eigen::VectorXd>(B + c * m_, m_));
  }

 private:
  Mobility mobility_;
  int m_;
  const LoopMatrix* W_ = nullptr;  // mobility_'s, as the last factorize() formed it
  LoopMatrix R_;
  Eigen::LLT<LoopMatrix> llt_;
};

}  // namespace

std::unique_ptr<ClosureSolver> make_dense_closure_solver(const Model& model, const std::vector<Loop>& loops,
                                                         const std::vector<LoopComponent>& components) {
  return std::make_unique<DenseClosureSolver>(model, loops, components);
}

std::unique_ptr<ClosureSolver> make_closure_solver(ClosureSolverKind kind, const Model& model,
                                                   const std::vector<Loop>& loops,
                                                   const std::vector<LoopComponent>& components) {
  const int m = static_cast<int>(components.size());
  const bool dense =
      kind == ClosureSolverKind::dense || (kind == ClosureSolverKind::automatic && m <= kMaxDenseComponents);
  return dense ? make_dense_closure_solver(model, loops, components)
               : make_sparse_closure_solver(model, loops, components);
}

}  // namespace unfurl::sim
