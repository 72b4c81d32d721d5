// Hands memory the program has freed back to the system. glibc keeps freed small blocks in its
// heap for reuse; a large structure built from many small blocks (a triangulation, a sparsity
// pattern) and then dropped stays in the resident set until malloc_trim returns its pages, and
// the factorization's large blocks (allocated by mmap) would not reuse it.
#pragma once

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace tightfit {

inline void release_freed_memory() {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

}  // namespace tightfit
