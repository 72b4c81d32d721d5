#!/usr/bin/env bash
# Ctrl-C or SIGTERM during a run: the run ends at the solver's next iteration with status
# 128 + the signal (130, 143), a note naming the load step it stopped in, and every step that
# finished before the signal written (pressure.csv rows, garment VTU, listed in garment.pvd).
#   interrupted_run_keeps_steps.sh TIGHTFIT CASE OUTPUT_DIR SIGNAL STATUS BACKEND
set -u
tightfit=$1 case_file=$2 out=$3 signal=$4 expected=$5 backend=$6
rm -rf "$out"
mkdir -p "$out"
"$tightfit" run "$case_file" --output "$out/run" --set "Solver/Backend=$backend" \
  >"$out/log" 2>&1 &
pid=$!
# Wait for two finished load steps (the header and two rows), at most 5 minutes.
for _ in $(seq 3000); do
  [ -f "$out/run/pressure.csv" ] && [ "$(wc -l <"$out/run/pressure.csv")" -ge 3 ] && break
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.1
done
kill -s "$signal" "$pid"
wait "$pid"
status=$?
fail() { echo "$1"; cat "$out/log"; exit 1; }
[ "$status" -eq "$expected" ] || fail "expected status $expected after SIG$signal, got $status"
grep -q "interrupted by SIG$signal" "$out/log" || fail "no note of the interruption"
grep -q "interrupted by SIG$signal" "$out/run/solver.log" || fail "solver.log has no note"
rows=$(($(wc -l <"$out/run/pressure.csv") - 1))
[ "$rows" -ge 2 ] || fail "expected at least 2 finished steps in pressure.csv, found $rows"
# The note names the first load step that did not finish, and the steps before it are written.
grep -q "load step $rows\b" "$out/log" || fail "the note does not name load step $rows"
grep -q "load steps 0 to $((rows - 1)) are written" "$out/log" || fail "the note does not say what is written"
last=$(printf 'garment_%04d.vtu' $((rows - 1)))
[ -s "$out/run/$last" ] || fail "the VTU of the last finished step ($last) is missing"
grep -q "$last" "$out/run/garment.pvd" || fail "garment.pvd does not list $last"
exit 0
