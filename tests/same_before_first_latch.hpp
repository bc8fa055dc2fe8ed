// For settings that act from the first latch's engagement on (a stability
// limit's detection, an order cap): the deployment must be left as it was.
#pragma once

#include <gtest/gtest.h>

#include "unfurl/sim/simulation.hpp"

namespace unfurl::test {

// `other`'s samples before `plain`'s first latch event equal `plain`'s bit
// for bit.
inline void expect_the_same_before_the_first_latch(const sim::RunResult& plain, const sim::RunResult& other) {
  ASSERT_FALSE(plain.trajectory.events.empty());
  const double latch = plain.trajectory.events.front().t;
  ASSERT_EQ(plain.trajectory.samples.size(), other.trajectory.samples.size());
  for (std::size_t k = 0; k < plain.trajectory.samples.size() && plain.trajectory.samples[k].t < latch; ++k)
    ASSERT_EQ(plain.trajectory.samples[k].y, other.trajectory.samples[k].y) << "t = " << plain.trajectory.samples[k].t;
}

}  // namespace unfurl::test
