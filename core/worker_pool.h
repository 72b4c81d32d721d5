// A few threads that share out the independent items of a loop (a frame's body queries, one
// per garment vertex): the caller's thread and threads() - 1 workers started once and kept
// asleep between loops.
//
// The items are handed out in consecutive parts from a shared counter, so a thread that the
// machine's other jobs keep off a core leaves its parts to the others; which thread computes an
// item changes from loop to loop, so an item's work must not depend on it: each writes only its
// own slots, and whatever the loop sums is summed afterwards in item order by the caller (then
// the results are the same to the last bit with any number of threads).
#pragma once

#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace tightfit {

class WorkerPool {
 public:
  // `threads` >= 1 (1: every loop runs on the caller's thread, no worker is started). Throws
  // std::invalid_argument below 1.
  explicit WorkerPool(int threads);
  // Wakes and joins the workers.
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  int threads() const { return int(workers_.size()) + 1; }

  // Calls work(begin, end) on consecutive parts of [0, n) that together cover it once, and
  // returns when every part is done. An exception thrown by a part is rethrown here (that of
  // the part nearest the start when several throw) once every part has ended. Not reentrant:
  // one loop at a time, from one thread.
  using Part = std::function<void(std::size_t begin, std::size_t end)>;
  void for_each_part(std::size_t n, const Part& work);

 private:
  struct Loop;
  // Takes and runs parts of `loop` until none is left.
  static void run_parts(Loop& loop);
  void work();

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_;      // a loop has started, or the pool is closing
  std::condition_variable finished_;  // a worker has left its loop
  Loop* loop_ = nullptr;              // the loop running now (null between loops)
  unsigned long loop_number_ = 0;     // counts the loops, so that a worker joins each once
  int workers_in_loop_ = 0;
  bool closing_ = false;
};

// pool->for_each_part(n, work), or work(0, n) on this thread when `pool` is null.
void for_each_part(WorkerPool* pool, std::size_t n, const WorkerPool::Part& work);

}  // namespace tightfit
