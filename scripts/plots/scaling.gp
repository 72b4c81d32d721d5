# docs/performance.md, "Scaling": CPU time of the 4 5T tube's first state in contact (alpha 1.0
# to 1.05) against the vertex count, log-log, one line per solver route, beside an N^1.5 guide.
# Rows are those of scripts/scaling-study.sh's table with status 0; `suffix` picks the routes of
# one BLAS ("" or "+blas").
# Usage: gnuplot -e "csv='docs/figures/scaling.csv'; out='scaling.png'; suffix=''" \
#                scripts/plots/scaling.gp
if (!exists("plots")) plots = 'scripts/plots'
if (!exists("suffix")) suffix = ''
load plots.'/style.gp'
# The header and the rows of one route and rank count that finished (status 0), contiguous so
# that each route is one line.
rows(r, np) = sprintf("< awk -F, 'NR == 1 || ($1 == \"%s\" && $2 == %d && $11 == 0)' %s", \
                      r, np, csv)
set title "4 5T tube: first state in contact (alpha 1.0 -> 1.05), one core unless stated"
set logscale xy
set xlabel 'vertices'
set ylabel 'CPU time of the load step [s]'
plot rows("massspring-implicit".suffix, 1) using "n_vertices":"first_contact_cpu_s" \
         with linespoints ls 1 title "mass-spring, implicit", \
     rows("massspring-rk4".suffix, 1) using "n_vertices":"first_contact_cpu_s" \
         with linespoints ls 2 title "mass-spring, RK4", \
     rows("fem-direct".suffix, 1) using "n_vertices":"first_contact_cpu_s" \
         with linespoints ls 5 title "FE, MUMPS, 1 rank", \
     rows("fem-direct".suffix, 2) using "n_vertices":"first_contact_cpu_s" \
         with linespoints ls 6 title "FE, MUMPS, 2 ranks (rank 0)", \
     rows("fem-cg-amg".suffix, 1) using "n_vertices":"first_contact_cpu_s" \
         with linespoints ls 7 title "FE, CG + BoomerAMG", \
     [2000:100000] 0.5 * (x / 8460.0)**1.5 with lines ls 3 dt 2 title "N^{1.5}"
