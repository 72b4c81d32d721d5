// The progress line of a long load step: none before its first time, one per interval after,
// and none once the step has ended (the destructor stops and joins the thread at once).
#include "core/step_heartbeat.h"

#include <gtest/gtest.h>

#include <chrono>
#include <sstream>
#include <thread>

namespace tightfit {
namespace {

int lines_of(const std::string& text) {
  int n = 0;
  for (char c : text) n += c == '\n';
  return n;
}

TEST(StepHeartbeat, SilentWhenTheStepEndsFirst) {
  std::ostringstream log;
  const auto start = std::chrono::steady_clock::now();
  { const StepHeartbeat beat(log, "step 1/3 (alpha 1.050)", std::chrono::seconds(30)); }
  // Ending the step does not wait for the next beat (30 s away).
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
  EXPECT_EQ(log.str(), "");
}

TEST(StepHeartbeat, SaysTheStepIsStillSolving) {
  std::ostringstream log;
  const auto start = std::chrono::steady_clock::now();
  {
    const StepHeartbeat beat(log, "step 2/3 (alpha 1.100)", std::chrono::seconds(1),
                             std::chrono::seconds(1));
    std::this_thread::sleep_for(std::chrono::milliseconds(2500));
  }
  const double elapsed_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // A beat 1 s after the start and every 1 s after the one before: a loaded machine wakes the
  // thread late, never early, so by 2.5 s the first has come, and no more than one per whole
  // second elapsed.
  const std::string text = log.str();
  EXPECT_GE(lines_of(text), 1) << text;
  EXPECT_LE(lines_of(text), static_cast<int>(elapsed_s)) << text;
  EXPECT_EQ(text.rfind("    step 2/3 (alpha 1.100): still solving, ", 0), 0u) << text;
}

TEST(DurationText, SecondsMinutesHours) {
  EXPECT_EQ(duration_text(0.42), "0.4 s");
  EXPECT_EQ(duration_text(45), "45 s");
  EXPECT_EQ(duration_text(150), "2.5 min");
  EXPECT_EQ(duration_text(3 * 3600), "3.0 h");
}

}  // namespace
}  // namespace tightfit
