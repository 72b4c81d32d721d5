#!/usr/bin/env bash
# The FE backend under MPI, end to end: with 2 ranks the garment of every load step is a .pvtu
# whose pieces exist (listed in garment.pvd), and pressure.csv holds the serial run's numbers;
# a convergence study runs under MPI too.
#   mpi_run_writes_pvtu.sh TIGHTFIT MPIEXEC CASE OUTPUT_DIR
set -eu
tightfit=$1 mpiexec=$2 case_file=$3 out=$4
rm -rf "$out"
mkdir -p "$out"
settings=(--set "Solver/Backend=fem" --set "Protocol/Final alpha=1.2"
  --set "Protocol/Alpha increment=0.2")
"$tightfit" run "$case_file" --output "$out/serial" "${settings[@]}" >"$out/serial.log" 2>&1 ||
  { echo "the serial run failed:"; cat "$out/serial.log"; exit 1; }
"$mpiexec" -n 2 "$tightfit" run "$case_file" --output "$out/parallel" "${settings[@]}" \
  >"$out/parallel.log" 2>&1 || { echo "the 2-rank run failed:"; cat "$out/parallel.log"; exit 1; }

parallel=$out/parallel
steps=$(($(wc -l <"$parallel/pressure.csv") - 1))
[ "$steps" -ge 2 ] || { echo "expected at least 2 load steps, found $steps"; exit 1; }
listed=$(grep -o 'file="[^"]*"' "$parallel/garment.pvd" | sed 's/^file="//; s/"$//')
[ "$(wc -l <<<"$listed")" -eq "$steps" ] || { echo "garment.pvd does not list $steps steps"; exit 1; }
for header in $listed; do
  [[ $header == *.pvtu ]] || { echo "garment.pvd lists $header, not a .pvtu"; exit 1; }
  [ -s "$parallel/$header" ] || { echo "missing $header"; exit 1; }
  pieces=$(grep -o 'Source="[^"]*"' "$parallel/$header" | sed 's/^Source="//; s/"$//')
  [ "$(wc -l <<<"$pieces")" -eq 2 ] || { echo "$header does not name 2 pieces"; exit 1; }
  for piece in $pieces; do
    [ -s "$parallel/$piece" ] || { echo "missing piece $piece of $header"; exit 1; }
  done
done
# Serial-only files are not written in parallel, and the body stays one file per step.
! ls "$parallel"/garment_????.vtu >/dev/null 2>&1 || { echo "plain garment VTU files in parallel"; exit 1; }
[ -s "$parallel/body.pvd" ] && [ -s "$parallel/body_0000.vtu" ] || { echo "no body output"; exit 1; }

# The serial run's numbers. The distributed solves sum in another order, so values may differ
# in the last digits: pressures (any column in Pa, the spread included) to 1e-8 of the step's
# largest pressure (the issue's bound on the mean), other numbers to 1e-8 relative, text and
# iteration counts exactly. The wall time and the solver's final residual (at round-off
# level) are not compared.
compare='BEGIN { FS = "," }
FNR == 1 { for (i = 1; i <= NF; ++i) name[i] = $i; next }
FNR == NR { for (i = 1; i <= NF; ++i) serial[FNR, i] = $i; rows = FNR; next }
{
  scale = 1
  for (i = 1; i <= NF; ++i) if (name[i] == "p_max_Pa" && serial[FNR, i] + 0 > 1) scale = serial[FNR, i] + 0
  for (i = 1; i <= NF; ++i) {
    a = serial[FNR, i]; b = $i
    if (name[i] == "wall_time_s" || name[i] == "residual_N" || a == b) continue
    if (a !~ /^-?[0-9.]/ || b !~ /^-?[0-9.]/ || name[i] == "iterations") { bad = 1 }
    else {
      d = a - b; if (d < 0) d = -d
      m = a < 0 ? -a : a; if (m < 1) m = 1
      if (name[i] ~ /_Pa$/) m = scale
      if (d > 1e-8 * m) bad = 1
    }
    if (bad) { printf "step %d, %s: serial %s, 2 ranks %s\n", FNR - 2, name[i], a, b; failed = 1; bad = 0 }
  }
}
END { if (FNR != rows) { print "the runs have different numbers of rows"; failed = 1 }; exit failed }'
[ "$(head -n 1 "$out/serial/pressure.csv")" = "$(head -n 1 "$parallel/pressure.csv")" ] ||
  { echo "the runs' pressure.csv have different columns"; exit 1; }
awk "$compare" "$out/serial/pressure.csv" "$parallel/pressure.csv" ||
  { echo "pressure.csv of the 2-rank run differs from the serial one"; exit 1; }

# A convergence study under MPI (every rank runs it, the FE solves distributed): it finishes
# and convergence.csv holds each backend's levels x steps, every row complete.
study=$out/convergence
"$mpiexec" -n 2 "$tightfit" convergence "$case_file" --levels 2 --output "$study" \
  --set "Garment/Mesh scale=2" --set "Protocol/Final alpha=1.2" \
  --set "Protocol/Alpha increment=0.2" >"$out/convergence.log" 2>&1 ||
  { echo "the 2-rank convergence study failed:"; cat "$out/convergence.log"; exit 1; }
steps=$(($(wc -l <"$study/fem/level_1/pressure.csv") - 1))
backends=$(ls -d "$study"/*/ | wc -l)
rows=$(($(wc -l <"$study/convergence.csv") - 1))
[ "$rows" -eq $((backends * 2 * steps)) ] ||
  { echo "convergence.csv has $rows rows, not $backends backends x 2 levels x $steps steps"; exit 1; }
awk -F, 'NR == 1 {n = NF} NF != n {print "convergence.csv line " NR " has " NF " fields"; bad = 1}
  END {exit bad}' "$study/convergence.csv" || exit 1
exit 0
