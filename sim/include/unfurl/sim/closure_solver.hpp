// Solves with R = W + diag(delta), W the loop components' mobility (mobility.hpp)
// at the sweep's configuration: the one linear algebra the full-matrix
// regulator gains need. Two ways to the same numbers:
// - dense: W from m batched passes of the sweep, then a Cholesky of R.
//   O(N m + m^3), allocation-free; the fastest for a few loops.
// - sparse: R^-1 b read off the loop-closure system over the primary graph
//   (body velocities, joint reactions, loop forces), factored by a sparse
//   LDL^T. O(N) for mechanisms whose loops are chained (a ladder such as the
//   pantograph), whatever the number of loops. Eigen's factorization
//   allocates its work space on each call.
#pragma once

#include <memory>
#include <vector>

#include "unfurl/sim/loop_components.hpp"
#include "unfurl/sim/mobility.hpp"
#include "unfurl/sim/regulator_settings.hpp"
#include "unfurl/sim/sweep.hpp"

namespace unfurl::sim {

class ClosureSolver {
 public:
  virtual ~ClosureSolver() = default;
  // Factors R = W + diag(delta) (one entry per component) at the sweep's
  // configuration. False if it could not.
  virtual bool factorize(const Sweep& sweep, const double* delta) = 0;
  // X = R^-1 B for the last factorization, B and X m x columns,
  // column-major (distinct arrays). Without refinement the sparse solver
  // stops after its first pass (about 1e-5 of B off near a branch point):
  // a smooth, linear stand-in for R^-1, enough for a Jacobian's product.
  virtual void solve(const double* B, double* X, int columns = 1, bool refine = true) = 0;
  // W of the last factorize() where the solver formed it (the dense one
  // does), so that an analysis at that configuration need not form it again.
  virtual const LoopMatrix* mobility() const { return nullptr; }
};

// automatic: the dense solver while it can (it is the faster up to its
// kMaxDenseComponents: 2.7 us per body at 48 components, the sparse one
// 3.9 to 5.2 us per body from 100 to 10,000 bodies; docs/scaling), else
// the sparse one.
std::unique_ptr<ClosureSolver> make_closure_solver(ClosureSolverKind kind, const Model& model,
                                                   const std::vector<Loop>& loops,
                                                   const std::vector<LoopComponent>& components);

std::unique_ptr<ClosureSolver> make_dense_closure_solver(const Model& model, const std::vector<Loop>& loops,
                                                         const std::vector<LoopComponent>& components);
std::unique_ptr<ClosureSolver> make_sparse_closure_solver(const Model& model, const std::vector<Loop>& loops,
                                                          const std::vector<LoopComponent>& components);

}  // namespace unfurl::sim
