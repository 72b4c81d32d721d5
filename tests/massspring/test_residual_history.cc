// The stall test's windows: a residual that falls geometrically never stalls, a limit cycle
// stalls in its second window, and a restart forgets the earlier windows.
#include "core/residual_history.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tightfit {
namespace {

TEST(ResidualHistory, GeometricFallNeverStalls) {
  // Damped modes: the residual falls by 0.999 a frame, 0.37 over a window of 1000 frames.
  ResidualHistory history(1000, 0.9);
  for (int frame = 0; frame < 10000; ++frame)
    EXPECT_FALSE(history.record(frame, std::pow(0.999, frame), 1e-5)) << frame;
  EXPECT_EQ(history.windows(), 10);
}

TEST(ResidualHistory, LimitCycleStallsInItsSecondWindow) {
  // A residual going round a cycle of 37 frames between 1e-3 and 3e-3 N: the second window's
  // smallest equals the first's, not 0.9 times it.
  ResidualHistory history(200, 0.9);
  int stalled_at = -1;
  for (int frame = 0; frame < 1000 && stalled_at < 0; ++frame)
    if (history.record(frame, 2e-3 + 1e-3 * std::sin(2 * M_PI * frame / 37.0), 2e-5))
      stalled_at = frame;
  EXPECT_EQ(stalled_at, 399);
  const std::string text = history.text();
  EXPECT_NE(text.find("stalled"), std::string::npos) << text;
  EXPECT_NE(text.find("windows of 200 frames"), std::string::npos) << text;
}

TEST(ResidualHistory, RestartForgetsTheEarlierWindows) {
  ResidualHistory history(10, 0.5);
  for (int frame = 0; frame < 10; ++frame) history.record(frame, 1e-3, 1e-5);
  history.restart();
  // A window higher than the one before, but the first after the restart: no stall.
  bool stalled = false;
  for (int frame = 10; frame < 20; ++frame) stalled = stalled || history.record(frame, 1.0, 1e-5);
  EXPECT_FALSE(stalled);
  // The next window does not fall by half: a stall.
  for (int frame = 20; frame < 30; ++frame) stalled = stalled || history.record(frame, 0.6, 1e-5);
  EXPECT_TRUE(stalled);
  EXPECT_EQ(history.windows(), 3);
}

TEST(ResidualHistory, RejectsAnEmptyWindowOrAFallOutsideZeroOne) {
  EXPECT_THROW(ResidualHistory(0, 0.5), std::invalid_argument);
  EXPECT_THROW(ResidualHistory(10, 1.0), std::invalid_argument);
  EXPECT_THROW(ResidualHistory(10, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace tightfit
