# Mesh convergence by region: each region's mean pressure on every level of a convergence study
# against its Richardson estimate (cases/convergence_run.h), |p_mean - p_Richardson| /
# p_Richardson in % against the mean edge length, log-log, at the last load step of one backend,
# with the 1% line; a region whose levels oscillate (no observed order, no Richardson value)
# against its finest level instead.
# Usage: gnuplot -e "dir='output/stocking_female_convergence'; out='regions.png';
#                    regions='B C G'; backend='massspring'" scripts/plots/region_convergence.gp
# (or levels='.../convergence_regions.csv'; summary='.../convergence_regions_summary.csv'
# in place of dir).
if (!exists("plots")) plots = 'scripts/plots'
if (!exists("backend")) backend = 'massspring'
load plots.'/style.gp'
if (!exists("levels")) levels = dir.'/convergence_regions.csv'
if (!exists("summary")) summary = dir.'/convergence_regions_summary.csv'

stats summary using "step" nooutput
last_step = int(STATS_max)
stats levels using (strcol("backend") eq backend ? 1e3 * column("edge_m") : NaN) nooutput
h_coarse = STATS_max
h_fine = STATS_min

# One region's levels: mean edge (mm) and the deviation (%) from the summary's Richardson value,
# or, where the sequence oscillates and has none, from the finest level's value (its own point
# then reads 0 and is left out); joined by awk on the column names (the summary, then the levels).
rows(r) = sprintf("< awk -F, 'BEGIN {n = 0} FNR == 1 {delete c; for (i = 1; i <= NF; i++) c[$i] = i; next} \
  $c[\"backend\"] != \"%s\" || $c[\"region\"] != \"%s\" || $c[\"step\"] != %d {next} \
  FILENAME == ARGV[1] {R = $c[\"p_mean_richardson_Pa\"]; next} \
  {h[n] = 1e3 * $c[\"edge_m\"]; p[n++] = $c[\"p_mean_Pa\"]} \
  END {ref = (R == \"\") ? p[n - 1] : R; for (k = 0; k < n - (R == \"\"); ++k) \
    printf \"%%.6g,%%.6g\\n\", h[k], 100 * (p[k] - ref) / ref}' '%s' '%s'", \
  backend, r, last_step, summary, levels)

set title sprintf("Mean pressure by region against its limit: Richardson, or the finest level (%s)", backend) noenhanced
set xlabel 'mean edge length h [mm]'
set ylabel '|p_{mean} - p_{limit}| / p_{limit} [%]'
set logscale xy
set xrange [h_fine / 1.3 : h_coarse * 1.3]
set xtics (2, 3, 4, 5, 6, 7, 8, 9, 10, 12, 14, 16, 20, 25, 30, 40)
set mxtics 10
set mytics 10
set key bottom right
# The 1% line always inside.
set yrange [* < 0.1 : 3 < *]

plot for [i=1:words(regions)] rows(word(regions, i)) using 1:(abs($2)) \
         with linespoints ls i title word(regions, i) noenhanced, \
     1 with lines lc rgb '#808080' dt 2 title '1%'
