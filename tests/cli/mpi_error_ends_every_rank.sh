#!/usr/bin/env bash
# Under MPI an error on one rank (here: rank 1 cannot write its piece of the first garment
# VTU, a directory stands in its way) ends every rank with the message and status 2, instead
# of leaving rank 0 waiting for rank 1 in the next solve. A hang shows as the timeout's 124.
#   mpi_error_ends_every_rank.sh TIGHTFIT MPIEXEC CASE OUTPUT_DIR
set -u
tightfit=$1 mpiexec=$2 case_file=$3 out=$4
rm -rf "$out"
mkdir -p "$out/garment_0000_1.vtu"
timeout 300 "$mpiexec" -n 2 "$tightfit" run "$case_file" --output "$out" \
  --set "Solver/Backend=fem" --set "Protocol/Final alpha=1.3" >"$out.log" 2>&1
status=$?
fail() { echo "$1"; cat "$out.log"; exit 1; }
[ "$status" -ne 124 ] || fail "the run hung (killed by the timeout)"
[ "$status" -eq 2 ] || fail "expected status 2, got $status"
grep -q "rank 1 of 2.*cannot write VTU file '.*garment_0000_1.vtu'" "$out.log" ||
  fail "the message does not name rank 1 and the file"
exit 0
