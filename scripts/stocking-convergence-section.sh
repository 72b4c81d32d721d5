#!/usr/bin/env bash
# Prints the section "Mesh convergence on a body" of docs/validation.md from the stocking
# studies' tables kept in docs/figures/ (scripts/stocking-convergence.sh writes them; a study
# takes minutes of CPU, so scripts/validation-report.sh renders the section from them without
# running it).
# Usage: scripts/stocking-convergence-section.sh [FIGURES_DIR]   (default docs/figures)
set -uo pipefail
figures=${1:-docs/figures}
# tables PREFIX [BACKEND]: the levels' table and the estimates' table of one backend's study
# (default massspring) kept as docs/figures/PREFIX_regions.csv, PREFIX_regions_summary.csv and
# PREFIX_times.csv.
tables() {
  local levels=$figures/$1_regions.csv summary=$figures/$1_regions_summary.csv times=$figures/$1_times.csv
  local backend=${2:-massspring}
  echo
  # Levels: size, time and each region's mean pressure with its distance from the limit: the
  # Richardson value, or the finest level's where the levels oscillate (no order, marked *).
  awk -F, -v backend="$backend" 'FNR == 1 {delete c; for (i = 1; i <= NF; i++) c[$i] = i; ++file; next}
    ("backend" in c) && $c["backend"] != backend {next}
    file == 1 { if (!($c["region"] in rich)) names[++nr] = $c["region"]; rich[$c["region"]] = $c["p_mean_richardson_Pa"]; next }
    file == 2 { t[$c["level"]] = $c["seconds"]; if ("cpu_seconds" in c) cpu[$c["level"]] = $c["cpu_seconds"]; next }
    { l = $c["level"]; if (l > nl) nl = l; nv[l] = $c["n_vertices"]; h[l] = $c["edge_m"]; p[l, $c["region"]] = $c["p_mean_Pa"] }
    END {
      line = "| level | vertices | mean edge [mm] | time [s] | CPU [s] |"; rule = "| ---: | ---: | ---: | ---: | ---: |"
      for (k = 1; k <= nr; k++) { r = names[k]; line = line " " r " p_mean [Pa] | from " (rich[r] == "" ? "finest* " : "Richardson ") "[%] |"; rule = rule " ---: | ---: |" }
      print line; print rule
      for (l = 0; l <= nl; l++) {
        line = sprintf("| %d | %d | %.2f | %s | %s |", l, nv[l], 1e3 * h[l], (l in t) ? sprintf("%.0f", t[l]) : "-", (l in cpu) ? sprintf("%.0f", cpu[l]) : "-")
        for (k = 1; k <= nr; k++) { r = names[k]; v = p[l, r]; ref = (rich[r] == "") ? p[nl, r] : rich[r]
          line = line sprintf(" %.1f | %+.2f |", v, 100 * (v - ref) / ref) }
        print line }
    }' "$summary" "$times" "$levels"
  echo
  echo "From Richardson: the level's distance from the region's Richardson estimate; from finest*:"
  echo "the region's levels oscillate (no observed order, no estimate), the distance from the finest."
  echo
  # The estimates, mean and peak, and where the mean has an order, the mesh it needs to come
  # within 1% of its limit: |p_h - p_R| / p_R = e_f (h / h_f)^p, so h_1% = h_f (1 / e_f)^(1/p)
  # with e_f in %, the vertices growing as (h_f / h)^2.
  awk -F, -v backend="$backend" 'FNR == 1 {delete c; for (i = 1; i <= NF; i++) c[$i] = i; ++file; next}
    $c["backend"] != backend {next}
    file == 1 { if ($c["level"] >= fine) { fine = $c["level"]; n_fine = $c["n_vertices"] }; next }
    {
      if (!header++) {
        print "| region | p_mean fine [Pa] | order | Richardson [Pa] | GCI [%] | p_peak fine [Pa] | order | Richardson [Pa] | GCI [%] | edge for 1% [mm] | vertices for 1% |"
        print "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |" }
      f = $c["p_mean_fine_Pa"]; R = $c["p_mean_richardson_Pa"]; p = $c["mean_order"]; hf = 1e3 * $c["edge_fine_m"]
      e = 100 * (f - R) / R; if (e < 0) e = -e
      h1 = "-"; n1 = "-"
      if (p != "" && R != "" && e > 0) { h1 = sprintf("%.1f", hf * (1 / e) ^ (1 / p)); n1 = sprintf("%.0f", n_fine * (1 / e) ^ (-2 / p)) }
      printf "| %s | %.1f | %s | %s | %s | %.1f | %s | %s | %s | %s | %s |\n", $c["region"], f,
        (p == "" ? "-" : sprintf("%.2f", p)), (R == "" ? "-" : sprintf("%.1f", R)),
        ($c["mean_gci_fine"] == "" ? "-" : sprintf("%.2f", 100 * $c["mean_gci_fine"])), $c["p_peak_fine_Pa"],
        ($c["peak_order"] == "" ? "-" : sprintf("%.2f", $c["peak_order"])),
        ($c["p_peak_richardson_Pa"] == "" ? "-" : sprintf("%.1f", $c["p_peak_richardson_Pa"])),
        ($c["peak_gci_fine"] == "" ? "-" : sprintf("%.2f", 100 * $c["peak_gci_fine"])), h1, n1
    }' "$levels" "$summary"
}

cat <<'MD'

## Mesh convergence on a body (the stocking)

The stocking (`cases/stocking_female.prm`, [stocking.md](stocking.md)) at three meshes, the
edge lengths halved from one level to the next (the case's own mesh, `Mesh scale` 0.5 and
0.25), on each backend; each level's mean and peak pressure in the 2 cm bands B, C and G round
the leg's measuring points, the observed order from the three levels, the Richardson estimate
and Roache's GCI (safety factor 1.25) of the finest level (columns in
cases/convergence_run.h). The mass-spring backend runs its implicit route (RK4's approach, then
Newton: [backends.md](backends.md), "On a mesh body"), whose cost grows with the vertices
alone, where RK4's stable time step falls with the edge; the FE backend runs with its
defaults:

    tightfit convergence cases/stocking_female.prm --levels 3 --backends massspring \
      --set "Measurements/List=regions, compression class" --set "Mass spring/Integrator=implicit"
    tightfit convergence cases/stocking_female.prm --levels 3 --backends fem \
      --set "Measurements/List=regions, compression class"

(`scripts/stocking-convergence.sh` runs both and redraws the figures and these tables.) Each
level's time is the wall time and the process's CPU time (every thread's), its mesh's making
included, on a two-core machine shared with other work: the CPU time is the cost, the wall
time mostly the other work's.
MD
if [[ ! -s $figures/stocking_convergence_regions_summary.csv ]]; then
  echo
  echo "_The stocking's study has not been run: scripts/stocking-convergence.sh._"
  exit 0
fi
echo
echo "### Mass spring"
tables stocking_convergence massspring
echo
echo "![The bands' mean pressure against its Richardson estimate](figures/stocking_convergence.png)"
echo
echo "![The bands' mean pressure against the mean edge, with its estimate](figures/stocking_convergence_means.png)"
cat <<'MD'

How fine must a stocking's mesh be for B, C and G to be within 1% of the extrapolated value?
All three bands converge monotonically, B and G at about the order of linear triangles (2.2
and 2.5), C at below first order on changes that stay small (0.6% from the coarsest level to
the limit). By the observed orders, C is within 1% on every mesh, G from a mean edge of about
13 mm (about 1400 vertices) and B from about 9.2 mm (about 2850 vertices). So a stocking needs
about 2850 vertices, a mean edge of 9 mm, for its bands to be within 1%; the case's own mesh
(1312 vertices, 13.5 mm) reads B 2.3%, G 1.1% and C 0.7% low. The finest level's GCI is 0.14%
(B), 0.30% (C) and 0.04% (G). The whole study took 108 s of CPU on mass spring, 93 s of it the
finest level, and 85 s on FE.

The landmark-cut stocking (`cases/stocking_female_landmarks.prm`, the same command with
`--levels 2`, 19 s of CPU) moves by as much from its own mesh (1280 vertices) to 5120: B +1.85%,
C +0.10%, G +0.85% (this stocking: +1.83%, +0.25%, +0.87%), so the same mesh serves it.

The same study on a mesh body whose answer is known
(`tests/cases/test_region_convergence_on_body.cc`): garment T held round a smooth 48-sided prism
at alpha 1.5, three levels whose hoops have 20, 40 and 80 vertices, two bands; each band's
observed order is 2.05, its Richardson estimate 1.1e-5 from the closed form, and the finest
level 7.74e-4 low, where the inscribed hoop predicts 7.71e-4.

The whole garment's mean pressure (the first table the command prints) converges more slowly:
observed order 0.81, its finest level 1.5% below its estimate (GCI 1.8%). Quote the bands.

The peaks do not converge, and the study fits no order to B's and G's: B's largest vertex
pressure falls from 11.2 to 8.4 kPa and rises to 8.8 kPa, G's falls from 2156 to 2151 Pa and
rises to 2307 Pa (single vertices at the ankle's tendons and over the thigh, where each mesh
resolves the body's curvature differently). C's rises monotonically, 3330, 3557, 3673 Pa, at an
observed order of 0.96 whose estimate (3794 Pa, GCI 4.1%) lies 3% above the finest level: a
peak that grows as the mesh resolves a curvature has no mesh-independent value. The bands'
means are the numbers to quote.

The settle's stop rule: the implicit route meets the default `Solver/Relative tolerance = 1e-4`
on every level. In the study below (measured with the tube on the earlier axis of the case, the
line through the centroids of the leg's horizontal sections, 2.8 mm lower at B), RK4 (the case's
integrator) stalls at three times it on the 2736-vertex level (2.1e-5 N against 6.8e-6 N, after 12 000 frames, on a vertex over the shin);
at 5e-4 (`--set "Solver/Relative tolerance=5e-4"` in place of the integrator) it settles the
three levels in 391 s of CPU, its means within 0.02% of the implicit route's (B 3438.9, C
1694.2, G 903.4 Pa at 21760 vertices); on the 1312 mesh, which settles either way, the looser
rule moves the means of B, C and G by at most 1.1e-6 of their value.

A coarser level cannot read the bands: at `Garment/Mesh scale = 2` (336 vertices, mean edge
2.7 cm) both backends settle ([stocking.md](stocking.md), "The coarse stocking": B, C and G
3.1 %, 2.9 % and 2.8 % below the 1312 mesh), but its warp edge (3 cm) is wider than a band
(2 cm), which holds one ring of vertices or none; the study leaves it out.
MD
echo
echo "### Finite elements"
if grep -q '^fem,' "$figures/stocking_convergence_regions_summary.csv"; then
  tables stocking_convergence fem
fi
cat <<'MD'

The FE backend, every solver entry at its default, settles every level: 26, 34 and 46 Newton
iterations (2.1, 11 and 72 s of CPU), and its bands lie within 3e-5 of the mass-spring
backend's on each level (B 3449.65 against 3449.57 Pa at 21760 vertices), so its orders,
estimates and the mesh each band needs are the mass-spring study's. The time of its finer
levels goes to the body, not to the linear solves: on the 5120-vertex level half of the CPU
time is the smooth contact surface's blend (`BlendedQuadricField::evaluate`, perf on a running
study), 4% the faceted closest point, 3% the membrane's assembly and 1-2% MUMPS.
MD
if [[ -s $figures/stocking_convergence_sqrt2_regions_summary.csv ]]; then
  cat <<'MD'

### The edge divided by sqrt(2) (mass spring)

With the edge lengths divided by sqrt(2) from one level to the next (`--ratio 1.41421356`,
`scripts/stocking-convergence.sh --sqrt2`; 70 s of CPU), measured with the tube on the case's
earlier axis (the line through the centroids of the leg's horizontal sections, 2.8 mm lower at
B; the halving study on that axis estimated B 3441.4, C 1696.1 and G 903.6 Pa): at 2736
vertices B, C and G lie 0.33%, 0.24% and 0.51% below those estimates, within 1% as predicted. Between 2736 and 5120
vertices B and C move by 0.1% and 0.01% against the trend (the band's rings of vertices and
the share of their cells inside it change from mesh to mesh), so from these three levels alone
the study observes no order for them:

MD
  tables stocking_convergence_sqrt2
  echo
  echo "![The same, edge divided by sqrt(2) each level](figures/stocking_convergence_sqrt2.png)"
fi

# The aaron top at two levels (scripts/stocking-convergence.sh --top): no observed order.
top=$figures/top_convergence
[[ -s ${top}_levels.csv ]] || exit 0
cat <<'MD'

### The aaron top at two levels

The aaron top on the female (`cases/top_female.prm`, [dressing.md](dressing.md)) on its own
mesh and on one with the edge lengths divided by sqrt(2), on the mass-spring backend, with the
case's regions and settle (`scripts/stocking-convergence.sh --top` runs both):

    tightfit run cases/top_female.prm --set "Garment/Mesh scale=0.70710678" \
      --set "Placement/Dressing/Coarse edge length=0.015" \
      --set "Placement/Dressing/Coarse settle tolerance=1e-2"

Both levels dress on the same coarse mesh (`Placement/Dressing/Coarse edge length`, which a
finer `Mesh scale` leaves alone) and carry it to their own mesh before the settle. At the
case's 20 mm the finer level cannot start: carried from the coarse mesh, a vertex lies 4.2 mm
inside the body, more than the quarter of a coarse edge the dressing allows (3.2 mm). At 15 mm
the coarse settle stalls at twice the case's `Coarse settle tolerance = 3e-3` (1.2e-4 N
against 6.3e-5 N); it only starts the fine settle, which keeps the case's tolerance, so it
stops at 1e-2 here. The times are wall times on the shared two-core machine, dressing included
(level 0: 81 s of CPU; level 1: 242 s until it stopped). The script runs the levels one by
one; `tightfit convergence` with `--levels 2 --ratio 1.41421356` and the same `--set`s would
dress each level once too, and run that dressed garment on each backend.

With two levels no order can be observed: a two-level Richardson value and GCI assume the
linear triangles' order 2 and take Roache's safety factor 3 for two meshes, as
`tightfit convergence` does with two levels (cases/convergence_analysis.h).
MD
echo
awk -F, 'NR == 1 {for (i = 1; i <= NF; i++) c[$i] = i; print "| level | Mesh scale | vertices | mean edge [mm] | time [s] |"; print "| ---: | ---: | ---: | ---: | ---: |"; next}
  {printf "| %d | %.4g | %d | %.1f | %d |\n", $c["level"], $c["mesh_scale"], $c["n_vertices"], 1e3 * $c["edge_m"], $c["seconds"]}' "${top}_levels.csv"
echo
if [[ ! -s ${top}_level1_regions.csv ]]; then
  cat <<'MD'
The finer level (9642 vertices) dresses but does not settle: the mass-spring settle stalls
after 16 633 frames and two time-step halvings at 7.8 times its tolerance (rms residual
2.4e-4 N against 3.1e-5 N), its largest residual, 0.017 N almost all across the body's normal,
on a vertex over the left hip (x = -0.151, y = -0.034, z = 0.072 m): a vertex sliding to and
fro on the body, as the stocking's coarsest mesh does over the shin. The run writes no region
table, so this study has one level and no change to report. The level that ran, beside the
case as it stands (dressed on its 20 mm coarse mesh, the same 4880-vertex mesh):

MD
  awk -F, 'FNR == 1 {delete c; for (i = 1; i <= NF; i++) c[$i] = i; ++file; next}
    { r = $c["region"]; if (file == 1) names[++nr] = r
      v[file, r] = ($c["p_mean_Pa"] == "" ? "no contact" : sprintf("%.1f / %.1f / %d", $c["p_mean_Pa"], $c["p_peak_Pa"], $c["n_contact_vertices"])) }
    END {
      print "| region | dressed at 15 mm: mean / peak [Pa] / vertices in contact | dressed at 20 mm (the case) |"
      print "| --- | ---: | ---: |"
      for (i = 1; i <= nr; i++) printf "| %s | %s | %s |\n", names[i], v[1, names[i]], v[2, names[i]]
    }' "${top}_level0_regions.csv" "${top}_case_regions.csv"
  cat <<'MD'

(The 15 mm column was measured from the start the case typed before its frame came from the
landmarks, 6 mm from today's; docs/dressing.md, "The results".) On one mesh the dressing's
start alone moves the bust's mean by 21% (40.0 against 50.7 Pa) and the shoulder blades' by
17%, the waist's by 4%: with friction the settled top keeps some
of the path that brought it there, and its regions touch the body at a few vertices (7 at the
waist, 26 to 32 on the bust). Before a mesh study of the top can say anything, its settled
state must depend on the mesh alone: the finer level has to settle, and the dressing's start
must not change the regions' means by more than the levels do.
MD
  exit 0
fi
# Per region: the mean and peak at each level and their change from the coarse level to the
# fine one. Two levels observe no order: the Richardson value and GCI assume the linear
# triangles' order 2 and take Roache's safety factor 3 for two meshes, as tightfit convergence
# does (cases/convergence_analysis.h), with r the ratio of the levels' mean edges.
awk -F, 'FNR == 1 {delete c; for (i = 1; i <= NF; i++) c[$i] = i; ++file; next}
  file == 1 { h[$c["level"]] = $c["edge_m"]; next }
  { l = file - 2; r = $c["region"]; if (l == 0) names[++nr] = r; m[l, r] = $c["p_mean_Pa"]; k[l, r] = $c["p_peak_Pa"] }
  END {
    q = 2; F = 3; ratio = h[0] / h[1]; d = ratio ^ q - 1
    printf "Ratio of the mean edges r = %.3f; order 2 assumed, safety factor 3.\n\n", ratio
    print "| region | p_mean coarse [Pa] | p_mean fine [Pa] | change [%] | Richardson [Pa] | GCI [%] | p_peak coarse [Pa] | p_peak fine [Pa] | change [%] |"
    print "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"
    for (i = 1; i <= nr; i++) { r = names[i]; a = m[0, r]; b = m[1, r]; pa = k[0, r]; pb = k[1, r]
      if (a == "" || b == "") { printf "| %s | %s | %s | - | - | - | - | - | - |\n", r, (a == "" ? "no contact" : sprintf("%.1f", a)), (b == "" ? "no contact" : sprintf("%.1f", b)); continue }
      e = (b - a) / b; g = F * (e < 0 ? -e : e) / d
      printf "| %s | %.1f | %.1f | %+.2f | %.1f | %.2f | %.1f | %.1f | %+.1f |\n", r, a, b, 100 * (b - a) / a,
        b + (b - a) / d, 100 * g, pa, pb, 100 * (pb - pa) / pa }
  }' "${top}_levels.csv" "${top}_level0_regions.csv" "${top}_level1_regions.csv"
