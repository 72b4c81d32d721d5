# The paper's Figure 10: pressure against the deformation ratio alpha = r / R0 from one or
# more runs (for example both backends), beside the closed form of the law in use and the
# paper's Eq. 7, P = Et (1 - 1/alpha) / R0. The closed forms are read from the first file.
# Usage: gnuplot -e "files='a/pressure.csv b/pressure.csv'; labels='massspring fem';
#                    out='fig10.png'; name='T'" scripts/plots/pressure_alpha.gp
if (!exists("plots")) plots = 'scripts/plots'
if (!exists("name")) name = 'garment'
load plots.'/style.gp'

first = word(files, 1)
set title sprintf("Pressure against alpha, garment '%s'", name) noenhanced
set xlabel 'deformation ratio {/Symbol a} = r / R_0'
set ylabel 'mean contact pressure [Pa]'
set y2label 'mean contact pressure [gf/cm^2]'
set xrange [1:*]
set yrange [0:*]

@dry_run
plot for [i=1:words(files)] word(files, i) using "alpha":"p_mean_Pa" with linespoints ls i \
         title word(labels, i) noenhanced, \
     first using "alpha":"p_theory_Pa" with lines ls 3 title 'closed form (law in use)', \
     first using "alpha":"p_eq7_Pa" with lines ls 4 title "paper's Eq. 7"
@with_gf_axis
