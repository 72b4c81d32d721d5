#include "core/memory_budget.h"

#include <unistd.h>

#include <cstdio>
#include <stdexcept>

namespace tightfit {

double physical_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), page_bytes = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page_bytes > 0 ? static_cast<double>(pages) * page_bytes : 0.0;
}

void require_memory(const std::string& what, double count, const std::string& items,
                    double bytes_each) {
  const double machine = physical_memory_bytes();
  const double needed = count * bytes_each;
  if (machine <= 0.0 || needed <= machine) return;
  char line[256];
  std::snprintf(line, sizeof line,
                " would need about %.3g GiB of memory (%.3g %s x %.3g kB), more than the %.3g "
                "GiB this machine has",
                needed / (1 << 30), count, items.c_str(), bytes_each / 1e3, machine / (1 << 30));
  throw std::invalid_argument(what + line);
}

}  // namespace tightfit
