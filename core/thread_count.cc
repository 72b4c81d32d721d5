#include "core/thread_count.h"

#include "core/number_text.h"

#include <sched.h>

#include <algorithm>
#include <cstdlib>
#include <thread>

namespace tightfit {

int parse_threads(const std::string& text) {
  // 0 = auto; far more threads than any machine runs, but a bound.
  return auto_or_count(text, "Solver/Threads", 1 << 16).value_or(0);
}

int usable_cores() {
  cpu_set_t mask;
  CPU_ZERO(&mask);
  if (sched_getaffinity(0, sizeof mask, &mask) == 0) return std::max(1, CPU_COUNT(&mask));
  return std::max(1, int(std::thread::hardware_concurrency()));
}

int automatic_threads(int mpi_ranks, const char* omp_num_threads, int cores) {
  if (mpi_ranks > 1) return 1;
  if (omp_num_threads) {
    char* end = nullptr;
    const long value = std::strtol(omp_num_threads, &end, 10);
    // "4" or "4,2" (nested levels: the first is this one); anything else is ignored.
    if (end != omp_num_threads && (*end == '\0' || *end == ',') && value > 0)
      return int(std::min(value, 1024L));
  }
  return std::max(1, cores);
}

int threads_for_run(int requested, int mpi_ranks) {
  if (requested > 0) return requested;
  return automatic_threads(mpi_ranks, std::getenv("OMP_NUM_THREADS"), usable_cores());
}

}  // namespace tightfit
