#!/usr/bin/env bash
# Regenerates docs/validation.md and docs/figures/ from scratch: runs the paper's cylinder
# cases, the cross-backend comparison, the cylinder with gravity, the paper's pressure
# definition, and a mesh-convergence study at modest levels, then draws the figures and
# writes the tables. A few minutes on two cores. The stocking's convergence study by region
# (scripts/stocking-convergence.sh) is rendered from the tables it keeps in docs/figures/.
#
# Usage: scripts/validation-report.sh [--levels N]   (convergence levels, default 3)
#   TIGHTFIT=path/to/tightfit overrides the executable (default build/app/tightfit).
# A run whose solver stops is reported in the document; the script carries on.
set -uo pipefail
cd "$(dirname "$0")/.."
levels=3
if [[ ${1:-} == --levels ]]; then levels=$2; fi
tightfit=${TIGHTFIT:-build/app/tightfit}
results=output/validation
figures=docs/figures
report=docs/validation.md
[[ -x $tightfit ]] || { echo "no $tightfit: build first (scripts/build.sh)" >&2; exit 2; }
# The report names the commit it was made from, read before anything is redrawn; uncommitted
# changes mark it "-dirty".
commit=$(git describe --always --dirty 2>/dev/null || echo unknown)
[[ $commit == *-dirty ]] && echo "note: the working tree has uncommitted changes; the report will say so" >&2
# Only this report's own figures are redrawn: docs/figures/ also holds the pictures of other
# scripts (top-figures.sh, instruments-report.sh, scaling-study.sh).
rm -rf "$results"
rm -f "$figures"/fig[0-9][0-9]_* "$figures"/convergence_error.*
mkdir -p "$results" "$figures"
log=$results/log.txt
no_vtu=(--set "Output/Write VTU=false")
declare -A status

# run NAME ARGS...: runs tightfit, records its exit status for the document.
run() {
  local name=$1
  shift
  echo "== $name: tightfit $*" | tee -a "$log"
  "$tightfit" "$@" >>"$log" 2>&1
  status[$name]=$?
  echo "   exit ${status[$name]}"
}

start=$(date +%s)
# The garment VTUs of this run draw the paper's Figure 6.
run cylinder_T run cases/cylinder_T.prm --output "$results/cylinder_T"
run cylinder_45T run cases/cylinder_45T.prm --output "$results/cylinder_45T" "${no_vtu[@]}"
run compare compare cases/cylinder_T.prm --output "$results/cylinder_T_compare" "${no_vtu[@]}"
# The paper's Figure 14: garment 4 5T at about 575 vertices (the case's own mesh, 552) and
# 1397 (Mesh scale 0.62: 1444 vertices, 2736 triangles against the paper's 2738).
run compare_45T compare cases/cylinder_45T.prm --output "$results/cylinder_45T_compare" \
  "${no_vtu[@]}"
run compare_45T_fine compare cases/cylinder_45T.prm --output "$results/cylinder_45T_fine" \
  "${no_vtu[@]}" --set "Garment/Mesh scale=0.62"
run gravity run cases/cylinder_T.prm --output "$results/cylinder_T_gravity" "${no_vtu[@]}" \
  --set "Protocol/Gravity while settling=true" --set "Protocol/Gravity while measuring=true"
run paper_area run cases/cylinder_T.prm --output "$results/cylinder_T_adjacent" "${no_vtu[@]}" \
  --set "Pressure/Vertex area=adjacent triangles"
# Levels from twice the case's edge length, so the finest level is the case's own mesh
# halved; every second load step (alpha 0.1 apart) keeps the study within a minute or two.
run convergence convergence cases/cylinder_T.prm --levels "$levels" --set "Garment/Mesh scale=2" \
  --set "Protocol/Alpha increment=0.1" --output "$results/cylinder_T_convergence"
# Coarse against fine (Figure 14) in the long format of convergence.csv, for the plot and tables.
vertices_of() { awk -v run="== $1:" 'index($0, run) == 1 {f = 1} f && /mesh:/ {print $2; exit}' "$log"; }
n_coarse=$(vertices_of compare_45T)
n_fine=$(vertices_of compare_45T_fine)
{
  echo "backend,level,n_vertices,alpha,p_mean_Pa,p_theory_Pa,rel_error"
  for backend in massspring fem; do
    for level in 0 1; do
      dir=$results/cylinder_45T_compare n=$n_coarse
      [[ $level == 1 ]] && dir=$results/cylinder_45T_fine n=$n_fine
      awk -F, -v b=$backend -v l=$level -v n="$n" '
        NR == 1 {for (i = 1; i <= NF; i++) c[$i] = i; next}
        {print b "," l "," n "," $c["alpha"] "," $c["p_mean_Pa"] "," $c["p_theory_Pa"] "," $c["rel_error"]}' \
        "$dir/$backend/pressure.csv" 2>/dev/null
    done
  done
} >"$results/coarse_fine.csv"
bash scripts/plot-figures.sh "$results" "$figures" | tee -a "$log"
elapsed=$(($(date +%s) - start))

# table CSV SPEC: a Markdown table of the CSV's columns named in SPEC, separated by ';'
# ("name:Header", or "name*100:Header" for a percentage).
table() {
  awk -F, -v spec="$2" '
    NR == 1 {
      for (i = 1; i <= NF; i++) c[$i] = i
      n = split(spec, parts, ";")
      header = "|"; rule = "|"
      for (k = 1; k <= n; k++) {
        split(parts[k], nh, ":"); name[k] = nh[1]; scale[k] = 1
        if (name[k] ~ /\*100$/) { sub(/\*100$/, "", name[k]); scale[k] = 100 }
        header = header " " nh[2] " |"; rule = rule " ---: |"
      }
      print header; print rule; next
    }
    {
      line = "|"
      for (k = 1; k <= n; k++) {
        v = $c[name[k]]
        if (v == "") v = "-"
        else if (v ~ /^-?[0-9.]+(e[-+]?[0-9]+)?$/) v = sprintf("%.4g", v * scale[k])
        line = line " " v " |"
      }
      print line
    }' "$1"
}

outcome() { [[ ${status[$1]} -eq 0 ]] && echo "finished" || echo "**stopped (exit ${status[$1]}; see $log)**"; }
png() { [[ -s $figures/$1.png ]] && echo "![$2](figures/$1.png)" || echo "_($1.png was not drawn: its run did not finish.)_"; }
last_row() { tail -n 1 "$1" | cut -d, -f"$2"; }
column_of() { head -n 1 "$1" | tr ',' '\n' | grep -nx "$2" | cut -d: -f1; }

{
  cat <<MD
# Validation of tightfit against the closed form and the paper

Regenerated by \`scripts/validation-report.sh\` on $(date -u +%Y-%m-%d) from commit
${commit} in ${elapsed} s. Every number and
figure below is drawn from the CSV files in \`$results/\`; each PNG in \`docs/figures/\` has
the CSV it was drawn from beside it. The closed form is the one in
[closed-forms.md](closed-forms.md) for the case's law and end condition (linear Biot, free
ends); Eq. 7 is the paper's \`P = Et (1 - 1/alpha) / R0\` ([paper.md](paper.md)).

## Runs

| run | command | outcome |
| --- | --- | --- |
| garment T on the growing cylinder | \`tightfit run cases/cylinder_T.prm\` | $(outcome cylinder_T) |
| garment 4 5T | \`tightfit run cases/cylinder_45T.prm\` | $(outcome cylinder_45T) |
| both backends, same mesh | \`tightfit compare cases/cylinder_T.prm\` | $(outcome compare) |
| garment 4 5T, both backends | \`tightfit compare cases/cylinder_45T.prm\` | $(outcome compare_45T) |
| garment 4 5T, both backends, fine mesh | \`compare\` with \`Garment/Mesh scale=0.62\` | $(outcome compare_45T_fine) |
| gravity while settling and measuring | \`run\` with \`Protocol/Gravity while ...=true\` | $(outcome gravity) |
| the paper's vertex area (adjacent triangles) | \`run\` with \`Pressure/Vertex area=adjacent triangles\` | $(outcome paper_area) |
| mesh convergence, ${levels} levels | \`tightfit convergence cases/cylinder_T.prm --levels ${levels} --set "Garment/Mesh scale=2" --set "Protocol/Alpha increment=0.1"\` | $(outcome convergence) |

## The garment on the growing cylinder (the paper's Figure 6)

The paper shows its garment coloured by pressure as the cylinder grows: the colour rises
with the radius and is even round the cylinder. tightfit's garment T (default backend), drawn
by the run itself (its \`pictures\` measurement, \`Panels at alpha\`: \`pressure_steps.png\`): the same even colour at each step, rising with alpha.

$(png fig06_pressure_map "Garment T coloured by contact pressure at four load steps")

## Pressure against radius and garment size (the paper's Figures 7 and 8)

The paper found pressure growing with the cylinder's radius and the smaller garment pressing
harder on the same cylinder. tightfit's mean pressure on garment T (default backend):

$(table "$results/cylinder_T/pressure.csv" "alpha:alpha;radius_m*100:r [cm];p_mean_Pa:p mean [Pa];p_theory_Pa:closed form [Pa];rel_error*100:error [%];p_eq7_Pa:Eq. 7 [Pa];p_mean_gf_cm2:p [gf/cm2]")

$(png fig07_pressure_radius "Pressure against radius, garment T")

$(png fig08_garment_sizes "Pressure against radius, garments T and 4 5T")

## Both backends beside the closed form and Eq. 7 (the paper's Figure 10)

The paper compared its simulator with Eq. 7 and with measurements, its simulator reading the
lowest of the three (its vertex area, below, reads a third of the force balance). tightfit's
two backends on the same mesh agree with each other and with the closed form of the case's
law (linear Biot, free ends, nu12 = 0.2021) within the errors in the table:

MD
  if [[ $(wc -l <"$results/cylinder_T_compare/compare.csv" 2>/dev/null || echo 0) -gt 1 ]]; then
    table "$results/cylinder_T_compare/compare.csv" \
      "alpha:alpha;p_mean_Pa_massspring:mass-spring [Pa];p_mean_Pa_fem:FEM [Pa];p_theory_Pa:closed form [Pa];rel_diff*100:FEM - mass-spring [%];rel_error_massspring*100:mass-spring error [%];rel_error_fem*100:FEM error [%]"
  else
    echo "_No load step finished on both backends (see $log)._"
  fi
  cat <<MD

$(png fig10_pressure_alpha "Pressure against alpha, both backends, closed form and Eq. 7")

Eq. 7 is the linear Biot law without Poisson coupling; the case's fabric has nu12 = 0.2021
and free ends, so the closed form lies above Eq. 7 as alpha grows.

## Newton's convergence (FE backend)

The FE backend's \`solver.log\` lists the largest residual force after every Newton
iteration, per augmented-Lagrangian round (\`|\` separates the rounds). The first load
steps of the comparison on garment T, and the order of convergence read off the last three
residuals of each step's first round, \`ln(r_k+1 / r_k) / ln(r_k / r_k-1)\` (2 for
Newton's quadratic convergence):

\`\`\`
$(sed -n '2,4p' "$results/cylinder_T_compare/fem/solver.log" 2>/dev/null | awk '
  { split($0, head, ";"); match($0, /rounds \(iterations: residuals N; gap m, in contact\): .*; largest/)
    print head[1] "; " substr($0, RSTART + 7, RLENGTH - 16) }')
\`\`\`

$(sed -n '2,4p' "$results/cylinder_T_compare/fem/solver.log" 2>/dev/null | awk '
  { match($0, /\[[0-9]+: [^;]*;/); n = split(substr($0, RSTART + 1, RLENGTH - 2), r, " ")
    for (k = 1; k < n; ++k) r[k] = r[k + 1]; --n
    split($0, head, ":")
    if (n >= 3) printf "- %s: order %.2f from %s, %s, %s N\n", head[1],
      log(r[n] / r[n - 1]) / log(r[n - 1] / r[n - 2]), r[n - 2], r[n - 1], r[n] }')

## Pressure round the cylinder, with and without gravity (the paper's Figures 11 and 13)

Without gravity the state is uniform and the pressure is the same all round; with gravity
the garment's weight adds to the pressure where it hangs on the body.

$(png fig11_pressure_theta "Pressure against angle, no gravity")

$(png fig13_pressure_theta_gravity "Pressure against angle, with and without gravity")

## The paper's pressure definition against the force-balancing one

The paper divides a vertex's normal force by the summed area of its adjacent triangles,
which counts every triangle three times; tightfit's default (barycentric) area balances
forces. At the last load step on garment T:

MD
  bary=$results/cylinder_T/pressure.csv
  adj=$results/cylinder_T_adjacent/pressure.csv
  if [[ -s $bary && -s $adj ]]; then
    pb=$(last_row "$bary" "$(column_of "$bary" p_mean_Pa)")
    pa=$(last_row "$adj" "$(column_of "$adj" p_mean_Pa)")
    pt=$(last_row "$bary" "$(column_of "$bary" p_theory_Pa)")
    awk -v pb="$pb" -v pa="$pa" -v pt="$pt" 'BEGIN {
      print "| vertex area | p mean [Pa] | over the closed form |"
      print "| --- | ---: | ---: |"
      printf "| barycentric (balances forces) | %.2f | %.4f |\n", pb, pb / pt
      printf "| adjacent triangles (the paper) | %.2f | %.4f |\n", pa, pa / pt
      printf "\nRatio paper / force balance: %.4f (one third expected).\n", pa / pb }'
  else
    echo "_One of the two runs did not finish._"
  fi
  cat <<MD

## Mesh convergence

The case at ${levels} meshes, the edge length halved each level, on every backend. Observed
order from the finest three levels, Richardson-extrapolated pressure, and Roache's grid
convergence index (safety factor 1.25) of the finest level; columns are described in
cases/convergence_run.h. Every fourth load step:

MD
  summary=$results/cylinder_T_convergence/convergence_summary.csv
  if [[ -s $summary ]]; then
    awk -F, 'NR == 1 || ($2 % 4 == 0 && $2 > 0)' "$summary" >"$results/summary_every4.csv"
    table "$results/summary_every4.csv" \
      "backend:backend;alpha:alpha;n_levels:levels;edge_fine_m*100:finest edge [cm];p_fine_Pa:p finest [Pa];p_richardson_Pa:p Richardson [Pa];p_theory_Pa:closed form [Pa];observed_order:order;gci_fine*100:GCI [%];rel_error_fine*100:error finest [%];rel_error_richardson*100:error Richardson [%];error_order:error order"
  else
    echo "_The study wrote no summary._"
  fi
  cat <<MD

The paper did not study convergence beyond Figure 14. tightfit: observed orders and
extrapolated pressure at the last load step, per backend (expected order about 2 for linear
triangles; the Richardson pressure within 0.1% of the closed form):

$(awk -F, 'NR == 1 {for (i = 1; i <= NF; i++) c[$i] = i; next} {last[$c["backend"]] = $0; order[++n] = $c["backend"]}
  END {
    print "| backend | alpha | observed order (pressure) | error order (vs closed form) | p Richardson [Pa] | closed form [Pa] | Richardson error [%] |"
    print "| --- | ---: | ---: | ---: | ---: | ---: | ---: |"
    for (k = 1; k <= n; k++) { b = order[k]; if (done[b]++) continue; split(last[b], f, ",")
      printf "| %s | %.2f | %.2f | %.2f | %.2f | %.2f | %+.3f |\n", b, f[c["alpha"]], f[c["observed_order"]],
        f[c["error_order"]], f[c["p_richardson_Pa"]], f[c["p_theory_Pa"]], 100 * f[c["rel_error_richardson"]] } }' \
  "$results/cylinder_T_convergence/convergence_summary.csv" 2>/dev/null)

Vertices per level:

$(awk -F, 'NR > 1 && !seen[$1 FS $2]++ {print "- " $1 ", level " $2 ": " $4 " vertices, mean edge " sprintf("%.2f", 1000 * $5) " mm"}' "$results/cylinder_T_convergence/convergence.csv" 2>/dev/null)

$(png convergence_error "Log-log error against edge length")

## Coarse against fine mesh (the paper's Figure 14)

The paper ran garment 4 5T on a coarse mesh (575 vertices) and a fine one (1397) and found
that the mean pressures "do not differ significantly". tightfit's garment 4 5T on its own
mesh and at Mesh scale 0.62, both backends, every fourth load step (alpha 0.2 apart):

$(awk -F, 'NR == 1 {for (i = 1; i <= NF; i++) c[$i] = i; next}
  {k = $c["backend"] SUBSEP $c["alpha"]; p[$c["level"], k] = $c["p_mean_Pa"]; t[k] = $c["p_theory_Pa"]
   nv[$c["level"]] = $c["n_vertices"]; if (!(k in seen)) {seen[k]; key[++n] = k}}
  END {
    printf "| backend | alpha | coarse (%s vertices) [Pa] | fine (%s vertices) [Pa] | fine - coarse [%%] | closed form [Pa] |\n", nv[0], nv[1]
    print "| --- | ---: | ---: | ---: | ---: | ---: |"
    worst = 0
    for (i = 1; i <= n; i++) { split(key[i], bk, SUBSEP); if (p[0, key[i]] <= 0 || p[1, key[i]] == "") continue
      d = 100 * (p[1, key[i]] - p[0, key[i]]) / p[0, key[i]]
      if (bk[2] > 1.01 && (d < 0 ? -d : d) > worst) {worst = (d < 0 ? -d : d); worst_at = bk[1] " at alpha " bk[2]}
      if (bk[2] > 1.09 && (d < 0 ? -d : d) > worst_later) worst_later = (d < 0 ? -d : d)
      if (int(100 * bk[2] + 0.5) % 20 == 0) printf "| %s | %.2f | %.2f | %.2f | %+.3f | %.2f |\n", bk[1], bk[2], p[0, key[i]], p[1, key[i]], d, t[key[i]] }
    printf "\nLargest coarse-fine difference over the loaded steps (alpha > 1.01): %.3f%%, %s; from alpha 1.1 on: %.3f%%.\n", worst, worst_at, worst_later }' \
  "$results/coarse_fine.csv" 2>/dev/null)

$(png fig14_coarse_fine "Coarse and fine meshes: pressure and error against alpha")

Where the two meshes differ most is where the pressure is smallest, just after the garment
first presses (alpha 1.05: 5% hoop strain). Linear triangles inscribe a polygon of N vertices
in the circle and under-read the hoop strain by about (pi/N)^2 / 6; relative to the strain
alpha - 1 that is (pi/N)^2 / 6 x alpha / (alpha - 1), twenty times larger at alpha 1.05 than
the strain error itself. With 46 vertices round the coarse hoop and 76 round the fine one
the predicted coarse-fine difference is 1.03% at alpha 1.05, 0.54% at 1.1 and 0.11% at 1.8
(docs/model.md, "Garments in pattern space"), what both backends measure: the difference is
the discretisation's, the same for either solver. Quadratic triangles (\`Finite
elements/Element degree = 2\`) follow the circle and leave errors of about 1e-6 on either
mesh.
MD
  # The stocking's study by region takes about 20 minutes: rendered from the tables
  # scripts/stocking-convergence.sh keeps in docs/figures/, not run here.
  scripts/stocking-convergence-section.sh "$figures"
} >"$report"
echo "wrote $report and $figures/ in ${elapsed} s of runs"
