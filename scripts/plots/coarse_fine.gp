# The paper's Figure 14: the same case on coarse and fine meshes. Top: mean pressure against
# alpha on every level of a convergence study and the closed form; bottom: the relative error
# against the closed form, where the meshes' differences show.
# Usage: gnuplot -e "csv='output/cylinder_T_convergence/convergence.csv'; out='fig14.png';
#                    backends='massspring fem'; name='T'" scripts/plots/coarse_fine.gp
if (!exists("plots")) plots = 'scripts/plots'
if (!exists("backends")) backends = 'massspring fem'
if (!exists("name")) name = 'garment'
load plots.'/style.gp'
set terminal pngcairo size 1100,1100 enhanced font 'DejaVu Sans,15' linewidth 2
set output out

stats csv using "level" nooutput
n_levels = int(STATS_max) + 1
array vertices[n_levels]
do for [l=0:n_levels-1] {
  stats csv using (column("level") == l ? column("n_vertices") : NaN) nooutput
  vertices[l+1] = int(STATS_max)
}
pick(b, l, value) = (strcol("backend") eq b && column("level") == l) ? value : NaN
# The settling step (alpha just above 1, closed form about 1 Pa) is left out of the error.
pick_loaded(b, l, value) = column("alpha") > 1.01 ? pick(b, l, value) : NaN
level_title(b, l) = sprintf("%s, %d vertices", b, vertices[l+1])
style(i, l) = 1 + (i - 1) * n_levels + l

set multiplot layout 2,1 title sprintf("Coarse and fine meshes, garment '%s'", name) noenhanced
set xlabel 'deformation ratio {/Symbol a} = r / R_0'
set xrange [1:*]
set ylabel 'mean contact pressure [Pa]'
set yrange [0:*]
plot for [i=1:words(backends)] for [l=0:n_levels-1] \
         csv using "alpha":(pick(word(backends, i), l, column("p_mean_Pa"))) \
         with linespoints ls style(i, l) title level_title(word(backends, i), l) noenhanced, \
     csv using "alpha":(pick(word(backends, 1), 0, column("p_theory_Pa"))) with lines ls 3 \
         title 'closed form'
set ylabel 'error against closed form [%]'
set yrange [*:*]
set key bottom right
plot for [i=1:words(backends)] for [l=0:n_levels-1] \
         csv using "alpha":(pick_loaded(word(backends, i), l, 100 * column("rel_error"))) \
         with linespoints ls style(i, l) title level_title(word(backends, i), l) noenhanced, \
     0 with lines ls 3 notitle
unset multiplot
