#!/usr/bin/env bash
# More MPI ranks than the garment has triangles: the FE backend's partition leaves some ranks
# without a cell (METIS on the triangles' graph), and deal.II's fully distributed triangulation
# and PETSc take a rank that owns nothing; the body map's blocks of triangles (RankShare) are
# empty there too. The run ends normally with the serial run's pressures (to 1e-8 of the
# step's largest, as cli_mpi_run_writes_parallel_vtu compares them), a garment piece from
# every rank and one body file per step. A hang shows as the timeout's 124.
#   mpi_more_ranks_than_triangles.sh TIGHTFIT MPIEXEC CASE OUTPUT_DIR RANKS
set -u
tightfit=$1 mpiexec=$2 case_file=$3 out=$4 ranks=$5
rm -rf "$out"
mkdir -p "$out"
# Mesh scale 12: a tube of 8 vertices and 8 triangles.
settings=(--set "Solver/Backend=fem" --set "Garment/Mesh scale=12" --set "Protocol/Final alpha=1.2"
  --set "Protocol/Alpha increment=0.2")
fail() { echo "$1"; cat "$2"; exit 1; }
"$tightfit" run "$case_file" --output "$out/serial" "${settings[@]}" >"$out/serial.log" 2>&1 ||
  fail "the serial run failed:" "$out/serial.log"
triangles=$(sed -n 's/^  mesh: .* \([0-9]*\) triangles.*/\1/p' "$out/serial.log")
[ -n "$triangles" ] && [ "$triangles" -lt "$ranks" ] ||
  fail "the garment has ${triangles:-?} triangles, not fewer than $ranks:" "$out/serial.log"
timeout 300 "$mpiexec" --oversubscribe -n "$ranks" "$tightfit" run "$case_file" \
  --output "$out/parallel" "${settings[@]}" >"$out/parallel.log" 2>&1
status=$?
[ "$status" -eq 0 ] || fail "$ranks ranks on $triangles triangles: status $status" "$out/parallel.log"

last=$(tail -n 1 "$out/serial/pressure.csv" | cut -d, -f1)
stem=$(printf 'garment_%04d' "$last")
pieces=$(grep -c '<Piece Source=' "$out/parallel/$stem.pvtu")
[ "$pieces" -eq "$ranks" ] || fail "$stem.pvtu names $pieces pieces, not $ranks" "$out/parallel.log"
[ -s "$(printf '%s/parallel/body_%04d.vtu' "$out" "$last")" ] ||
  fail "no body file for the last step" "$out/parallel.log"
# Each step's mean and largest pressure against the serial run's.
awk -F, 'FNR == 1 { for (i = 1; i <= NF; ++i) column[$i] = i; next }
  FNR == NR { mean[FNR] = $column["p_mean_Pa"]; largest[FNR] = $column["p_max_Pa"]; next }
  { scale = largest[FNR] > 1 ? largest[FNR] : 1
    d1 = mean[FNR] - $column["p_mean_Pa"]; d2 = largest[FNR] - $column["p_max_Pa"]
    if (d1 * d1 > (1e-8 * scale) ^ 2 || d2 * d2 > (1e-8 * scale) ^ 2) {
      printf "step %d: serial %s and %s Pa, parallel %s and %s Pa\n", FNR - 2, mean[FNR],
             largest[FNR], $column["p_mean_Pa"], $column["p_max_Pa"]; bad = 1 } }
  END { exit bad }' "$out/serial/pressure.csv" "$out/parallel/pressure.csv" ||
  fail "the pressures differ from the serial run's" "$out/parallel.log"
exit 0
