# The paper's Figure 8: pressure against the cylinder's radius for two garment sizes (the
# smaller garment presses harder on the same cylinder), simulated beside the closed form.
# Usage: gnuplot -e "csv1='output/cylinder_T/pressure.csv'; name1='T';
#                    csv2='output/cylinder_45T/pressure.csv'; name2='4 5T'; out='fig8.png'" \
#                scripts/plots/garment_sizes.gp
if (!exists("plots")) plots = 'scripts/plots'
load plots.'/style.gp'

set title 'Pressure on the growing cylinder: two garment sizes'
set xlabel 'cylinder radius r [cm]'
set ylabel 'mean contact pressure [Pa]'
set y2label 'mean contact pressure [gf/cm^2]'
set yrange [0:*]

@dry_run
plot csv1 using (100 * column("radius_m")):"p_mean_Pa" with linespoints ls 1 title sprintf("'%s' simulated", name1), \
     csv1 using (100 * column("radius_m")):"p_theory_Pa" with lines ls 3 dt 2 lw 1.5 title 'closed forms', \
     csv2 using (100 * column("radius_m")):"p_mean_Pa" with linespoints ls 2 title sprintf("'%s' simulated", name2), \
     csv2 using (100 * column("radius_m")):"p_theory_Pa" with lines ls 3 dt 2 lw 1.5 notitle
@with_gf_axis
