# Shared look of tightfit's figures: PNG through cairo, a font legible at half size, a light
# grid, and the CSV format tightfit writes (comma separated, a header line, empty = missing).
# Every figure script loads this first; `out` is the PNG to write.
png_terminal = "set terminal pngcairo size 1100,750 enhanced font 'DejaVu Sans,15' linewidth 2"
@png_terminal
set output out
set datafile separator ','
set datafile missing ''
set grid lc rgb '#d0d0d0' lw 1
set key top left box opaque samplen 3 spacing 1.2
set border lw 1.5
set tics out nomirror
set mxtics 2
set mytics 2

# The paper's unit beside SI: 1 gf/cm^2 = 98.0665 Pa. A plot drawn with `@dry_run`, then
# `@with_gf_axis` gets a right-hand axis in gf/cm^2 matching the left one in Pa (gnuplot's
# `set link` would only relabel the left axis's tics with awkward numbers).
Pa_per_gf_cm2 = 98.0665
dry_run = "set output '/dev/null'"
with_gf_axis = "set yrange [GPVAL_Y_MIN:GPVAL_Y_MAX]; \
  set y2range [GPVAL_Y_MIN / Pa_per_gf_cm2 : GPVAL_Y_MAX / Pa_per_gf_cm2]; set y2tics; \
  set my2tics 2; @png_terminal; set output out; replot"

set style line 1 lc rgb '#0060ad' lw 2.5 pt 7 ps 1.3   # first backend / simulated
set style line 2 lc rgb '#dd181f' lw 2.5 pt 5 ps 1.2   # second backend
set style line 3 lc rgb '#000000' lw 2.0 dt 1          # closed form
set style line 4 lc rgb '#5e9c36' lw 2.0 dt 2          # the paper's Eq. 7
set style line 5 lc rgb '#ff8c00' lw 2.5 pt 9 ps 1.4
set style line 6 lc rgb '#8a2be2' lw 2.5 pt 11 ps 1.4
set style line 7 lc rgb '#2f4f4f' lw 2.5 pt 13 ps 1.4
set style line 8 lc rgb '#b8860b' lw 2.5 pt 3 ps 1.4
