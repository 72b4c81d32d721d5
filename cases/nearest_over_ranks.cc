#include "cases/nearest_over_ranks.h"

#include "bodies/triangle_bvh.h"

#include <mpi.h>

#include <type_traits>

namespace tightfit {

namespace {

static_assert(std::is_trivially_copyable_v<NearestReading>, "readings are sent as bytes");

bool nearer(const NearestReading& a, const NearestReading& b) {
  if (a.triangle < 0) return false;
  if (b.triangle < 0) return true;
  const auto vec = [](const std::array<double, 3>& v) { return Vec3(v[0], v[1], v[2]); };
  const int order = compare_distances(vec(a.query_m), vec(a.point_m), vec(b.point_m));
  return order < 0 || (order == 0 && a.triangle < b.triangle);
}

// MPI's user operation: `inout` keeps, entry by entry, the nearer of the two readings. The
// entries are the same query points in the same order (MPI may pass a part of the arrays).
void keep_nearer(void* in, void* inout, int* length, MPI_Datatype* /*type*/) {
  const auto* a = static_cast<const NearestReading*>(in);
  auto* b = static_cast<NearestReading*>(inout);
  for (int i = 0; i < *length; ++i)
    if (nearer(a[i], b[i])) b[i] = a[i];
}

}  // namespace

std::pair<int, int> RankShare::block(int n) const {
  const auto bound = [&](int r) {
    return static_cast<int>(static_cast<long long>(n) * r / n_ranks);
  };
  return {bound(rank), bound(rank + 1)};
}

void keep_nearest_over_ranks(std::vector<NearestReading>& readings, const RankShare& share) {
  if (share.n_ranks == 1) return;
  MPI_Datatype reading;
  MPI_Type_contiguous(static_cast<int>(sizeof(NearestReading)), MPI_BYTE, &reading);
  MPI_Type_commit(&reading);
  MPI_Op keep;
  MPI_Op_create(&keep_nearer, /*commute=*/1, &keep);
  MPI_Allreduce(MPI_IN_PLACE, readings.data(), static_cast<int>(readings.size()), reading, keep,
                MPI_COMM_WORLD);
  MPI_Op_free(&keep);
  MPI_Type_free(&reading);
}

}  // namespace tightfit
