// MPI (and PETSc, through deal.II) for the whole run: started before anything else, finished
// after everything else. Under `mpirun -np N` the ranks share the FE backend's solves; the
// first rank alone prints; files are shared out by rank (OutputSettings).
#pragma once

#include <memory>

namespace tightfit {

class MpiSession {
 public:
  MpiSession(int& argc, char**& argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  bool is_first_rank() const;
  int rank() const;  // 0 .. n_ranks() - 1 in MPI_COMM_WORLD
  int n_ranks() const;
  // Ends every rank of the run with `status`. A rank that stops on an error while the others
  // go on would leave them waiting for it in the next collective operation.
  [[noreturn]] void abort_all_ranks(int status) const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace tightfit
