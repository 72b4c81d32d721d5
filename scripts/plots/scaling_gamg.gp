# docs/performance.md, "Scaling": the GAMG footprint bench (build/bench/fem_solver_footprint)
# against the vertex count, log-log, on 1 and 2 ranks: left the CPU time of the step (rank 0),
# right the peak resident set per rank, whole and above the libraries' floor. Rows are those of
# scripts/scaling-study.sh's GAMG table with status 0; `memory` names the bench's setting.
# Usage: gnuplot -e "csv='docs/figures/scaling_gamg.csv'; out='scaling_gamg.png'; \
#                    memory='fast'" scripts/plots/scaling_gamg.gp
if (!exists("plots")) plots = 'scripts/plots'
if (!exists("memory")) memory = 'fast'
load plots.'/style.gp'
set terminal pngcairo size 1500,650 enhanced font 'DejaVu Sans,15' linewidth 2
set output out
# The header and the rows of one rank count that finished (status 0).
rows(np) = sprintf("< awk -F, 'NR == 1 || ($1 == %d && $11 == 0)' %s", np, csv)
set multiplot layout 1,2 title sprintf("4 5T tube from a start in contact at alpha 1.1, \
CG/GMRES + GAMG (%s), the solver footprint bench", memory) noenhanced
set logscale xy
set xlabel 'vertices'
set ylabel 'CPU time of the step [s] (rank 0)'
plot rows(1) using "n_vertices":"cpu_s" with linespoints ls 1 title "1 rank", \
     rows(2) using "n_vertices":"cpu_s" with linespoints ls 2 title "2 ranks"
set ylabel 'peak resident set per rank [MB]'
set key bottom right font ',13' samplen 2 spacing 1.1
plot rows(1) using "n_vertices":"peak_MB" with linespoints ls 1 \
         title "1 rank, total", \
     rows(2) using "n_vertices":"peak_MB" with linespoints ls 2 \
         title "2 ranks, total (largest rank)", \
     rows(1) using "n_vertices":"peak_above_floor_MB" with linespoints ls 5 dt 2 \
         title "1 rank, above the floor", \
     rows(2) using "n_vertices":"peak_above_floor_MB" with linespoints ls 6 dt 2 \
         title "2 ranks, above the floor"
unset multiplot
