# Eq. 3 from virtual stamps against the simulated contact pressure at each stamp's centre:
# one point per stamp and load step, for one or more runs' stamps.csv, on the line of equality.
# Usage: gnuplot -e "files='a/stamps.csv b/stamps.csv'; labels='massspring fem';
#                    out='stamps_eq3.png'; name='T, Table 2 fabric'" scripts/plots/stamps_eq3.gp
if (!exists("plots")) plots = 'scripts/plots'
if (!exists("name")) name = 'garment'
load plots.'/style.gp'

set title sprintf("Eq. 3 from the stamps against the simulated pressure, garment '%s'", name) noenhanced
set xlabel 'simulated contact pressure at the stamp centre [Pa]'
set ylabel "Eq. 3 from the stamp's fitted stretches [Pa]"
set xrange [0:*]
set yrange [0:*]
set size ratio -1
set key top left

plot for [i=1:words(files)] word(files, i) using "p_sim_Pa":"p_eq3_Pa" with points ls i \
         pt (i == 1 ? 6 : 2) ps 1.6 title word(labels, i) noenhanced, \
     x with lines ls 3 title 'equality'
