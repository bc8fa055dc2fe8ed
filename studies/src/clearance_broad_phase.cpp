#include "unfurl/studies/clearance_broad_phase.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace unfurl::studies {

namespace {

using Kind = sim::CollisionShape::Kind;

// A sphere's or a cylinder's enclosing sphere's radius, about its offset.
double round_radius(const Solid& s) { return s.kind == Kind::sphere ? s.radius : std::hypot(s.radius, 0.5 * s.length); }

// Each solid's extent as points with a radius about them (body frame): a
// primitive's corners (a box's eight; a sphere's and a cylinder's centre
// with their radius), a mesh's vertices.
template <typename Visit>
void for_each_extent(const std::vector<Solid>& solids, Visit visit) {
  for (const Solid& s : solids) {
    if (s.kind == Kind::box) {
      for (int c = 0; c < 8; ++c) {
        const sim::Vec3 corner(c & 1 ? 0.5 : -0.5, c & 2 ? 0.5 : -0.5, c & 4 ? 0.5 : -0.5);
        visit(s.offset + s.rotation * corner.cwiseProduct(s.size), 0.0);
      }
    } else if (s.kind != Kind::mesh) {
      visit(s.offset, round_radius(s));
    } else {
      for (const sim::Vec3& v : s.mesh.vertices) visit(s.offset + s.rotation * v, 0.0);
    }
  }
}

}  // namespace

BodyBox enclosing_box(const std::vector<Solid>& solids) {
  Eigen::AlignedBox3d box;
  for_each_extent(solids, [&](const sim::Vec3& p, double r) {
    box.extend(p - sim::Vec3::Constant(r));
    box.extend(p + sim::Vec3::Constant(r));
  });
  BodyBox out;
  if (box.isEmpty()) return out;
  out.centre = box.center();
  out.half = 0.5 * box.sizes();
  out.radius = 0;
  for_each_extent(solids, [&](const sim::Vec3& p, double r) { out.radius = std::max(out.radius, (p - out.centre).norm() + r); });
  return out;
}

NearPairs::NearPairs(const std::vector<BodyBox>& boxes, std::size_t samples, const PoseAt& pose, double margin) {
  for (std::size_t i = 0; i < boxes.size(); ++i)
    if (boxes[i].radius >= 0) bodies_.push_back(static_cast<int>(i));
  // Body i's box at sample k in the base frame, and its centre.
  const auto placed = [&](std::size_t k, int i, sim::Vec3& centre) {
    const sim::Pose& p = pose(k, i);
    centre = p.position + p.rotation.transpose() * boxes[i].centre;
    const sim::Vec3 half = p.rotation.transpose().cwiseAbs() * boxes[i].half;
    return Span{centre - half, centre + half};
  };
  std::vector<Span> spans(boxes.size());
  std::unordered_set<std::uint64_t> found;
  sim::Vec3 c0, c1;
  if (samples == 1) {
    for (int i : bodies_) spans[i] = placed(0, i, c0);
    sweep(spans, margin, found);
  }
  for (std::size_t k = 1; k < samples; ++k) {
    for (int i : bodies_) {
      const Span a = placed(k - 1, i, c0), b = placed(k, i, c1);
      const double turn = Eigen::AngleAxisd(pose(k, i).rotation * pose(k - 1, i).rotation.transpose()).angle();
      const sim::Vec3 grow = sim::Vec3::Constant((c1 - c0).norm() + boxes[i].radius * turn);
      spans[i] = {a.low.cwiseMin(b.low) - grow, a.high.cwiseMax(b.high) + grow};
    }
    sweep(spans, margin, found);
  }
  pairs_.reserve(found.size());
  for (const std::uint64_t key : found)
    pairs_.push_back({static_cast<int>(key >> 32), static_cast<int>(key & 0xffffffffu)});
  std::sort(pairs_.begin(), pairs_.end());
}

bool NearPairs::near(int a, int b) const {
  return std::binary_search(pairs_.begin(), pairs_.end(), std::pair{std::min(a, b), std::max(a, b)});
}

// Every pair of boxes within `margin` of each other along all three axes
// (so their solids are, at least): sorted by their low end along the axis
// their centres spread most along (an array hinged about x spreads along y
// or z, its panels all overlapping in x), each is compared with those that
// begin before it ends.
void NearPairs::sweep(const std::vector<Span>& spans, double margin, std::unordered_set<std::uint64_t>& found) {
  Eigen::AlignedBox3d centres;
  for (int i : bodies_) centres.extend(0.5 * (spans[i].low + spans[i].high));
  int axis = 0;
  if (!centres.isEmpty()) centres.sizes().maxCoeff(&axis);
  order_ = bodies_;
  std::sort(order_.begin(), order_.end(), [&](int a, int b) { return spans[a].low[axis] < spans[b].low[axis]; });
  for (std::size_t u = 0; u < order_.size(); ++u) {
    const Span& a = spans[order_[u]];
    for (std::size_t v = u + 1; v < order_.size() && spans[order_[v]].low[axis] <= a.high[axis] + margin; ++v) {
      const Span& b = spans[order_[v]];
      if (((b.low - a.high).array() > margin).any() || ((a.low - b.high).array() > margin).any()) continue;
      const auto [low, high] = std::minmax(order_[u], order_[v]);
      found.insert(static_cast<std::uint64_t>(low) << 32 | static_cast<std::uint64_t>(high));
    }
  }
}

}  // namespace unfurl::studies
