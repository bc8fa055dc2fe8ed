#include "unfurl/studies/stability_verdicts.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace unfurl::studies {

bool as_expected(const StabilityResult& r) {
  if (r.spec.probe)
    return r.status == sim::RunStatus::finished || (r.status == sim::RunStatus::failed && !r.failed_check.empty());
  if (r.spec.expected_check.empty()) return r.status == sim::RunStatus::finished;
  return r.status == sim::RunStatus::failed && r.failed_check == r.spec.expected_check;
}

double closing_time(const sim::Trajectory& tr, double level) {
  for (const sim::Sample& s : tr.samples)
    if (largest_gap(s) < level) return s.t;
  return std::numeric_limits<double>::quiet_NaN();
}

double largest_gap(const sim::Sample& s) {
  double r = 0;
  for (const sim::ClosureError& c : s.closure) r = std::max({r, c.distance, c.angle});
  return r;
}

std::vector<std::string> describe_branches(const sim::Scene& scene, const sim::Trajectory& trajectory) {
  const sim::Model& model = scene.model;
  std::vector<std::string> out;
  if (trajectory.empty()) return out;
  const sim::Sample &first = trajectory.samples.front(), &last = trajectory.samples.back();
  for (const sim::Loop& loop : scene.loops) {
    // The joints from the split body and from its image up to their common
    // ancestor: the loop's path through the tree.
    std::vector<int> a, b;
    for (int i = loop.body; i != sim::kBase; i = model.parent[i]) a.push_back(i);
    for (int i = loop.image; i != sim::kBase; i = model.parent[i]) b.push_back(i);
    while (!a.empty() && !b.empty() && a.back() == b.back()) a.pop_back(), b.pop_back();
    a.insert(a.end(), b.rbegin(), b.rend());
    std::string opened, held, between;
    for (int i : a) {
      const int c = model.first_position[i].value;
      if (c < 0) continue;
      const double moved = std::abs(last.y[c] - first.y[c]);
      std::string& list = moved > 0.1 ? opened : moved < 0.01 ? held : between;
      list += (list.empty() ? "" : ", ") + model.joints[i].name;
    }
    std::string note = "loop " + loop.name + ": ";
    note += held.empty() ? "every joint of the loop moved (the lazy-tongs path)" : "held " + held + "; opened " + (opened.empty() ? "none" : opened);
    if (!between.empty()) note += "; moved a little " + between;
    out.push_back(note);
  }
  return out;
}

}  // namespace unfurl::studies
