# The relative difference (Eq. 3 - simulated) / simulated of every stamp against alpha, for one
# or more runs' stamps.csv.
# Usage: gnuplot -e "files='a/stamps.csv b/stamps.csv'; labels='massspring fem';
#                    out='stamps_eq3_error.png'; name='T'" scripts/plots/stamps_eq3_error.gp
if (!exists("plots")) plots = 'scripts/plots'
if (!exists("name")) name = 'garment'
load plots.'/style.gp'

set title sprintf("Eq. 3 against the simulated pressure at each stamp, garment '%s'", name) noenhanced
set xlabel 'deformation ratio {/Symbol a} = r / R_0'
set ylabel '(Eq. 3 - simulated) / simulated [%]'
set key bottom right

plot for [i=1:words(files)] word(files, i) using "alpha":(100 * column("rel_difference")) \
         with points ls i pt (i == 1 ? 6 : 2) ps 1.6 title word(labels, i) noenhanced
