# A design's pressure profile along the limb (docs/design.md): at each measuring point the
# target, Laplace's law on the designed circumference, the simulated band mean and peak, and the
# check backend's mean where design.csv has it. x: height along the garment.
# Usage: gnuplot -e "csv='output/design_stocking/design.csv'; out='design_profile.png'; \
#                    name='class II'" scripts/plots/design_profile.gp
if (!exists("plots")) plots = 'scripts/plots'
if (!exists("name")) name = 'design'
load plots.'/style.gp'
set key top right box opaque
set title sprintf("Designed stocking, %s: band pressures along the leg", name) noenhanced
set xlabel 'height along the stocking H [cm]'
set ylabel 'pressure [mmHg]'
set yrange [0:*]
set offsets 2, 6, 20, 0   # room above the peaks for the key
has_check = system(sprintf("head -1 '%s' | grep -c check_mean_mmHg", csv)) + 0
plot csv using (100 * column("height_m")):"laplace_mmHg" with linespoints ls 4 pt 4 ps 1.4 title "Laplace's law", \
     csv using (100 * column("height_m")):"mean_mmHg" with linespoints ls 1 title 'simulated mean (mass spring)', \
     csv using (100 * column("height_m")):"peak_mmHg" with linespoints ls 2 title 'simulated peak (mass spring)', \
     for [i=1:has_check] csv using (100 * column("height_m")):"check_mean_mmHg" with points ls 5 title 'simulated mean (FE check)', \
     csv using (100 * column("height_m")):"target_mmHg" with points ls 3 pt 6 ps 2.2 title 'target', \
     csv using (100 * column("height_m")):"peak_mmHg":"point" with labels offset 0,1.1 notitle
