#!/usr/bin/env bash
# A solver that fails part-way: exit status 1, a message naming the step, and the steps that
# finished before it still in pressure.csv (header + at least one row per finished step).
#   stopped_run_keeps_steps.sh TIGHTFIT CASE OUTPUT_DIR
set -u
tightfit=$1 case_file=$2 out=$3
rm -rf "$out"
# The sewn 4 5T tube settles loose in about 40 frames and hangs loose up to alpha 1 (no frames
# needed); from alpha 1.05 on it must close round the cylinder, which takes over 100 frames.
output=$("$tightfit" run "$case_file" --output "$out" --set "Mass spring/Maximum frames=80" 2>&1)
status=$?
[ "$status" -eq 1 ] || { echo "expected status 1, got $status"; echo "$output"; exit 1; }
grep -q "load step 5" <<<"$output" || { echo "the message does not name load step 5:"; echo "$output"; exit 1; }
rows=$(($(wc -l <"$out/pressure.csv") - 1))
[ "$rows" -eq 5 ] || { echo "expected the 5 finished steps in pressure.csv, found $rows"; exit 1; }
[ -f "$out/garment_0004.vtu" ] || { echo "the VTU of step 4 is missing"; exit 1; }
grep -q 'garment_0004.vtu' "$out/garment.pvd" || { echo "garment.pvd lost step 4"; exit 1; }
exit 0
