#include "core/worker_pool.h"

#include <algorithm>
#include <atomic>
#include <limits>
#include <stdexcept>

namespace tightfit {

// One call of for_each_part: its parts, the counter that hands them out, and the first error.
struct WorkerPool::Loop {
  const Part* work = nullptr;
  std::size_t n = 0, part_size = 1, n_parts = 0;
  std::atomic<std::size_t> next_part{0};
  std::mutex error_mutex;
  std::size_t error_part = std::numeric_limits<std::size_t>::max();
  std::exception_ptr error;
};

WorkerPool::WorkerPool(int threads) {
  if (threads < 1)
    throw std::invalid_argument("worker pool: " + std::to_string(threads) +
                                " threads (at least 1)");
  workers_.reserve(std::size_t(threads - 1));
  for (int k = 1; k < threads; ++k) workers_.emplace_back([this] { work(); });
}

WorkerPool::~WorkerPool() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    closing_ = true;
  }
  wake_.notify_all();
  for (std::thread& worker : workers_) worker.join();
}

void WorkerPool::run_parts(Loop& loop) {
  for (;;) {
    const std::size_t part = loop.next_part.fetch_add(1, std::memory_order_relaxed);
    if (part >= loop.n_parts) return;
    const std::size_t begin = part * loop.part_size;
    const std::size_t end = std::min(loop.n, begin + loop.part_size);
    try {
      (*loop.work)(begin, end);
    } catch (...) {
      std::lock_guard<std::mutex> lock(loop.error_mutex);
      if (part < loop.error_part) {
        loop.error_part = part;
        loop.error = std::current_exception();
      }
    }
  }
}

void WorkerPool::for_each_part(std::size_t n, const Part& work) {
  if (n == 0) return;
  if (workers_.empty()) {
    work(0, n);
    return;
  }
  // Sixteen parts a thread: small enough that a thread held off its core by another job
  // leaves little for the rest to wait on, large enough that taking a part (one atomic
  // increment) costs nothing beside a part's queries.
  Loop loop;
  loop.work = &work;
  loop.n = n;
  loop.n_parts = std::min(n, std::size_t(16) * std::size_t(threads()));
  loop.part_size = (n + loop.n_parts - 1) / loop.n_parts;
  loop.n_parts = (n + loop.part_size - 1) / loop.part_size;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    loop_ = &loop;
    ++loop_number_;
  }
  wake_.notify_all();
  run_parts(loop);
  {
    // Every part has been taken; those still running belong to workers in the loop. Once none
    // is left in it the loop may end (a worker woken later finds no loop and sleeps again).
    std::unique_lock<std::mutex> lock(mutex_);
    loop_ = nullptr;
    finished_.wait(lock, [this] { return workers_in_loop_ == 0; });
  }
  if (loop.error) std::rethrow_exception(loop.error);
}

void WorkerPool::work() {
  unsigned long joined = 0;  // the number of the last loop this worker took parts of
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    wake_.wait(lock, [&] { return closing_ || (loop_ && loop_number_ != joined); });
    if (closing_) return;
    joined = loop_number_;
    Loop& loop = *loop_;
    ++workers_in_loop_;
    lock.unlock();
    run_parts(loop);
    lock.lock();
    if (--workers_in_loop_ == 0) finished_.notify_one();
  }
}

void for_each_part(WorkerPool* pool, std::size_t n, const WorkerPool::Part& work) {
  if (pool)
    pool->for_each_part(n, work);
  else if (n > 0)
    work(0, n);
}

}  // namespace tightfit
