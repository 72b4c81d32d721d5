#!/usr/bin/env bash
# A small run with the regions measurement: regions.csv has one row per region and load step,
# the region away from the garment notes it, and the table is on screen.
#   run_with_regions.sh TIGHTFIT CASE OUTPUT_DIR
set -eu
tightfit=$1 case_file=$2 out=$3
rm -rf "$out"
"$tightfit" run "$case_file" --output "$out" --set "Garment/Mesh scale=2" \
  --set "Protocol/Final alpha=1.2" --set "Protocol/Alpha increment=0.1" \
  --set "Output/Write VTU=false" --set "Measurements/List=cylinder theory, regions" \
  --set "Measurements/Regions/Definitions=middle: slab x -0.06 0.06; away: ball 1,1,1 0.1" \
  >"$out.log" 2>&1
header=$(head -n 1 "$out/regions.csv")
[ "$header" = "step,alpha,region,contact_area_m2,p_mean_Pa,p_peak_Pa,p_mean_mmHg,p_peak_mmHg,normal_force_N,n_contact_vertices,garment_area_m2,note" ] ||
  { echo "regions.csv header: $header"; exit 1; }
[ "$(($(wc -l <"$out/regions.csv") - 1))" -eq 6 ] || { echo "expected 3 steps x 2 regions"; exit 1; }
grep -q '^2,.*,away,0,,,,,0,0,0,no garment in the region$' "$out/regions.csv" ||
  { echo "the empty region's row:"; cat "$out/regions.csv"; exit 1; }
grep -q "Pressure by region, load step 2" "$out.log" || { echo "no region table on screen"; exit 1; }
grep -q -E "^ *middle +[0-9.e-]+ +[0-9.]+ " "$out.log" || { echo "no middle row on screen"; cat "$out.log"; exit 1; }
