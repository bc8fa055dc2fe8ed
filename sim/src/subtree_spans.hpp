// Each body's place in a depth-first order of the tree, and where its
// subtree's places end: body b is in body i's subtree (moved by joint i)
// when first[i] <= first[b] < end[i].
#pragma once

#include <utility>
#include <vector>

#include "unfurl/sim/model.hpp"

namespace unfurl::sim {

class SubtreeSpans {
 public:
  explicit SubtreeSpans(const Model& model) : first_(model.size()), end_(model.size()) {
    std::vector<std::pair<int, bool>> to_visit;  // (body, whether its subtree is done)
    for (int i = model.size() - 1; i >= 0; --i)
      if (model.parent[i] == kBase) to_visit.push_back({i, false});
    int next = 0;
    while (!to_visit.empty()) {
      const auto [i, done] = to_visit.back();
      to_visit.pop_back();
      if (done) {
        end_[i] = next;
        continue;
      }
      first_[i] = next++;
      to_visit.push_back({i, true});
      for (int child : model.children[i]) to_visit.push_back({child, false});
    }
  }
  bool contains(int i, int b) const { return first_[i] <= first_[b] && first_[b] < end_[i]; }

 private:
  std::vector<int> first_, end_;
};

}  // namespace unfurl::sim
