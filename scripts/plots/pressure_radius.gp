# The paper's Figure 7: mean contact pressure against the cylinder's radius, beside the closed
# form and the paper's Eq. 7, in Pa (left) and the paper's gf/cm^2 (right).
# Usage: gnuplot -e "csv='output/cylinder_T/pressure.csv'; out='fig7.png'; name='T'" \
#                scripts/plots/pressure_radius.gp
if (!exists("plots")) plots = 'scripts/plots'
if (!exists("name")) name = 'garment'
load plots.'/style.gp'

set title sprintf("Pressure on the growing cylinder, garment '%s'", name) noenhanced
set xlabel 'cylinder radius r [cm]'
set ylabel 'mean contact pressure [Pa]'
set y2label 'mean contact pressure [gf/cm^2]'
set yrange [0:*]

@dry_run
plot csv using (100 * column("radius_m")):"p_mean_Pa" with linespoints ls 1 title 'tightfit (simulated)', \
     csv using (100 * column("radius_m")):"p_theory_Pa" with lines ls 3 title 'closed form (law in use)', \
     csv using (100 * column("radius_m")):"p_eq7_Pa" with lines ls 4 title "paper's Eq. 7"
@with_gf_axis
