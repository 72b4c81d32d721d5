// A case whose mesh would need more memory than the machine has is refused before anything
// is allocated, with the estimate in the message (exit status 2), instead of being killed by
// the system part-way or swapping for hours.
#pragma once

#include <string>

namespace tightfit {

// What a run needs per garment vertex, bytes, FE backend with the direct solver (the larger of
// the two backends): measured peak resident memory of `tightfit run` on the 4 5T tube at
// growing vertex counts (docs/testing.md, "Memory guard").
constexpr double run_bytes_per_garment_vertex = 40e3;
// What reading a body mesh needs per face, bytes: the reader's arrays, the imported surface,
// its checks and the AABB tree (docs/testing.md, "Memory guard").
constexpr double bytes_per_body_face = 2e3;

// The machine's physical memory, bytes (sysconf); 0 when it cannot be told.
double physical_memory_bytes();

// Throws std::invalid_argument naming `what`, the estimate (count x bytes each) and the
// machine's memory when count x bytes_each exceeds the physical memory.
void require_memory(const std::string& what, double count, const std::string& items,
                    double bytes_each);

}  // namespace tightfit
