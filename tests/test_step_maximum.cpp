// A load's maximum between the steps (step_maximum.hpp): a ringing load
// sampled at uneven steps keeps its true maxima to O((h w)^3), where the
// largest step value falls short by up to (h w)^2 / 8.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <vector>

#include "step_maximum.hpp"

namespace unfurl {
namespace {

// x = 1 + cos(w t) at steps of h (1 + 0.4 sin(k)), maxima of 2 at
// t = 2 pi n / w: the worst of its maxima as the steps have them (the
// largest step next to each) and as interpolated.
struct Misses {
  double step = 0, vertex = 0, vertex_time = 0;
};
Misses sample_cosine(double w, double h) {
  Misses worst;
  sim::StepMaximum between;
  double t = 0.3, previous = 0, before = 0;
  for (int k = 0; k < 4000; ++k) {
    t += h * (1 + 0.4 * std::sin(k));
    const double x = 1 + std::cos(w * t);
    if (const std::optional<sim::Peak> v = between.observe(t, x)) {
      worst.step = std::max(worst.step, 2 - previous);
      worst.vertex = std::max(worst.vertex, std::abs(v->value - 2));
      const double nearest = std::round(w * v->t / (2 * M_PI)) * 2 * M_PI / w;
      worst.vertex_time = std::max(worst.vertex_time, std::abs(v->t - nearest) * w);
      EXPECT_GT(previous, before);
      EXPECT_GE(previous, x);
    }
    before = previous, previous = x;
  }
  return worst;
}

TEST(StepMaximum, ARingingLoadKeepsItsMaximaBetweenUnevenSteps) {
  for (const double hw : {0.3, 0.1, 0.03}) {
    const Misses worst = sample_cosine(1000, hw / 1000);
    EXPECT_GT(worst.step, 0.05 * hw * hw) << hw;  // what the steps alone miss
    EXPECT_LT(worst.vertex, 0.03 * hw * hw * hw) << hw;
    EXPECT_LT(worst.vertex_time, 0.1 * hw * hw) << hw;
  }
}

TEST(StepMaximum, ARiseOrAFallAloneHasNoMaximumBetween) {
  sim::StepMaximum between;
  for (int k = 0; k < 5; ++k) EXPECT_FALSE(between.observe(k, k * k)) << k;
  sim::StepMaximum falling;
  for (int k = 0; k < 5; ++k) EXPECT_FALSE(falling.observe(k, -k)) << k;
}

TEST(StepMaximum, ARestartNeedsThreeNewSteps) {
  sim::StepMaximum between;
  between.observe(0, 1);
  between.observe(1, 3);
  between.restart();
  EXPECT_FALSE(between.observe(2, 2));  // 1, 3, 2 would have one
  EXPECT_FALSE(between.observe(3, 5));
  const std::optional<sim::Peak> v = between.observe(4, 4);
  ASSERT_TRUE(v);
  EXPECT_GE(v->value, 5);
  EXPECT_GT(v->t, 2.5);
  EXPECT_LT(v->t, 4);
}

}  // namespace
}  // namespace unfurl
