# Mesh convergence by region, the values themselves: each region's mean pressure on every level of
# a convergence study against the mean edge length, one panel a region, each backend's levels
# with its Richardson estimate (cases/convergence_run.h) drawn at h = 0 and as a dashed line, and
# the band within 1% of the first backend's estimate shaded. A backend whose region has no
# estimate (its levels oscillate) gets no line. The last load step of the study.
# Usage: gnuplot -e "levels='.../convergence_regions.csv'; summary='.../convergence_regions_summary.csv';
#                    out='means.png'; regions='B C G'; backends='massspring fem'" \
#          scripts/plots/region_convergence_means.gp
if (!exists("plots")) plots = 'scripts/plots'
if (!exists("backends")) backends = 'massspring fem'
load plots.'/style.gp'
set terminal pngcairo size 1500,620 enhanced font 'DejaVu Sans,15' linewidth 2
set output out

stats summary using "step" nooutput
last_step = int(STATS_max)
stats levels using (1e3 * column("edge_m")) nooutput
h_coarse = STATS_max

# The estimate of region r on backend b (NaN where there is none), read from the summary.
array estimate[words(backends)]
richardson(b, r) = sprintf("awk -F, 'FNR == 1 {for (i = 1; i <= NF; i++) c[$i] = i; next} \
  $c[\"backend\"] == \"%s\" && $c[\"region\"] == \"%s\" && $c[\"step\"] == %d \
  {v = $c[\"p_mean_richardson_Pa\"]} END {print (v == \"\" ? \"nan\" : v)}' '%s'", \
  b, r, last_step, summary)

# One backend's levels of region r: mean edge (mm) and mean pressure (Pa), coarse to fine.
rows(b, r) = sprintf("< awk -F, 'FNR == 1 {for (i = 1; i <= NF; i++) c[$i] = i; next} \
  $c[\"backend\"] == \"%s\" && $c[\"region\"] == \"%s\" && $c[\"step\"] == %d \
  {print 1e3 * $c[\"edge_m\"] \",\" $c[\"p_mean_Pa\"]}' '%s'", b, r, last_step, levels)

set multiplot layout 1, words(regions) title \
  'Mean pressure by region against the mean edge length; dashed: the Richardson estimate, grey: within 1% of the first backend''s' noenhanced
set xlabel 'mean edge length h [mm]'
set xrange [-0.5 : h_coarse * 1.08]
set xtics 2
set key top right
do for [i = 1:words(regions)] {
  r = word(regions, i)
  do for [k = 1:words(backends)] {
    estimate[k] = real(system(richardson(word(backends, k), r)))
  }
  set title sprintf('%s', r) noenhanced offset 0,-0.5
  set ylabel (i == 1 ? 'p_{mean} [Pa]' : '')
  R1 = estimate[1]
  plot (R1 == R1 ? 1.01 * R1 : NaN) with filledcurves y1 = (0.99 * R1) fc rgb '#e8e8e8' notitle, \
       for [k = 1:words(backends)] rows(word(backends, k), r) using 1:2 \
         with linespoints ls k title word(backends, k) noenhanced, \
       for [k = 1:words(backends)] (estimate[k] == estimate[k] ? estimate[k] : NaN) \
         with lines ls k dt 2 lw 1.5 notitle, \
       for [k = 1:words(backends)] '+' using (0):(estimate[k]) every ::0::0 \
         with points ls k pt 6 ps 2 notitle
}
unset multiplot
