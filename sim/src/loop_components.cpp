#include "unfurl/sim/loop_components.hpp"

#include <cmath>
#include <random>

namespace unfurl::sim {

std::vector<LoopComponent> active_loop_components(const Model& model, const std::vector<Loop>& loops,
                                                  const std::vector<double>& q0, double length, Sweep& sweep) {
  const int N = model.size();
  const int L = static_cast<int>(loops.size());
  std::vector<std::vector<double>> samples{q0};
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI);
  // Random joint positions; flexible bodies undeformed, as where a loop
  // closes (an elastic coordinate of the size of an angle is a deflection
  // of metres).
  for (int s = 0; s < 3; ++s) {
    std::vector<double> q(model.nq, 0.0);
    for (int c = 0; c < model.nq; ++c)
      if (model.joint_of_position[c] >= 0) q[c] = angle(rng);
    samples.push_back(q);
  }
  // Row (l, a) of eps T A equals (J^T e)^T = (A^T T^T eps^T e)^T: one
  // backward force pass per component. The joints above both the body and
  // its image (a free bus's, say) move the two alike and cannot open a
  // closed loop; at the random samples, where the loop is open, they would
  // seem to, so their columns are left out.
  std::vector<std::vector<bool>> shared(L, std::vector<bool>(model.nv, false));
  for (int l = 0; l < L; ++l) {
    std::vector<bool> above_body(N, false);
    for (int i = loops[l].body; i >= 0; i = model.parent[i]) above_body[i] = true;
    for (int i = loops[l].image; i >= 0; i = model.parent[i])
      if (above_body[i])
        for (int r = 0; r < model.joints[i].dof(); ++r) shared[l][(model.first_velocity[i] + r).value] = true;
  }
  std::vector<double> row_norm(6 * L, 0.0);
  std::vector<Vec6> F(N);
  std::vector<double> x(model.nv);
  for (const auto& q : samples) {
    sweep.set_configuration(q.data());
    for (int l = 0; l < L; ++l) {
      for (int a = 0; a < 6; ++a) {
        for (Vec6& f : F) f.setZero();
        F[loops[l].body][a] = 1;
        F[loops[l].image][a] = -1;
        sweep.generalized_forces(F, x.data());
        for (int c = 0; c < model.nv; ++c)
          if (!shared[l][c]) row_norm[6 * l + a] = std::max(row_norm[6 * l + a], std::abs(x[c]) / (a < 3 ? length : 1.0));
      }
    }
  }
  double largest = 0;
  for (double r : row_norm) largest = std::max(largest, r);
  std::vector<LoopComponent> active;
  for (int l = 0; l < L; ++l)
    for (int a = 0; a < 6; ++a)
      if (row_norm[6 * l + a] > 1e-9 * largest) active.push_back({l, a});
  return active;
}

void residual_rate(const std::vector<Loop>& loops, const std::vector<LoopComponent>& components,
                   const std::vector<Vec6>& v, double* g_dot) {
  for (std::size_t c = 0; c < components.size(); ++c) {
    const LoopComponent& lc = components[c];
    g_dot[c] = v[loops[lc.loop].body][lc.axis] - v[loops[lc.loop].image][lc.axis];
  }
}

void add_loop_forces(const std::vector<Loop>& loops, const std::vector<LoopComponent>& components,
                     const double* lambda, double scale, std::vector<Vec6>& F) {
  for (std::size_t c = 0; c < components.size(); ++c) {
    const LoopComponent& lc = components[c];
    F[loops[lc.loop].body][lc.axis] += scale * lambda[c];
    F[loops[lc.loop].image][lc.axis] -= scale * lambda[c];
  }
}

void geometric_gap(const std::vector<Loop>& loops, const std::vector<LoopComponent>& components,
                   const std::vector<Pose>& poses, double* g) {
  int loop = -1;
  Vec6 mismatch;
  for (std::size_t c = 0; c < components.size(); ++c) {
    const LoopComponent& lc = components[c];
    if (lc.loop != loop) {
      loop = lc.loop;
      mismatch = closure_mismatch(poses[loops[loop].body], poses[loops[loop].image]);
    }
    g[c] = mismatch[lc.axis];
  }
}

}  // namespace unfurl::sim
