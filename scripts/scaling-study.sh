#!/usr/bin/env bash
# Scaling study: time and peak memory per load step against the vertex count, on the paper's
# 4 5T tube (cases/cylinder_45T.prm) at finer and finer `Garment/Mesh scale`, for the
# mass-spring backend (implicit integrator; RK4 on the smaller meshes) and the FE backend
# (1 and 2 MPI ranks). Each configuration runs twice: settled and taken to alpha 1.0 (no
# contact yet), and on to alpha 1.15 (three load steps in contact). The time per load step is
# the difference of the two runs' CPU time (/usr/bin/time's user time; with mpirun the ranks'
# sum) over three: CPU time, because the machine is shared and wall time there says little.
# The peak memory is /usr/bin/time's maximum resident set of the longer run (with mpirun: the
# largest rank, so memory per rank). Writes docs/figures/scaling.csv, docs/figures/scaling.png
# and the fitted exponents (least squares of log time against log vertex count) to
# docs/figures/scaling_fit.txt. Runs under `nice`.
#
# Usage: scripts/scaling-study.sh [SCALE ...]   (mesh scales, default 1 0.5 0.35 0.25 0.18 0.125)
#   TIGHTFIT=path/to/tightfit overrides the executable (default build/app/tightfit).
#   RK4_MIN_SCALE (default 0.25): RK4 runs only down to this mesh scale.
#   FE_RANKS (default "1 2").
set -uo pipefail
cd "$(dirname "$0")/.."
tightfit=${TIGHTFIT:-build/app/tightfit}
[[ -x $tightfit ]] || { echo "no $tightfit: build first (scripts/build.sh)" >&2; exit 2; }
scales=("$@")
[[ ${#scales[@]} -gt 0 ]] || scales=(1 0.5 0.35 0.25 0.18 0.125)
rk4_min=${RK4_MIN_SCALE:-0.25}
fe_ranks=${FE_RANKS:-1 2}
results=output/scaling
figures=docs/figures
mkdir -p "$results" "$figures"
table=$figures/scaling.csv
echo "route,ranks,mesh_scale,n_vertices,step_cpu_s,peak_rss_MB,total_user_s,status" >"$table"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1

# run_to DIR ALPHA LAUNCHER... -- ARGS...: one run under /usr/bin/time into DIR; prints its
# exit status.
run_to() {
  local dir=$1 alpha=$2
  shift 2
  rm -rf "$dir"
  mkdir -p "$dir"
  /usr/bin/time -v -o "$dir/time.txt" nice "$@" run cases/cylinder_45T.prm --output "$dir" \
    --set "Protocol/Final alpha=$alpha" --set "Output/Write VTU=false" "${args[@]}" \
    >"$dir/run.log" 2>&1
  echo $?
}
user_s() { awk -F': ' '/User time/ {print $2}' "$1/time.txt"; }

# measure ROUTE RANKS SCALE ARGS...: one configuration, one row of the table.
measure() {
  local route=$1 ranks=$2 scale=$3
  shift 3
  args=(--set "Garment/Mesh scale=$scale" "$@")
  local dir=$results/${route}_np${ranks}_s${scale}
  local launcher=("$tightfit")
  [[ $ranks -gt 1 ]] && launcher=(mpirun -np "$ranks" "$tightfit")
  echo "== $route, $ranks rank(s), mesh scale $scale"
  local base_status status
  base_status=$(run_to "$dir/to_1.0" 1.0 "${launcher[@]}")
  status=$(run_to "$dir/to_1.15" 1.15 "${launcher[@]}")
  [[ $base_status -eq 0 ]] || status=$base_status
  local vertices rss user base step
  vertices=$(grep -o -m1 'mesh: [0-9]* vertices' "$dir/to_1.15/run.log" | grep -o '[0-9]*')
  rss=$(awk -F': ' '/Maximum resident set size/ {printf "%.1f", $2 / 1024}' "$dir/to_1.15/time.txt")
  user=$(user_s "$dir/to_1.15")
  base=$(user_s "$dir/to_1.0")
  step=$(awk -v a="$user" -v b="$base" 'BEGIN { printf "%.3g", (a - b) / 3 }')
  echo "$route,$ranks,$scale,${vertices:-},${step:-},${rss:-},${user:-},$status" | tee -a "$table"
}

for scale in "${scales[@]}"; do
  measure massspring-implicit 1 "$scale" --set "Solver/Backend=massspring" \
    --set "Mass spring/Integrator=implicit"
  if awk -v s="$scale" -v m="$rk4_min" 'BEGIN { exit !(s >= m) }'; then
    measure massspring-rk4 1 "$scale" --set "Solver/Backend=massspring"
  fi
  for ranks in $fe_ranks; do
    measure fem "$ranks" "$scale" --set "Solver/Backend=fem"
  done
done

# Fitted exponent of the time per load step against the vertex count (from the meshes of 2000
# vertices and more, where start-up costs no longer dominate), per route.
fit=$figures/scaling_fit.txt
awk -F, 'NR > 1 && $8 == 0 && $4 >= 2000 && $5 > 0 {
           k = $1 " np" $2; x = log($4); y = log($5); n[k]++; sx[k] += x; sy[k] += y;
           sxx[k] += x * x; sxy[k] += x * y; mem[k] = $6 * 1024 / $4 }
         END { for (k in n) if (n[k] >= 2) {
                 b = (n[k] * sxy[k] - sx[k] * sy[k]) / (n[k] * sxx[k] - sx[k] * sx[k]);
                 printf "%s: time per load step ~ N^%.2f (%d meshes); peak memory at the largest %.1f kB per vertex\n", k, b, n[k], mem[k] } }' \
  "$table" | sort | tee "$fit"

if command -v gnuplot >/dev/null; then
  gnuplot <<GNUPLOT
set terminal pngcairo size 900,600
set output "$figures/scaling.png"
set datafile separator ","
set logscale xy
set xlabel "vertices"
set ylabel "CPU time per load step [s]"
set key top left
set grid
set title "4 5T tube, one load step in contact (alpha 1.05-1.15)"
plot "< awk -F, '\$1 == \"massspring-implicit\" && \$8 == 0' $table" using 4:5 with linespoints title "mass-spring, implicit", \
     "< awk -F, '\$1 == \"massspring-rk4\" && \$8 == 0' $table" using 4:5 with linespoints title "mass-spring, RK4", \
     "< awk -F, '\$1 == \"fem\" && \$2 == 1 && \$8 == 0' $table" using 4:5 with linespoints title "FE, 1 rank", \
     "< awk -F, '\$1 == \"fem\" && \$2 == 2 && \$8 == 0' $table" using 4:5 with linespoints title "FE, 2 ranks", \
     [2000:100000] 1e-4 * (x / 1000.0)**1.5 with lines dashtype 2 title "N^1.5"
GNUPLOT
fi
echo "table $table, fits $fit, figure $figures/scaling.png"
