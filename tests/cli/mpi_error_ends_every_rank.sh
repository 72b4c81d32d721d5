#!/usr/bin/env bash
# Under MPI an error on one rank (it cannot write one of its files: a directory stands in the
# way) ends every rank with the message and status 2, instead of leaving the others waiting
# for it in the next solve, or the first rank finishing while the second still solves. A hang
# shows as the timeout's 124.
#   mpi_error_ends_every_rank.sh TIGHTFIT MPIEXEC OUTPUT_DIR BLOCKED RANK COMMAND CASE [ARGS...]
# BLOCKED: the file, relative to OUTPUT_DIR, made a directory; RANK: the rank that writes it.
set -u
tightfit=$1 mpiexec=$2 out=$3 blocked=$4 rank=$5
shift 5
rm -rf "$out"
mkdir -p "$out/$blocked"
timeout 300 "$mpiexec" -n 2 "$tightfit" "$@" --output "$out" >"$out.log" 2>&1
status=$?
fail() { echo "$1"; cat "$out.log"; exit 1; }
[ "$status" -ne 124 ] || fail "the run hung (killed by the timeout)"
[ "$status" -eq 2 ] || fail "expected status 2, got $status"
grep -q "rank $rank of 2): error: .*'$out/$blocked'" "$out.log" ||
  fail "the message does not name rank $rank and the file $out/$blocked"
exit 0
