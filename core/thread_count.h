// How many threads a run's per-vertex work uses (Solver/Threads, docs/parameters.md).
#pragma once

#include <string>

namespace tightfit {

// Solver/Threads as written: "auto" or a whole number >= 0 (0 = auto), returned as that number.
// Throws std::invalid_argument naming the entry for anything else.
int parse_threads(const std::string& text);

// The cores this process may run on: its CPU affinity mask (what `taskset` or a batch
// scheduler leaves it), std::thread::hardware_concurrency where the mask cannot be read; at
// least 1.
int usable_cores();

// The threads for Solver/Threads = `requested` (0: automatic) in a run of `mpi_ranks` ranks:
// `requested` when above 0. Automatic: one thread under MPI with more than one rank (the ranks
// share the cores); else OMP_NUM_THREADS when it holds a positive number (its first, for a
// list), the variable by which OpenMP and BLAS programs are told their threads; else
// `cores`. `omp_num_threads` is that variable's value (null: unset).
int automatic_threads(int mpi_ranks, const char* omp_num_threads, int cores);
int threads_for_run(int requested, int mpi_ranks);

}  // namespace tightfit
