#!/usr/bin/env bash
# A small end-to-end run: every output file of `tightfit run` is there, with the columns the
# documentation promises.
#   small_run_writes_outputs.sh TIGHTFIT CASE OUTPUT_DIR
set -eu
tightfit=$1 case_file=$2 out=$3
rm -rf "$out"
"$tightfit" run "$case_file" --output "$out" --set "Garment/Mesh scale=2" \
  --set "Protocol/Final alpha=1.2" --set "Protocol/Alpha increment=0.1" >"$out.log" 2>&1
header=$(head -n 1 "$out/pressure.csv")
for column in step radius_m alpha p_mean_Pa p_std_Pa p_theory_Pa rel_error p_mean_gf_cm2 \
  p_mean_mmHg contact_fraction; do
  grep -q -E "(^|,)$column(,|$)" <<<"$header" || { echo "pressure.csv lacks $column: $header"; exit 1; }
done
[ "$(($(wc -l <"$out/pressure.csv") - 1))" -eq 3 ] || { echo "expected 3 load steps"; exit 1; }
for f in pressure_theta.csv garment.pvd body.pvd garment_0000.vtu garment_0002.vtu body_0002.vtu; do
  [ -s "$out/$f" ] || { echo "missing $f"; exit 1; }
done
# solver.log: one report per load step after its header line.
[ "$(grep -c '^step [0-9]*, alpha ' "$out/solver.log")" -eq 3 ] ||
  { echo "solver.log does not report 3 load steps"; exit 1; }
grep -q "Pressure on the cylinder" "$out.log" || { echo "no summary table on screen"; exit 1; }
