// The choice of threads a run makes as it goes (simulation/thread_chooser.hpp), on given times:
// a busy machine's threads slower than one thread are given up, and taken again when the
// machine is free.
#include <gtest/gtest.h>

#include "simulation/thread_chooser.hpp"

namespace talus {
namespace {

// Times a stretch of `steps` at `per_step` s each for the threads the chooser gives, per
// thread count, at wall time `now`; returns the threads that ran it.
struct Machine {
  double on_all, on_one; ///< s per step
  double now = 0.0;
  int stretch(ThreadChooser& c, std::uint64_t steps = 100) {
    const int t = c.threads();
    const double seconds = static_cast<double>(steps) * (t == 1 ? on_one : on_all);
    now += seconds;
    c.took(seconds, steps, now);
    return t;
  }
};

TEST(ThreadChooser, GivesUpThreadsSlowerThanOneAndTakesThemBackLater) {
  ThreadChooser c(2, /*every=*/20.0, /*phase=*/0.05);
  Machine busy{4e-3, 1e-3};      // two threads four times slower than one
  EXPECT_EQ(busy.stretch(c), 2); // the trial: all threads first
  EXPECT_EQ(busy.stretch(c), 1); // then one
  EXPECT_EQ(c.threads(), 1);     // one was faster
  EXPECT_DOUBLE_EQ(c.time_all(), 4e-3);
  EXPECT_DOUBLE_EQ(c.time_one(), 1e-3);
  for (int k = 0; k < 100 && busy.now < 19.0; ++k) EXPECT_EQ(busy.stretch(c), 1);
  // the machine frees up; the next trial, after 20 s, goes back to two threads
  Machine free{0.6e-3, 1e-3, busy.now};
  while (free.now < busy.now + 25.0 && c.threads() == 1) free.stretch(c);
  EXPECT_EQ(c.threads(), 2);
  EXPECT_GE(free.now, 20.0);
}

// A trial's half lasts at least `phase` s: stretches of a step or two are gathered, not timed
// alone.
TEST(ThreadChooser, ShortStretchesAreGatheredIntoAPhase) {
  ThreadChooser c(2, 20.0, 0.05);
  Machine m{1e-3, 2e-3};
  int on_all = 0;
  while (c.threads() == 2 && c.time_all() == 0.0) on_all += m.stretch(c, 1) == 2;
  EXPECT_GE(on_all, 50); // 50 steps of 1 ms before the first half ends
  while (c.time_one() == 0.0) m.stretch(c, 1);
  EXPECT_EQ(c.threads(), 2); // two threads were faster
}

TEST(ThreadChooser, OneThreadHasNothingToChoose) {
  ThreadChooser c(1);
  Machine m{1e-3, 1e-3};
  for (int k = 0; k < 10; ++k) EXPECT_EQ(m.stretch(c), 1);
}

} // namespace
} // namespace talus
