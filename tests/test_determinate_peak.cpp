// The determinate peak keeps only maxima the rigid model reaches
// (determinate_peak.hpp): a load rising into an indeterminate span, or
// falling out of one, counts with the indeterminate peak, unless a latch
// engaged where the run-up ends.
#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "determinate_peak.hpp"

namespace unfurl {
namespace {

// (value, determinate) at t = 0, 1, 2, ...
sim::DeterminatePeak observe(const std::vector<std::pair<double, bool>>& steps) {
  sim::DeterminatePeak peak;
  double t = 0;
  for (const auto& [x, determinate] : steps) {
    if (determinate)
      peak.determinate(x, t);
    else
      peak.indeterminate(x, t);
    t += 1;
  }
  return peak;
}

TEST(DeterminatePeak, AMaximumBetweenDeterminateStepsIsKept) {
  const sim::DeterminatePeak peak = observe({{1, true}, {5, true}, {2, true}, {3, true}});
  EXPECT_EQ(peak.settled().value, 5);
  EXPECT_EQ(peak.settled().t, 1);
  EXPECT_EQ(peak.over_indeterminate_steps().value, 0);
}

TEST(DeterminatePeak, ALoadRisingIntoAnIndeterminateSpanIsNotADeterminatePeak) {
  // A toggle: 4 is a maximum; 6, 9 run up to the span, where the rigid
  // load has no bound.
  const sim::DeterminatePeak peak = observe({{4, true}, {3, true}, {6, true}, {9, true}, {20, false}, {30, false}});
  EXPECT_EQ(peak.settled().value, 4);
  EXPECT_EQ(peak.over_indeterminate_steps().value, 30);
  const sim::DeterminatePeak cut = observe({{4, true}, {3, true}, {6, true}, {9, true}, {2, false}});
  EXPECT_EQ(cut.over_indeterminate_steps().value, 9);
  EXPECT_EQ(cut.over_indeterminate_steps().t, 3);
}

TEST(DeterminatePeak, ALoadFallingOutOfAnIndeterminateSpanCountsThereUntilItRises) {
  const sim::DeterminatePeak peak = observe({{2, true}, {1, true}, {7, false}, {8, true}, {5, true}, {3, true}, {4, true},
                                             {1, true}});
  EXPECT_EQ(peak.settled().value, 4);
  EXPECT_EQ(peak.settled().t, 6);
  EXPECT_EQ(peak.over_indeterminate_steps().value, 8);
}

TEST(DeterminatePeak, ALatchEngagingEndsTheRunUpBeforeIt) {
  // The load rises to the latch's engagement, where the steps turn
  // indeterminate: the model changed there, so 9 is the rigid model's.
  sim::DeterminatePeak peak = observe({{4, true}, {3, true}, {6, true}, {9, true}});
  peak.latched();
  peak.indeterminate(20, 4);
  EXPECT_EQ(peak.settled().value, 9);
  EXPECT_EQ(peak.settled().t, 3);
  EXPECT_EQ(peak.over_indeterminate_steps().value, 20);
}

TEST(DeterminatePeak, ARunThatEndsRisingKeepsItsLastLoadsAsDeterminate) {
  const sim::DeterminatePeak peak = observe({{1, true}, {2, true}, {3, true}});
  EXPECT_EQ(peak.settled().value, 3);
  EXPECT_EQ(peak.settled().t, 2);
}

}  // namespace
}  // namespace unfurl
