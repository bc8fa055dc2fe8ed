#include "unfurl/sim/loop_components.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

namespace unfurl::sim {

namespace {

// The bodies on a loop's body's and image's paths to the base, in
// decreasing order; shared: above both (from where the paths meet up).
struct LoopPath {
  std::vector<int> bodies;
  std::vector<bool> shared;
};

LoopPath loop_path(const Model& model, const Loop& loop) {
  std::vector<int> from_body, from_image;  // decreasing: a parent's number is below its children's
  for (int i = loop.body; i >= 0; i = model.parent[i]) from_body.push_back(i);
  const auto on_body_path = [&](int i) {
    return std::binary_search(from_body.begin(), from_body.end(), i, std::greater<int>());
  };
  int meet = loop.image;
  for (; meet >= 0 && !on_body_path(meet); meet = model.parent[meet]) from_image.push_back(meet);
  std::vector<std::pair<int, bool>> on;
  bool shared = false;
  for (const int i : from_body) on.push_back({i, shared = shared || i == meet});
  for (const int i : from_image) on.push_back({i, false});
  std::sort(on.begin(), on.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  LoopPath path;
  for (const auto& [i, s] : on) path.bodies.push_back(i), path.shared.push_back(s);
  return path;
}

// Visits body i's coordinates: its joint's (unless `joint` is false) and
// its elastic ones.
template <class Visit>
void for_coordinates(const Model& model, int i, bool joint, Visit visit) {
  if (joint)
    for (int r = 0; r < model.joints[i].dof(); ++r) visit((model.first_velocity[i] + r).value);
  if (const int e = model.first_elastic_velocity[i]; e >= 0)
    for (int c = e; c < model.nv && model.body_of_elastic_velocity[c] == i; ++c) visit(c);
}

}  // namespace

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
  // Row (l, a) of eps T A equals (J^T e)^T = (A^T T^T eps^T e)^T: a backward
  // force pass per component, along the body's and the image's paths to the
  // base, where the row lies (passes over the whole tree made this O(N^2)
  // on large arrays, the most of building a 1000-stage one's dynamics).
  // The joints above both (a free bus's, say) move the two alike and cannot
  // open a closed loop; at the random samples, where the loop is open, they
  // would seem to, so their columns are left out.
  std::vector<LoopPath> path;
  for (const Loop& loop : loops) path.push_back(loop_path(model, loop));
  std::vector<double> row_norm(6 * L, 0.0);
  std::vector<Vec6> F(N, Vec6::Zero());
  std::vector<double> x(model.nv);
  for (const auto& q : samples) {
    sweep.set_configuration(q.data());
    for (int l = 0; l < L; ++l) {
      for (int a = 0; a < 6; ++a) {
        for (const int i : path[l].bodies) F[i].setZero();
        F[loops[l].body][a] = 1;
        F[loops[l].image][a] = -1;
        sweep.generalized_forces_along(path[l].bodies, F, x.data());
        double& norm = row_norm[6 * l + a];
        for (std::size_t k = 0; k < path[l].bodies.size(); ++k)
          for_coordinates(model, path[l].bodies[k], !path[l].shared[k],
                          [&](int c) { norm = std::max(norm, std::abs(x[c]) / (a < 3 ? length : 1.0)); });
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
