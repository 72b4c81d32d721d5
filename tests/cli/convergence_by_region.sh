#!/usr/bin/env bash
# A convergence study of a case with named regions (cases/convergence_run.h): the per-level and
# summary region tables hold one row per level, step and region, the region away from the
# garment reads empty, the summary's order, Richardson value and GCI are those of its own
# level rows (recomputed here from convergence_regions.csv by Roache's formulas), and the region
# round the whole garment reads the whole garment's mean pressure, and every level's rows are
# those of the level's own regions.csv.
#   convergence_by_region.sh TIGHTFIT CASE OUTPUT_DIR
set -eu
tightfit=$1 case_file=$2 out=$3
rm -rf "$out"
"$tightfit" convergence "$case_file" --output "$out" --levels 3 --ratio 1.5 --backends massspring \
  --set "Garment/Mesh scale=2" --set "Protocol/Final alpha=1.2" \
  --set "Protocol/Alpha increment=0.1" --set "Measurements/List=cylinder theory, regions" \
  --set "Measurements/Regions/Definitions=all: ball 0,0,0 10; middle: slab x -0.06 0.06; away: ball 1,1,1 0.1" \
  >"$out.log" 2>&1 || { echo "convergence failed"; cat "$out.log"; exit 1; }
levels=$out/convergence_regions.csv summary=$out/convergence_regions_summary.csv
[ "$(head -n 1 "$levels")" = "backend,level,mesh_scale,n_vertices,edge_m,step,alpha,region,p_mean_Pa,p_peak_Pa,contact_area_m2,n_contact_vertices" ] ||
  { echo "convergence_regions.csv header: $(head -n 1 "$levels")"; exit 1; }
# 3 levels x 3 load steps x 3 regions; 3 steps x 3 regions in the summary.
[ "$(($(wc -l <"$levels") - 1))" -eq 27 ] || { echo "expected 27 level rows"; cat "$levels"; exit 1; }
[ "$(($(wc -l <"$summary") - 1))" -eq 9 ] || { echo "expected 9 summary rows"; cat "$summary"; exit 1; }
[ "$(grep -c ',away,,,0,0$' "$levels")" -eq 9 ] || { echo "the empty region's rows:"; cat "$levels"; exit 1; }
# Roache's formulas on the level rows of the last step (2), against the summary's columns.
awk -F, -v summary="$summary" '
  NR > 1 && $6 == 2 && $8 != "away" { edge[$8, $2] = $5; mean[$8, $2] = $9; peak[$8, $2] = $10; names[$8] = 1 }
  END {
    while ((getline line < summary) > 0) {
      split(line, s, ",")
      if (s[2] != 2 || s[4] == "away") continue
      r = s[4]; ratio = sqrt(edge[r, 0] / edge[r, 2])
      for (q = 0; q < 2; ++q) {
        f3 = q ? peak[r, 0] : mean[r, 0]; f2 = q ? peak[r, 1] : mean[r, 1]; f1 = q ? peak[r, 2] : mean[r, 2]
        p = log((f3 - f2) / (f2 - f1)) / log(ratio)
        rich = f1 + (f1 - f2) / (ratio ^ p - 1)
        gci = 1.25 * ((f2 - f1) / f1 < 0 ? (f1 - f2) / f1 : (f2 - f1) / f1) / (ratio ^ p - 1)
        col = q ? 14 : 9
        if ((s[7] - ratio) ^ 2 > 1e-16 || (s[col] - p) ^ 2 > 1e-12 ||
            (s[col + 2] - rich) ^ 2 > 1e-12 * rich ^ 2 || (s[col + 3] - gci) ^ 2 > 1e-12 * gci ^ 2) {
          printf "region %s (%s): summary ratio %s order %s Richardson %s GCI %s; levels give %.10g %.10g %.10g %.10g\n", \
            r, q ? "peak" : "mean", s[7], s[col], s[col + 2], s[col + 3], ratio, p, rich, gci
          bad = 1
        }
        ++checked
      }
    }
    if (checked != 4) { print "checked " checked " estimates, expected 4"; bad = 1 }
    exit bad
  }' "$levels"
# The region holding the whole garment against the whole garment's mean (convergence.csv), every
# level at the last step: the region's is area-weighted, the garment's a vertex mean; on the
# cylinder's even mesh they agree to 1e-4 (measured 3e-6 at most; margin 30).
awk -F, 'FNR == 1 { ++file; next }
  file == 1 && $6 == 2 { whole[$2] = $8 }
  file == 2 && $6 == 2 && $8 == "all" { all[$2] = $9 }
  END {
    for (l = 0; l < 3; ++l) {
      d = (all[l] - whole[l]) / whole[l]
      if (d * d > 1e-8 || whole[l] == "") { printf "level %d: region all %s Pa, garment %s Pa\n", l, all[l], whole[l]; exit 1 }
    }
  }' "$out/convergence.csv" "$levels"
# The study reads each level's regions as the level's own run writes them (regions.csv).
for level in 0 1 2; do
  diff <(awk -F, -v l=$level 'NR > 1 && $2 == l {print $6 "," $8 "," $9 "," $10 "," $11}' "$levels") \
    <(awk -F, 'NR > 1 {print $1 "," $3 "," $5 "," $6 "," $4}' "$out/massspring/level_$level/regions.csv") ||
    { echo "level $level: convergence_regions.csv differs from the level's regions.csv"; exit 1; }
done
grep -q "Mesh convergence by region" "$out.log" || { echo "no region summary on screen"; exit 1; }
grep -q -E "^ *massspring +2 +middle +3 +[0-9.]+ +[0-9.]+ +[0-9.]+ +[0-9.]+ " "$out.log" ||
  { echo "no middle row in the summary on screen"; cat "$out.log"; exit 1; }
