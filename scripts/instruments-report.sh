#!/usr/bin/env bash
# Runs the paper's garment T with its Table 2 fabric (cases/cylinder_T_table2.prm) on both
# backends with the virtual instruments (air-pack sensors, stamps) and draws Eq. 3 from the
# stamps against the simulated pressure (docs/instruments.md) into docs/figures, each PNG
# beside the CSV files it was drawn from.
#
# Usage: scripts/instruments-report.sh [BUILD_DIR [RESULTS_DIR [FIGURES_DIR]]]
#   defaults: build, output/instruments, docs/figures
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
results=${2:-output/instruments}
figures=${3:-docs/figures}
plots=scripts/plots
mkdir -p "$results" "$figures"

for backend in massspring fem; do
  "$build/app/tightfit" run cases/cylinder_T_table2.prm --output "$results/$backend" \
    --set "Solver/Backend=$backend" --set "Output/Write VTU=false"
done
ms=$results/massspring/stamps.csv
fem=$results/fem/stamps.csv
gnuplot -e "plots='$plots'; out='$figures/stamps_eq3.png'; files='$ms $fem'; \
  labels='\"mass-spring backend\" \"FEM backend\"'; name='T, Table 2 fabric'" "$plots/stamps_eq3.gp"
gnuplot -e "plots='$plots'; out='$figures/stamps_eq3_error.png'; files='$ms $fem'; \
  labels='\"mass-spring backend\" \"FEM backend\"'; name='T, Table 2 fabric'" \
  "$plots/stamps_eq3_error.gp"
for backend in massspring fem; do
  cp "$results/$backend/stamps.csv" "$figures/stamps_eq3.$backend.csv"
  cp "$results/$backend/sensors.csv" "$figures/sensors.$backend.csv"
  cp "$results/$backend/pressure.csv" "$figures/table2_pressure.$backend.csv"
done
echo "  $figures/stamps_eq3.png, $figures/stamps_eq3_error.png"
