#!/usr/bin/env bash
# The paper's case run whole on each backend, as a user runs it: the median user CPU time of
# N runs (default 3) of `tightfit run cases/cylinder_45T.prm` (start-up, load steps, measurements
# and output), and the last step's mean pressure. docs/performance.md tracks these numbers.
# CPU time rather than wall time, so that other work on the machine does not count.
# Usage: scripts/bench_paper_case.sh [N] [TIGHTFIT] (TIGHTFIT defaults to build/app/tightfit)
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-3}
tightfit=${2:-build/app/tightfit}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for backend in massspring fem; do
  times=()
  for ((k = 0; k < runs; ++k)); do
    /usr/bin/time -f "%U" -o "$out/time" "$tightfit" run cases/cylinder_45T.prm \
      --set "Solver/Backend=$backend" --output "$out/run" > /dev/null
    times+=("$(cat "$out/time")")
  done
  median=$(printf '%s\n' "${times[@]}" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
  pressure=$(tail -n 1 "$out/run/pressure.csv" | cut -d, -f3)
  echo "$backend: median user CPU ${median} s of ${runs} runs (${times[*]}); last step p_mean ${pressure} Pa"
done
