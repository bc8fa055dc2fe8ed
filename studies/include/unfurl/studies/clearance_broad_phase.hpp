// The broad phase of the clearance check: which pairs of bodies can come
// within a margin of each other at all over a run, from boxes that enclose
// each body's solids, so that the exact distances (FCL's) are asked only of
// those. Its cost grows with the bodies' near neighbours, not with the
// square of their number; boxes rather than spheres, because a stowed
// array's flat panels lie a few millimetres apart in a stack, where every
// panel's sphere takes in every other's.
//
// Between two samples a body lies in the union of its boxes at the two,
// grown by the centre's chord plus its radius times the angle it turned:
// twice the path length that the clearance check's own bounds allow a point
// (the chord plus the turn), so that an arc-shaped path is covered too.
// Pairs are found interval by interval by sweep and prune along the axis
// the bodies spread most along.
#pragma once

#include <cstdint>
#include <functional>
#include <unordered_set>
#include <utility>
#include <vector>

#include "unfurl/sim/kinematics.hpp"
#include "unfurl/sim/spatial.hpp"
#include "unfurl/studies/body_solids.hpp"

namespace unfurl::studies {

// An axis-aligned box in a body's frame about its solids, and the largest
// distance of their points from its centre.
struct BodyBox {
  sim::Vec3 centre = sim::Vec3::Zero(), half = sim::Vec3::Zero();
  double radius = -1;  // negative: no solids
};

BodyBox enclosing_box(const std::vector<Solid>& solids);

// The pairs of bodies that come within `margin` of each other at some time
// of a run, as a list (a table of every pair was N^2 for a 1000-stage
// array's 6,000 bodies).
class NearPairs {
 public:
  // pose(k, i): body i's pose at sample k of `samples` (base frame).
  using PoseAt = std::function<const sim::Pose&(std::size_t k, int i)>;
  NearPairs(const std::vector<BodyBox>& boxes, std::size_t samples, const PoseAt& pose, double margin);
  bool near(int a, int b) const;
  // Each pair once, (a, b) with a < b, in increasing order.
  const std::vector<std::pair<int, int>>& pairs() const { return pairs_; }

 private:
  struct Span {
    sim::Vec3 low, high;
  };
  // spans[i], indexed by body, for the bodies in `bodies_`; into `found`
  // each near pair as a << 32 | b, a < b.
  void sweep(const std::vector<Span>& spans, double margin, std::unordered_set<std::uint64_t>& found);

  std::vector<std::pair<int, int>> pairs_;
  std::vector<int> bodies_;  // those with solids
  std::vector<int> order_;   // scratch
};

}  // namespace unfurl::studies
