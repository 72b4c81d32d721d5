#!/usr/bin/env bash
# Draws the paper's figures from the CSV files tightfit wrote, with gnuplot (Debian's
# gnuplot-nox), into a figures folder, each PNG beside a copy of the CSV it was drawn from.
# A figure whose CSV is missing is skipped with a note.
#
# Usage: scripts/plot-figures.sh [RESULTS_DIR [FIGURES_DIR]]
#   RESULTS_DIR  where the runs wrote (default output), read as:
#     cylinder_T/, cylinder_45T/        tightfit run cases/cylinder_T.prm cases/cylinder_45T.prm
#     cylinder_T_compare/               tightfit compare cases/cylinder_T.prm
#     cylinder_T_gravity/               the same case with gravity (optional)
#     cylinder_T_convergence/           tightfit convergence cases/cylinder_T.prm
#     coarse_fine.csv                   both backends on garment 4 5T's coarse and fine meshes
#                                       (optional; written by validation-report.sh in
#                                       convergence.csv's columns)
#   Figure 6 is cylinder_T/pressure_steps.png, drawn by the run itself.
#   FIGURES_DIR  where the PNGs go (default docs/figures)
set -euo pipefail
cd "$(dirname "$0")/.."
results=${1:-output}
figures=${2:-docs/figures}
plots=scripts/plots
mkdir -p "$figures"

# has_rows CSV: the file exists and holds a row below its header.
has_rows() { [[ -s $1 && $(wc -l <"$1") -gt 1 ]]; }

# plot FIGURE SCRIPT GNUPLOT_SETTINGS CSV...: draws $figures/FIGURE.png when every CSV has rows,
# and copies each CSV beside it as FIGURE.<parent folder>.csv (FIGURE.csv when only one).
plot() {
  local figure=$1 script=$2 settings=$3
  shift 3
  for csv in "$@"; do
    if ! has_rows "$csv"; then
      echo "  $figure: skipped ($csv is missing)"
      return 0
    fi
  done
  gnuplot -e "plots='$plots'; out='$figures/$figure.png'; $settings" "$plots/$script"
  if [[ $# -eq 1 ]]; then
    cp "$1" "$figures/$figure.csv"
  else
    for csv in "$@"; do cp "$csv" "$figures/$figure.$(basename "$(dirname "$csv")").csv"; done
  fi
  echo "  $figure.png"
}

# The backends named in a convergence.csv, in order of appearance.
backends_in() { tail -n +2 "$1" | cut -d, -f1 | awk '!seen[$0]++' | tr '\n' ' '; }

T=$results/cylinder_T
T45=$results/cylinder_45T
compare=$results/cylinder_T_compare
gravity=$results/cylinder_T_gravity
convergence=$results/cylinder_T_convergence/convergence.csv

echo "Figures from $results into $figures:"
# Figure 6: the garment coloured by pressure at four load steps (settled, 1.2, 1.5 and the
# last) on one colour scale, drawn by tightfit itself (cases/cylinder_T.prm's pictures,
# Panels at alpha: pressure_steps.png).
if [[ -s $T/pressure_steps.png ]]; then
  cp "$T/pressure_steps.png" "$figures/fig06_pressure_map.png"
  cp "$T/pressure.csv" "$figures/fig06_pressure_map.csv"
  echo "  fig06_pressure_map.png"
else
  echo "  fig06_pressure_map: skipped (no pressure_steps.png in $T)"
fi
plot fig07_pressure_radius pressure_radius.gp \
  "csv='$T/pressure.csv'; name='T'" "$T/pressure.csv"
plot fig08_garment_sizes garment_sizes.gp \
  "csv1='$T/pressure.csv'; name1='T'; csv2='$T45/pressure.csv'; name2='4 5T'" \
  "$T/pressure.csv" "$T45/pressure.csv"
if has_rows "$compare/massspring/pressure.csv" && has_rows "$compare/fem/pressure.csv"; then
  plot fig10_pressure_alpha pressure_alpha.gp \
    "files='$compare/massspring/pressure.csv $compare/fem/pressure.csv'; \
     labels='\"mass-spring backend\" \"FEM backend\"'; name='T'" \
    "$compare/massspring/pressure.csv" "$compare/fem/pressure.csv"
else
  plot fig10_pressure_alpha pressure_alpha.gp \
    "files='$T/pressure.csv'; labels='tightfit'; name='T'" "$T/pressure.csv"
fi
plot fig11_pressure_theta pressure_theta.gp \
  "files='$T/pressure_theta.csv'; labels='\"no gravity\"'; name='T'" "$T/pressure_theta.csv"
if has_rows "$gravity/pressure_theta.csv"; then
  plot fig13_pressure_theta_gravity pressure_theta.gp \
    "files='$T/pressure_theta.csv $gravity/pressure_theta.csv'; \
     labels='\"no gravity\" \"with gravity\"'; name='T'" \
    "$T/pressure_theta.csv" "$gravity/pressure_theta.csv"
fi
if has_rows "$convergence"; then
  backends=$(backends_in "$convergence")
  plot convergence_error convergence_error.gp \
    "csv='$convergence'; backends='$backends'" "$convergence"
  if ! has_rows "$results/coarse_fine.csv"; then
    plot fig14_coarse_fine coarse_fine.gp \
      "csv='$convergence'; backends='$backends'; name='T'" "$convergence"
  fi
else
  echo "  convergence_error: skipped ($convergence is missing)"
fi
if has_rows "$results/coarse_fine.csv"; then
  plot fig14_coarse_fine coarse_fine.gp \
    "csv='$results/coarse_fine.csv'; backends='massspring fem'; name='4 5T'" \
    "$results/coarse_fine.csv"
fi
