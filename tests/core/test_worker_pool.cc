// The worker pool (core/worker_pool.h) and the thread count of Solver/Threads
// (core/thread_count.h): every item of a loop done once whatever the threads, errors carried
// back to the caller, many short loops in a row (where a worker that wakes late meets the next
// loop), and the automatic count's rules.
#include "core/thread_count.h"
#include "core/worker_pool.h"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

namespace tightfit {
namespace {

TEST(WorkerPool, EveryItemOnceInConsecutiveParts) {
  for (int threads : {1, 2, 3, 5}) {
    for (std::size_t n : {std::size_t(0), std::size_t(1), std::size_t(7), std::size_t(33),
                          std::size_t(1000), std::size_t(4097)}) {
      WorkerPool pool(threads);
      EXPECT_EQ(pool.threads(), threads);
      std::vector<int> done(n, 0);
      std::atomic<long> parts{0}, items{0};
      pool.for_each_part(n, [&](std::size_t begin, std::size_t end) {
        EXPECT_LT(begin, end);
        EXPECT_LE(end, n);
        for (std::size_t i = begin; i < end; ++i) ++done[i];
        ++parts;
        items += long(end - begin);
      });
      EXPECT_EQ(items.load(), long(n)) << threads << " threads, " << n << " items";
      for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(done[i], 1) << "item " << i;
      // At most sixteen parts a thread; one part on one thread.
      EXPECT_LE(parts.load(), 16L * threads);
      if (threads == 1 && n > 0) EXPECT_EQ(parts.load(), 1);
    }
  }
}

TEST(WorkerPool, ManyShortLoopsInARow) {
  WorkerPool pool(3);
  std::vector<double> slot(64, 0.0);
  for (int loop = 0; loop < 20000; ++loop)
    pool.for_each_part(slot.size(), [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) slot[i] += 1.0;
    });
  for (double s : slot) EXPECT_EQ(s, 20000.0);
}

TEST(WorkerPool, RethrowsTheErrorOfThePartNearestTheStart) {
  WorkerPool pool(2);
  const std::size_t n = 1000;
  std::vector<int> done(n, 0);
  try {
    pool.for_each_part(n, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) done[i] = 1;
      // Two parts throw; the one that starts at 0 is reported whichever thread ran it.
      if (begin == 0 || end == n) throw std::runtime_error("part at " + std::to_string(begin));
    });
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "part at 0");
  }
  // Every part ran to its end before the error came back, and the pool works on.
  for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(done[i], 1) << "item " << i;
  std::atomic<long> items{0};
  pool.for_each_part(n, [&](std::size_t begin, std::size_t end) { items += long(end - begin); });
  EXPECT_EQ(items.load(), long(n));
}

TEST(WorkerPool, RefusesFewerThanOneThread) {
  EXPECT_THROW(WorkerPool(0), std::invalid_argument);
}

TEST(WorkerPool, WithoutAPoolTheLoopRunsHereInOnePart) {
  int calls = 0;
  for_each_part(nullptr, 10, [&](std::size_t begin, std::size_t end) {
    EXPECT_EQ(begin, 0u);
    EXPECT_EQ(end, 10u);
    ++calls;
  });
  for_each_part(nullptr, 0, [&](std::size_t, std::size_t) { ++calls; });
  EXPECT_EQ(calls, 1);
}

TEST(ThreadCount, AutomaticRules) {
  // Several ranks share the cores: one thread each.
  EXPECT_EQ(automatic_threads(2, nullptr, 8), 1);
  EXPECT_EQ(automatic_threads(4, "8", 8), 1);
  // One rank: OMP_NUM_THREADS when it holds a positive number, else the cores.
  EXPECT_EQ(automatic_threads(1, nullptr, 8), 8);
  EXPECT_EQ(automatic_threads(1, "3", 8), 3);
  EXPECT_EQ(automatic_threads(1, "2,1", 8), 2);
  EXPECT_EQ(automatic_threads(1, "0", 8), 8);
  EXPECT_EQ(automatic_threads(1, "", 8), 8);
  EXPECT_EQ(automatic_threads(1, "many", 8), 8);
  EXPECT_EQ(automatic_threads(1, "4x", 8), 8);
  EXPECT_EQ(automatic_threads(1, nullptr, 0), 1);
  EXPECT_GE(usable_cores(), 1);
  // A number asked for is taken as it is.
  EXPECT_EQ(threads_for_run(3, 4), 3);
  EXPECT_EQ(threads_for_run(1, 1), 1);
}

TEST(ThreadCount, ParsesAutoOrAWholeNumber) {
  EXPECT_EQ(parse_threads("auto"), 0);
  EXPECT_EQ(parse_threads("0"), 0);
  EXPECT_EQ(parse_threads("2"), 2);
  for (const char* bad : {"", "-1", "two", "2.5", "2 ", "Auto"})
    EXPECT_THROW(parse_threads(bad), std::invalid_argument) << "'" << bad << "'";
}

}  // namespace
}  // namespace tightfit
