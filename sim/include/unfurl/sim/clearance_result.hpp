// What a clearance check gives (studies/clearance.hpp computes it): the
// closest approach of the pairs of bodies not jointed together that came
// near each other (the rest certified farther apart), and when any two
// touched or went through each other. Plain data, for the summary, files,
// plots and the workbench's timeline.
#pragma once

#include <string>
#include <vector>

namespace unfurl::sim {

// A pair's closest approach over the run: the distance between their solids
// (m; 0 where they touch or interpenetrate) and when.
struct PairClearance {
  std::string body_a, body_b;
  double distance = 0;
  double t = 0;
};

// A span of the run in which two bodies touched or interpenetrated, from the
// first to the last time seen so (a contact seen between two samples has
// t_begin == t_end).
struct ClearanceContact {
  std::string body_a, body_b;
  double t_begin = 0, t_end = 0;
  bool at_start = false;  // already at the run's first sample (the stowed geometry overlaps)
};

struct Clearance {
  // The pairs measured, closest first (at equal distances, as touching
  // pairs are, the earliest first): every pair that came within
  // `listed_within` (m) of each other at some time, and some farther ones
  // (their swept bounding boxes came that near). The other `pairs_beyond`
  // pairs stayed farther apart than `listed_within` throughout (their
  // boxes did), and so farther than the closest pair: a tenth of the
  // largest body's reach, doubled until it holds the closest pair;
  // infinite when every pair was measured.
  std::vector<PairClearance> pairs;
  double listed_within = 0;
  long pairs_beyond = 0;
  std::vector<ClearanceContact> contacts;  // by time
  std::vector<std::string> without_solid;  // bodies left out: no mesh and no collision shapes
  std::vector<std::string> unread;         // meshes that could not be had, and why
  int samples = 0;                         // the run's samples checked
  long distance_queries = 0;               // pairs measured (the rest were certified clear)
  double wall_time_s = 0;

  // The closest pair, or nullptr when no pair was checked.
  const PairClearance* closest() const { return pairs.empty() ? nullptr : &pairs.front(); }
  bool clear() const { return contacts.empty(); }
};

}  // namespace unfurl::sim
