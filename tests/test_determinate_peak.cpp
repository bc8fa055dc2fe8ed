// The determinate peak keeps only maxima the rigid model reaches
// (determinate_peak.hpp): a load rising into an indeterminate span, or
// falling out of one, counts with the indeterminate peak, unless a latch
// engaged where the run-up or the fall ends. A maximum between three
// determinate steps counts at the vertex of the parabola through them
// (StepMaximum).
#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "determinate_peak.hpp"

namespace unfurl {
namespace {

// (value, determinate) at t = 0, 1, 2, ... after those already observed.
void observe(sim::DeterminatePeak& peak, const std::vector<std::pair<double, bool>>& steps, double t = 0) {
  for (const auto& [x, determinate] : steps) peak.observe(x, t++, determinate);
}

sim::DeterminatePeak observed(const std::vector<std::pair<double, bool>>& steps) {
  sim::DeterminatePeak peak;
  observe(peak, steps);
  return peak;
}

TEST(DeterminatePeak, AMaximumBetweenDeterminateStepsIsKept) {
  const sim::DeterminatePeak peak = observed({{1, true}, {5, true}, {2, true}, {3, true}});
  EXPECT_DOUBLE_EQ(peak.settled(true).value, 5 + 1.0 / 56);  // 1, 5, 2's parabola
  EXPECT_DOUBLE_EQ(peak.settled(true).t, 1 + 1.0 / 14);
  EXPECT_EQ(peak.over_indeterminate_steps(true).value, 0);
}

TEST(DeterminatePeak, ALoadRisingIntoAnIndeterminateSpanIsNotADeterminatePeak) {
  // A toggle: 4 is a maximum; 6, 9 run up to the span, where the rigid
  // load has no bound.
  const sim::DeterminatePeak peak = observed({{4, true}, {3, true}, {6, true}, {9, true}, {20, false}, {30, false}});
  EXPECT_EQ(peak.settled(true).value, 4);
  EXPECT_EQ(peak.over_indeterminate_steps(true).value, 30);
  const sim::DeterminatePeak cut = observed({{4, true}, {3, true}, {6, true}, {9, true}, {2, false}});
  EXPECT_EQ(cut.over_indeterminate_steps(true).value, 9);
  EXPECT_EQ(cut.over_indeterminate_steps(true).t, 3);
}

TEST(DeterminatePeak, ALoadFallingOrFlatIntoASpanStaysDeterminate) {
  const sim::DeterminatePeak falling = observed({{5, true}, {3, true}, {1, false}});
  EXPECT_EQ(falling.settled(true).value, 5);
  EXPECT_EQ(falling.over_indeterminate_steps(true).value, 1);
  const sim::DeterminatePeak flat = observed({{2, true}, {4, true}, {4, true}, {1, false}});
  EXPECT_DOUBLE_EQ(flat.settled(true).value, 4.25);  // 2, 4, 4's parabola, at t = 1.5
  EXPECT_EQ(flat.over_indeterminate_steps(true).value, 1);
}

TEST(DeterminatePeak, ALoadFallingOutOfAnIndeterminateSpanCountsThereUntilItRises) {
  const sim::DeterminatePeak peak =
      observed({{2, true}, {1, true}, {7, false}, {8, true}, {5, true}, {3, true}, {4, true}, {1, true}});
  EXPECT_DOUBLE_EQ(peak.settled(true).value, 4.125);  // 3, 4, 1's parabola
  EXPECT_DOUBLE_EQ(peak.settled(true).t, 5.75);
  EXPECT_EQ(peak.over_indeterminate_steps(true).value, 8);
}

TEST(DeterminatePeak, ALatchEngagingEndsTheRunUpOrTheFallBeforeIt) {
  // The load rises to the latch's engagement, where the steps turn
  // indeterminate: the model changed there, so 9 is the rigid model's.
  sim::DeterminatePeak rising = observed({{4, true}, {3, true}, {6, true}, {9, true}});
  rising.latched();
  observe(rising, {{20, false}}, 4);
  EXPECT_EQ(rising.settled(true).value, 9);
  EXPECT_EQ(rising.settled(true).t, 3);
  EXPECT_EQ(rising.over_indeterminate_steps(true).value, 20);
  // Falling out of a span, a latch's impact is the rigid model's.
  sim::DeterminatePeak falling = observed({{20, false}, {8, true}});
  falling.latched();
  observe(falling, {{6, true}, {3, true}}, 2);
  EXPECT_EQ(falling.settled(true).value, 6);
  EXPECT_EQ(falling.over_indeterminate_steps(true).value, 20);
}

TEST(DeterminatePeak, ARunThatEndsRisingKeepsItsLastLoadsUnlessItFailedThere) {
  const sim::DeterminatePeak peak = observed({{1, true}, {2, true}, {3, true}});
  EXPECT_EQ(peak.settled(true).value, 3);
  EXPECT_EQ(peak.settled(true).t, 2);
  EXPECT_EQ(peak.settled(false).value, 0);
  EXPECT_EQ(peak.over_indeterminate_steps(false).value, 3);
}

}  // namespace
}  // namespace unfurl
