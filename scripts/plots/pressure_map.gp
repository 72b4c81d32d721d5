# The paper's Figure 6: the garment coloured by contact pressure on the growing cylinder, one
# panel per load step, on one colour scale so the panels compare. Reads the polygon files
# scripts/plots/vtu_triangles.py writes from the garment VTUs (x y z in cm, pressure in Pa).
# Usage: gnuplot -e "files='a.dat b.dat'; labels='1.2 1.8'; means='451 1378'; pmax=1500; levels=48;
#                    out='fig06.png'; name='T'" scripts/plots/pressure_map.gp
# (files written by vtu_triangles.py with the same pmax and levels).
if (!exists("plots")) plots = 'scripts/plots'
if (!exists("name")) name = 'garment'
if (!exists("levels")) levels = 48
load plots.'/style.gp'
n = words(files)
panel_px = 280
width_px = panel_px * n + 170
set terminal pngcairo size width_px, 440 enhanced font 'DejaVu Sans,13'
set output out
set datafile separator whitespace
unset grid
unset key

# Cylinder axis along x (cases/cylinder_*.prm), seen from the side and a little above.
set view 62, 28, 1.5, 1.5
set view equal xyz
set xyplane 0
set xrange [-12:12]
set yrange [-10:10]
set zrange [-10:10]
unset xtics
unset ytics
unset ztics
set border 0
# A turbo-like colour map. gnuplot 5.4 fills `with polygons` in one fixed colour per plot (a
# palette colour is not honoured), so each level is drawn in the colour level_rgb() computes
# from these stops, and the palette below (the same stops) draws the colour box.
array stop_f[8] = [0, 0.15, 0.35, 0.5, 0.65, 0.8, 0.9, 1]
array stop_c[8] = [0x30123b, 0x4662d7, 0x36aaf9, 0x1ae4b6, 0x72fe5e, 0xefcd3a, 0xfb8022, 0x7a0403]
channel(c, shift) = (int(c) >> shift) & 255
mix(a, b, t, shift) = int(channel(a, shift) + t * (channel(b, shift) - channel(a, shift)) + 0.5)
segment(f) = (f >= stop_f[7]) ? 7 : (f >= stop_f[6]) ? 6 : (f >= stop_f[5]) ? 5 : \
             (f >= stop_f[4]) ? 4 : (f >= stop_f[3]) ? 3 : (f >= stop_f[2]) ? 2 : 1
rgb_in(f, i) = sprintf('#%02x%02x%02x', \
  mix(stop_c[i], stop_c[i + 1], (f - stop_f[i]) / (stop_f[i + 1] - stop_f[i]), 16), \
  mix(stop_c[i], stop_c[i + 1], (f - stop_f[i]) / (stop_f[i + 1] - stop_f[i]), 8), \
  mix(stop_c[i], stop_c[i + 1], (f - stop_f[i]) / (stop_f[i + 1] - stop_f[i]), 0))
level_rgb(k) = rgb_in((k + 0.5) / levels, segment((k + 0.5) / levels))
set palette defined (0 '#30123b', 0.15 '#4662d7', 0.35 '#36aaf9', 0.5 '#1ae4b6', \
                     0.65 '#72fe5e', 0.8 '#efcd3a', 0.9 '#fb8022', 1 '#7a0403')
set palette maxcolors levels
set cbrange [0:pmax]
set cbtics font ',12'
set cblabel 'contact pressure [Pa]' font ',13' offset 1.5, 0
set pm3d depthorder border lc rgb '#404040' lw 0.3
set style fill solid 1.0

panel_w = (1.0 * panel_px) / width_px
set multiplot title \
  sprintf("Contact pressure on the growing cylinder, garment '%s' (the paper's Figure 6)", name) \
  noenhanced font ',16'
unset colorbox
do for [i=1:n] {
  set origin (i - 1) * panel_w, 0.0
  set size panel_w, 0.92
  set label 1 sprintf('{/Symbol a} = r / R_0 = %s', word(labels, i)) \
    at screen (i - 0.5) * panel_w, 0.80 center font ',14'
  if (exists("means")) {
    set label 2 sprintf('mean %s Pa', word(means, i)) at screen (i - 0.5) * panel_w, 0.20 \
      center font ',13'
  }
  splot for [k=0:levels-1] word(files, i) index k using 1:2:3 with polygons \
    fillcolor rgb level_rgb(k)
}
unset label
# The colour box, drawn by an empty plot that uses the palette.
set origin n * panel_w, 0.0
set size 1.0 - n * panel_w, 0.92
unset title
set colorbox vertical user origin n * panel_w + 0.015, 0.17 size 0.02, 0.6
set border 0
unset xtics
unset ytics
plot '+' using (NaN):(NaN):(0) with points lc palette
unset multiplot
