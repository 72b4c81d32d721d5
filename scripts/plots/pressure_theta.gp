# The paper's Figures 11 and 13: pressure against the angle round the cylinder at the last
# load step, from one or more runs (with and without gravity, say), beside the closed form
# (uniform round the circle). Angle 0 and its direction are those of pressure_theta.csv.
# Usage: gnuplot -e "files='a/pressure_theta.csv b/pressure_theta.csv';
#                    labels='no_gravity gravity'; out='fig11.png'; name='T'" \
#                scripts/plots/pressure_theta.gp
if (!exists("plots")) plots = 'scripts/plots'
if (!exists("name")) name = 'garment'
load plots.'/style.gp'

first = word(files, 1)
stats first using "alpha" nooutput
set title sprintf("Pressure round the cylinder, garment '%s', alpha = %.2f", name, STATS_max) noenhanced
set xlabel 'angle round the cylinder {/Symbol q} [deg]'
set ylabel 'contact pressure [Pa]'
set y2label 'contact pressure [gf/cm^2]'
set xrange [0:360]
set xtics 45
# Autoscaled, not from zero: the variation round the circle is a few percent at most.
set key bottom right

@dry_run
plot for [i=1:words(files)] word(files, i) using "theta_deg":"pressure_Pa" with linespoints ls i \
         title word(labels, i) noenhanced, \
     first using "theta_deg":"p_theory_Pa" with lines ls 3 title 'closed form'
@with_gf_axis
