#include "app/mpi_session.h"

#include <deal.II/base/mpi.h>

#include <cstdlib>

namespace tightfit {

struct MpiSession::State {
  // One thread per rank: the solves are small and the ranks (or other runs) use the cores.
  State(int& argc, char**& argv) : init(argc, argv, 1) {}
  dealii::Utilities::MPI::MPI_InitFinalize init;
};

MpiSession::MpiSession(int& argc, char**& argv) : state_(std::make_unique<State>(argc, argv)) {}

MpiSession::~MpiSession() = default;

bool MpiSession::is_first_rank() const {
  return rank() == 0;
}

int MpiSession::rank() const {
  return static_cast<int>(dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD));
}

void MpiSession::abort_all_ranks(int status) const {
  MPI_Abort(MPI_COMM_WORLD, status);
  std::abort();  // MPI_Abort does not return; this tells the compiler so
}

int MpiSession::n_ranks() const {
  return static_cast<int>(dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD));
}

}  // namespace tightfit
