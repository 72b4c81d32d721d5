# Log-log error of the mean pressure against the mean edge length, per backend, at the last
# load step of a convergence study, with a slope-2 guide (linear triangles: error ~ h^2).
# Usage: gnuplot -e "csv='output/cylinder_T_convergence/convergence.csv'; out='error.png';
#                    backends='massspring fem'" scripts/plots/convergence_error.gp
if (!exists("plots")) plots = 'scripts/plots'
if (!exists("backends")) backends = 'massspring fem'
load plots.'/style.gp'

stats csv using "step" nooutput
last_step = int(STATS_max)
stats csv using (column("step") == last_step ? column("alpha") : NaN) nooutput
last_alpha = STATS_max
# The guide passes through the first backend's coarsest point.
stats csv using (column("step") == last_step && strcol("backend") eq word(backends, 1) \
                 ? 1e3 * column("edge_m") : NaN) nooutput
h_coarse = STATS_max
h_fine = STATS_min
stats csv using (column("step") == last_step && strcol("backend") eq word(backends, 1) \
                 && column("level") == 0 ? 100 * abs(column("rel_error")) : NaN) nooutput
e_coarse = STATS_max
guide(h) = e_coarse * (h / h_coarse)**2

set title sprintf("Mesh convergence of the mean pressure at alpha = %.2f", last_alpha)
set xlabel 'mean edge length h [mm]'
set ylabel '|p_{mean} - p_{closed form}| / p_{closed form} [%]'
set logscale xy
set xrange [h_fine / 1.5 : h_coarse * 1.5]
set format y '10^{%T}'
set xtics (2, 3, 4, 5, 6, 8, 10, 15, 20, 30, 40, 60, 80, 100, 150, 200)
set mxtics 10
set mytics 10
set key bottom right

# One backend's rows of the last step, header kept, picked by column name with awk (gnuplot
# would break the line at every row of another step).
rows(b) = sprintf("< awk -F, 'NR == 1 {for (i = 1; i <= NF; i++) c[$i] = i; print; next} \
  $c[\"backend\"] == \"%s\" && $c[\"step\"] == %d' '%s'", b, last_step, csv)
plot for [i=1:words(backends)] rows(word(backends, i)) \
         using (1e3 * column("edge_m")):(100 * abs(column("rel_error"))) \
         with linespoints ls i title word(backends, i) noenhanced, \
     guide(x) with lines ls 3 dt 3 title 'slope 2 (h^2)'
