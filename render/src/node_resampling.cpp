#include "node_resampling.hpp"

#include <algorithm>
#include <cmath>

namespace unfurl::render {

std::vector<NodeMotion> resample_along(std::vector<StationMotion> stations, double from, double length, int n) {
  std::sort(stations.begin(), stations.end(), [](const StationMotion& x, const StationMotion& y) { return x.at < y.at; });
  std::vector<StationMotion> merged;
  for (std::size_t k = 0; k < stations.size();) {
    std::size_t end = k;
    NodeMotion sum = NodeMotion::Zero();
    while (end < stations.size() && stations[end].at <= stations[k].at + 1e-9 * length) sum += stations[end++].u;
    merged.push_back({stations[k].at, sum / static_cast<double>(end - k)});
    k = end;
  }
  std::vector<NodeMotion> out(n, merged.empty() ? NodeMotion::Zero() : merged.front().u);
  if (merged.size() < 2) return out;
  std::size_t s = 0;
  for (int k = 0; k < n; ++k) {
    const double x = from + length * k / (n - 1);
    while (s + 2 < merged.size() && merged[s + 1].at < x) ++s;
    const double x0 = merged[s].at, x1 = merged[s + 1].at;
    const double f = std::clamp((x - x0) / (x1 - x0), 0.0, 1.0);
    out[k] = (1 - f) * merged[s].u + f * merged[s + 1].u;
  }
  return out;
}

std::vector<NodeMotion> resample_over(const std::vector<ScatteredMotion>& nodes, const Eigen::Vector2d& from,
                                      const Eigen::Vector2d& size, int n) {
  const double spacing = std::sqrt(size.prod() / static_cast<double>(nodes.size()));
  const double radius = 2.5 * spacing, floor = 1e-12 * size.squaredNorm();
  std::vector<NodeMotion> out(n * n, NodeMotion::Zero());
  for (int r = 0; r < n; ++r)
    for (int k = 0; k < n; ++k) {
      const Eigen::Vector2d x = from + Eigen::Vector2d(size.x() * k / (n - 1), size.y() * r / (n - 1));
      NodeMotion sum = NodeMotion::Zero();
      double total = 0;
      for (const ScatteredMotion& node : nodes) {
        const double d = (node.at - x).norm();
        if (d >= radius) continue;
        const double fade = 1 - d / radius, weight = fade * fade / (d * d + floor);
        sum += weight * node.u;
        total += weight;
      }
      if (total > 0) out[r * n + k] = sum / total;
    }
  return out;
}

}  // namespace unfurl::render
