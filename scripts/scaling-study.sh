#!/usr/bin/env bash
# Scaling study: CPU time and peak memory per load step against the vertex count, on the paper's
# 4 5T tube (cases/cylinder_45T.prm) at finer and finer `Garment/Mesh scale`, for the
# mass-spring backend (implicit integrator; RK4 on the smaller meshes) and the FE backend
# (direct solver on 1 rank and on 2 MPI ranks, CG with BoomerAMG on the smaller meshes, GMRES
# with GAMG).
#
# Each configuration runs once, settled and taken to alpha 1.1: the load step to alpha 1.05 is
# the garment's first state in contact (the hardest: the tube stretches from zero tension onto
# the body), the step to 1.1 a typical later one (predicted from the last two states). Their
# CPU times are the backend's own, from the step lines of solver.log (`... s CPU`, this
# process's or MPI rank 0's std::clock): CPU time, because the machine is shared and wall time
# there says little. The peak memory is /usr/bin/time's maximum resident set of the run (with
# mpirun the largest rank: memory per rank), which includes the program's libraries (about
# 60 MB).
#
# Writes docs/figures/scaling.csv, docs/figures/scaling.png (gnuplot, scripts/plots/scaling.gp)
# and the fitted exponents (least squares of log time against log vertex count, meshes of 2000
# vertices and more) to docs/figures/scaling_fit.txt. Runs under `nice`, one configuration at a time.
#
# Usage: scripts/scaling-study.sh [SCALE ...]
#   SCALE: mesh scales, default 1 0.5 0.25 0.18 0.125 0.09 0.073 (552 to 96600 vertices)
#   TIGHTFIT=path/to/tightfit overrides the executable (default build/app/tightfit).
#   RK4_MIN_SCALE (default 0.5): RK4 runs only down to this mesh scale.
#   FE_RANKS (default "1 2"); FE_MPI_MIN_SCALE (default 0.125): more than one rank only down to
#   this scale. CG_MIN_SCALE (default 0.25): CG with BoomerAMG only down to this scale.
#   GAMG_MIN_SCALE (default 0.073): GMRES with GAMG down to this scale. The loose tube's settle
#   (a singular tangent) defeats it and falls back to MUMPS, which also solves the first state
#   in contact (the solver asked for returns once the garment presses): only the next state is
#   GAMG's, and the figure leaves this route out.
#   BLAS_DIR: a folder with another libblas.so.3 (e.g. OpenBLAS's), put first on
#   LD_LIBRARY_PATH for the runs; the table's route names get a suffix "+blas".
#   APPEND=1: add to the table of an earlier run instead of starting it afresh.
#   STUDY (default "all"): "gamg" runs only the GAMG footprint below, "runs" only the runs above.
#
# The GAMG footprint: build/bench/fem_solver_footprint (CG with GAMG, falling back to GMRES with
# GAMG at an indefinite preconditioner) from a start in contact, on FE_RANKS ranks at every
# scale, so that neither the loose settle nor MUMPS enters. Per rank it reports the resident set
# with MPI and PETSc started (the libraries' floor, which no distribution lowers), after the
# garment's mesh, after the backend's setup, and its peak. Writes
# docs/figures/scaling_gamg.csv (the largest rank's numbers), the fitted exponents of CPU time
# and of the peak above the floor against the vertex count to docs/figures/scaling_gamg_fit.txt,
# and docs/figures/scaling_gamg.png (scripts/plots/scaling_gamg.gp). The table's last column is
# the largest rank's peak during the setup (the triangulation and DoF handler alive), before the
# solve.
#   GAMG_MEMORY (default fast): the bench's `Finite elements/Iterative solver memory`; "lean"
#   writes scaling_gamg_lean.csv, _fit.txt and .png instead.
#   PLOT_ONLY=1: no runs; fit and draw the existing table again.
set -uo pipefail
cd "$(dirname "$0")/.."
tightfit=${TIGHTFIT:-build/app/tightfit}
[[ -x $tightfit ]] || { echo "no $tightfit: build first (scripts/build.sh)" >&2; exit 2; }
scales=("$@")
[[ ${#scales[@]} -gt 0 ]] || scales=(1 0.5 0.25 0.18 0.125 0.09 0.073)
rk4_min=${RK4_MIN_SCALE:-0.5}
fe_ranks=${FE_RANKS:-1 2}
mpi_min=${FE_MPI_MIN_SCALE:-0.125}
cg_min=${CG_MIN_SCALE:-0.25}
gamg_min=${GAMG_MIN_SCALE:-0.073}
suffix=""
if [[ -n ${BLAS_DIR:-} ]]; then
  export LD_LIBRARY_PATH=$BLAS_DIR${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
  suffix="+blas"
fi
results=output/scaling
figures=docs/figures
mkdir -p "$results" "$figures"
table=$figures/scaling${suffix:+_blas}.csv
# APPEND=1 adds rows to the table of an earlier run (a study done in parts).
plot_only=${PLOT_ONLY:-0}
[[ ($plot_only == 1 || ${APPEND:-0} == 1 || ${STUDY:-all} == gamg) && -f $table ]] ||
  echo "route,ranks,mesh_scale,n_vertices,first_contact_cpu_s,first_contact_iterations,next_step_cpu_s,next_step_iterations,peak_rss_MB,peak_kB_per_vertex,status" >"$table"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1

at_least() { awk -v s="$1" -v m="$2" 'BEGIN { exit !(s >= m) }'; }
# step_field LOG STEP: "CPU_SECONDS ITERATIONS" of load step STEP in solver.log.
step_field() {
  grep "^step $2," "$1" | sed -E 's/.*[ (]([0-9.e+-]+) s CPU\).*/\1/' | tr '\n' ' '
  grep "^step $2," "$1" | grep -oE '(newton|after) [0-9]+' | head -1 | grep -oE '[0-9]+'
}

# measure ROUTE RANKS SCALE ARGS...: one configuration, one row of the table.
measure() {
  local route=$1$suffix ranks=$2 scale=$3
  shift 3
  local dir=$results/${route}_np${ranks}_s${scale}
  local launcher=("$tightfit")
  [[ $ranks -gt 1 ]] && launcher=(mpirun -np "$ranks" "$tightfit")
  echo "== $route, $ranks rank(s), mesh scale $scale"
  rm -rf "$dir"
  mkdir -p "$dir"
  /usr/bin/time -v -o "$dir/time.txt" nice "${launcher[@]}" run cases/cylinder_45T.prm \
    --output "$dir" --set "Garment/Mesh scale=$scale" --set "Protocol/Final alpha=1.1" \
    --set "Output/Write VTU=false" "$@" >"$dir/run.log" 2>&1
  local status=$?
  local vertices rss first next per_vertex
  vertices=$(grep -o -m1 'mesh: [0-9]* vertices' "$dir/run.log" | grep -o '[0-9]*')
  rss=$(awk -F': ' '/Maximum resident set size/ {printf "%.1f", $2 / 1024}' "$dir/time.txt")
  read -r -a first <<<"$(step_field "$dir/solver.log" 5 2>/dev/null)"
  read -r -a next <<<"$(step_field "$dir/solver.log" 6 2>/dev/null)"
  per_vertex=$(awk -v m="$rss" -v n="${vertices:-0}" 'BEGIN { if (n > 0) printf "%.1f", m * 1024 / n }')
  echo "$route,$ranks,$scale,${vertices:-},${first[0]:-},${first[1]:-},${next[0]:-},${next[1]:-},${rss:-},$per_vertex,$status" |
    tee -a "$table"
}

study=${STUDY:-all}
gamg_memory=${GAMG_MEMORY:-fast}
gamg_suffix=${suffix:+_blas}
[[ $gamg_memory == fast ]] || gamg_suffix+=_$gamg_memory
gamg_table=$figures/scaling_gamg$gamg_suffix.csv
footprint=${FOOTPRINT:-build/bench/fem_solver_footprint}
# footprint RANKS SCALE: one row of the GAMG footprint table.
footprint() {
  local ranks=$1 scale=$2 dir=$results/gamg-footprint${gamg_suffix}_np$1_s$2
  local launcher=("$footprint")
  [[ $ranks -gt 1 ]] && launcher=(mpirun -np "$ranks" "$footprint")
  echo "== GAMG footprint, $ranks rank(s), mesh scale $scale"
  mkdir -p "$dir"
  nice "${launcher[@]}" "$scale" cg-gamg 1.1 "$gamg_memory" >"$dir/run.log" 2>&1
  local status=$?
  # The largest rank's line: "rank R of N: V vertices, cg-gamg: resident F MB with MPI ...,
  # M MB with the mesh, S MB after setup, peak P MB (A MB above the first); C s CPU, ...;
  # setup peak Q MB; ..." and the step's Newton iterations.
  local newton setup_peak
  newton=$(grep -oE '^newton [0-9]+' "$dir/run.log" | grep -oE '[0-9]+')
  setup_peak=$(grep -oE 'setup peak [0-9]+' "$dir/run.log" | grep -oE '[0-9]+' | sort -n | tail -1)
  grep '^rank ' "$dir/run.log" | sed -E 's/^rank [0-9]+ of [0-9]+: ([0-9]+) vertices, [a-z-]+: resident ([0-9]+) MB with MPI and PETSc started, ([0-9]+) MB with the mesh, ([0-9]+) MB after setup, peak ([0-9]+) MB \(([0-9-]+) MB above the first\); ([0-9.]+) s CPU.*/\1 \2 \3 \4 \5 \6 \7/' |
    sort -k5 -n | tail -1 | while read -r v floor mesh setup peak above cpu; do
    echo "$ranks,$scale,$v,${newton:-},$cpu,$floor,$mesh,$setup,$peak,$above,$status,${setup_peak:-}" | tee -a "$gamg_table"
  done
}
if [[ $plot_only != 1 && $study != runs ]]; then
  [[ ${APPEND:-0} == 1 && -f $gamg_table ]] ||
    echo "ranks,mesh_scale,n_vertices,newton_iterations,cpu_s,floor_MB,with_mesh_MB,after_setup_MB,peak_MB,peak_above_floor_MB,status,setup_peak_MB" >"$gamg_table"
  for scale in "${scales[@]}"; do
    for ranks in $fe_ranks; do footprint "$ranks" "$scale"; done
  done
fi
if [[ -f $gamg_table ]]; then
  # Least squares of log y against log N over the meshes of 2000 vertices and more, per rank
  # count: y the CPU time, then the peak above the floor.
  awk -F, 'NR > 1 && $11 == 0 && $3 >= 2000 {
             k = $1; x = log($3); n[k]++; sx[k] += x; sxx[k] += x * x;
             t = log($5); st[k] += t; sxt[k] += x * t; m = log($10); sm[k] += m; sxm[k] += x * m }
           END { for (k in n) if (n[k] >= 2) {
                   d = n[k] * sxx[k] - sx[k] * sx[k];
                   printf "GAMG footprint, %d rank(s): CPU time ~ N^%.2f, peak above the floor ~ N^%.2f (%d meshes)\n",
                          k, (n[k] * sxt[k] - sx[k] * st[k]) / d, (n[k] * sxm[k] - sx[k] * sm[k]) / d, n[k] } }' \
    "$gamg_table" | sort | tee "$figures/scaling_gamg${gamg_suffix}_fit.txt"
  if command -v gnuplot >/dev/null; then
    gnuplot -e "csv='$gamg_table'; out='$figures/scaling_gamg${gamg_suffix}.png'; \
      memory='$gamg_memory'" scripts/plots/scaling_gamg.gp
  fi
fi
[[ $study == gamg ]] && exit 0

[[ $plot_only == 1 ]] && scales=()
for scale in "${scales[@]}"; do
  measure massspring-implicit 1 "$scale" --set "Solver/Backend=massspring" \
    --set "Mass spring/Integrator=implicit"
  at_least "$scale" "$rk4_min" && measure massspring-rk4 1 "$scale" --set "Solver/Backend=massspring"
  for ranks in $fe_ranks; do
    [[ $ranks -gt 1 ]] && ! at_least "$scale" "$mpi_min" && continue
    measure fem-direct "$ranks" "$scale" --set "Solver/Backend=fem" \
      --set "Finite elements/Linear solver=direct"
  done
  at_least "$scale" "$cg_min" && measure fem-cg-amg 1 "$scale" --set "Solver/Backend=fem" \
    --set "Finite elements/Linear solver=cg-amg"
  # 200 Krylov iterations: enough where GAMG converges (at most about 110 measured), and the
  # failing settle falls back to MUMPS sooner.
  at_least "$scale" "$gamg_min" && measure fem-gmres-gamg 1 "$scale" --set "Solver/Backend=fem" \
    --set "Finite elements/Linear solver=gmres-gamg" \
    --set "Finite elements/Maximum linear iterations=200"
done

# Fitted exponent of the time of the first state in contact against the vertex count (meshes
# of 2000 vertices and more, where start-up costs no longer dominate), per route.
fit=$figures/scaling${suffix:+_blas}_fit.txt
awk -F, 'NR > 1 && $11 == 0 && $4 >= 2000 && $5 > 0 {
           k = $1 " np" $2; x = log($4); y = log($5); n[k]++; sx[k] += x; sy[k] += y;
           sxx[k] += x * x; sxy[k] += x * y; mem[k] = $10; big[k] = $4 }
         END { for (k in n) if (n[k] >= 2) {
                 b = (n[k] * sxy[k] - sx[k] * sy[k]) / (n[k] * sxx[k] - sx[k] * sx[k]);
                 printf "%s: first state in contact ~ N^%.2f (%d meshes); peak memory %.1f kB per vertex at %d vertices\n", k, b, n[k], mem[k], big[k] } }' \
  "$table" | sort | tee "$fit"

if command -v gnuplot >/dev/null; then
  gnuplot -e "csv='$table'; out='$figures/scaling${suffix:+_blas}.png'; suffix='$suffix'" \
    scripts/plots/scaling.gp
fi
echo "table $table, fits $fit, figure $figures/scaling${suffix:+_blas}.png"
