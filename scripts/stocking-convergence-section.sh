#!/usr/bin/env bash
# Prints the section "Mesh convergence on a body" of docs/validation.md from the stocking
# studies' tables kept in docs/figures/ (scripts/stocking-convergence.sh writes them; a study
# takes minutes of CPU, so scripts/validation-report.sh renders the section from them without
# running it).
# Usage: scripts/stocking-convergence-section.sh [FIGURES_DIR]   (default docs/figures)
set -uo pipefail
figures=${1:-docs/figures}
# tables PREFIX: the levels' table and the estimates' table of the study kept as
# docs/figures/PREFIX_regions.csv, PREFIX_regions_summary.csv and PREFIX_times.csv.
tables() {
  local levels=$figures/$1_regions.csv summary=$figures/$1_regions_summary.csv times=$figures/$1_times.csv
  echo
  # Levels: size, time and each region's mean pressure with its distance from the limit: the
  # Richardson value, or the finest level's where the levels oscillate (no order, marked *).
  awk -F, 'FNR == 1 {delete c; for (i = 1; i <= NF; i++) c[$i] = i; ++file; next}
    file == 1 { if (!($c["region"] in rich)) names[++nr] = $c["region"]; rich[$c["region"]] = $c["p_mean_richardson_Pa"]; next }
    file == 2 { t[$c["level"]] = $c["seconds"]; next }
    { l = $c["level"]; if (l > nl) nl = l; nv[l] = $c["n_vertices"]; h[l] = $c["edge_m"]; p[l, $c["region"]] = $c["p_mean_Pa"] }
    END {
      line = "| level | vertices | mean edge [mm] | time [s] |"; rule = "| ---: | ---: | ---: | ---: |"
      for (k = 1; k <= nr; k++) { r = names[k]; line = line " " r " p_mean [Pa] | from " (rich[r] == "" ? "finest* " : "Richardson ") "[%] |"; rule = rule " ---: | ---: |" }
      print line; print rule
      for (l = 0; l <= nl; l++) {
        line = sprintf("| %d | %d | %.2f | %s |", l, nv[l], 1e3 * h[l], (l in t) ? sprintf("%.0f", t[l]) : "-")
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
  awk -F, 'FNR == 1 {delete c; for (i = 1; i <= NF; i++) c[$i] = i; ++file; next}
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
0.25), on the mass-spring backend; each level's mean and peak pressure in the 2 cm bands B, C
and G round the leg's measuring points, the observed order from the three levels, the
Richardson estimate and Roache's GCI (safety factor 1.25) of the finest level (columns in
cases/convergence_run.h):

    tightfit convergence cases/stocking_female.prm --levels 3 --backends massspring \
      --set "Measurements/List=regions, compression class" --set "Solver/Relative tolerance=5e-4"

(`scripts/stocking-convergence.sh` runs it and redraws the figure and these tables.) The times
are wall times on a two-core machine shared with other work, where the study had about a third
of a core (391 s of CPU for the three levels, 20 min in all).
MD
if [[ ! -s $figures/stocking_convergence_regions_summary.csv ]]; then
  echo
  echo "_The stocking's study has not been run: scripts/stocking-convergence.sh._"
  exit 0
fi
echo
tables stocking_convergence
echo
echo "![The bands' mean pressure against its Richardson estimate](figures/stocking_convergence.png)"
cat <<'MD'

How fine must a stocking's mesh be for B, C and G to be within 1% of the extrapolated value?
All three bands converge monotonically, B and G at about the order of linear triangles (2.4),
C at about first order on changes that stay small (0.5% from the coarsest level to the
limit). By the observed orders, C is within 1% on every mesh, G from a mean edge of about
12.7 mm (about 1500 vertices) and B from about 9.2 mm (about 2800 vertices); the 2736-vertex
mesh of the study below (`Garment/Mesh scale = 0.71`, mean edge 9.4 mm) measured all three
within 0.6% of these estimates. So a stocking needs about 2800 vertices, a mean edge of 9 mm,
for its bands to be within 1%; the case's own mesh (1312 vertices, 13.5 mm) reads B 2.4%,
G 1.1% and C 0.5% low. The finest level's GCI is 0.11% (B), 0.14% (C) and 0.05% (G).

The whole garment's mean pressure (the first table the command prints) converges more slowly:
observed order 0.7, its finest level 1.7% below its estimate (GCI 2.2%). Quote the bands.

The peaks do not converge: the largest vertex pressure in B falls from 11.8 to 8.7 kPa and
rises to 9.0 kPa (one vertex at the ankle's tendons, where each mesh resolves the curvature
differently); the bands' means are the numbers to quote.

The settle's stop rule: at the default `Solver/Relative tolerance = 1e-4` the 2736-vertex level
(below) stalls at three times its tolerance (2.1e-5 N against 6.8e-6 N, after 12 000 frames, on
a vertex over the shin). At 5e-4 every level finishes; on the 1312 mesh, which settles either
way, the looser rule moves the means of B, C and G by at most 1.1e-6 of their value and the
peaks by at most 5e-4, far below the differences between levels.

A coarser level cannot work: at `Garment/Mesh scale = 2` (336 vertices, mean edge 2.7 cm)
neither backend settles. The mass-spring backend stalls at ten times the tolerance (5.7e-4 N
against 5.5e-5 N after 20 000 frames), its largest residual across the body's normal on a vertex
over the shin (z = -0.633 m), a ring sliding to and fro over the shin's crest; the FE backend's
Newton iterations stop at 1000 with 1.3 times the tolerance left (7.1e-5 N against 5.5e-5 N,
line-search steps of 1/1024), the residual again across the normal, on the calf. Even settled
that mesh could not read the bands: its warp edge (3 cm) is wider than a band (2 cm), which
would hold one ring of vertices or none.

The FE backend on the case's own mesh (1312 vertices, the same command with `--backends fem`)
reads B 3358.0, C 1687.1 and G 893.4 Pa, the mass-spring backend's to 1e-5 (B, C) and 4e-5
(G). Its finer levels are slower: on the same shared machine the 1312 level took 325 Newton
iterations in 102 s, the 2736 level had done 189 in 16 min; its study is not in this page.
MD
if [[ -s $figures/stocking_convergence_sqrt2_regions_summary.csv ]]; then
  cat <<'MD'

With the edge lengths divided by sqrt(2) from one level to the next (`--ratio 1.41421356`,
`scripts/stocking-convergence.sh --sqrt2`; 70 s of CPU): at 2736 vertices B, C and G lie 0.35%,
0.24% and 0.53% below the estimates above, within 1% as predicted. Between 2736 and 5120
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
[[ -s ${top}_regions_summary.csv ]] || exit 0
cat <<'MD'

### The aaron top at two levels

The aaron top on the female (`cases/top_female.prm`, [dressing.md](dressing.md)) on its own
mesh and one with the edge lengths divided by sqrt(2), on the mass-spring backend, with the
case's regions and settle (`scripts/stocking-convergence.sh --top`):

    tightfit convergence cases/top_female.prm --levels 2 --ratio 1.41421356 --backends massspring \
      --set "Placement/Dressing/Coarse edge length=0.015"

Both levels dress on the same coarse mesh (`Placement/Dressing/Coarse edge length`, which the
study does not scale) and carry it to their own mesh before the settle. At the case's 20 mm
the finer level cannot start: carried from the coarse mesh, a vertex lies 4.2 mm inside the
body, more than the quarter of a coarse edge the dressing allows (3.2 mm), and the study
stops with that message; at 15 mm both levels dress.
MD
echo
awk -F, 'FNR == 1 {delete c; for (i = 1; i <= NF; i++) c[$i] = i; ++file; next}
  file == 1 { t[$c["level"]] = $c["seconds"]; next }
  { l = $c["level"]; if (!(l in nv)) { nv[l] = $c["n_vertices"]; h[l] = $c["edge_m"]; if (l > nl) nl = l } }
  END {
    print "| level | vertices | mean edge [mm] | time [s] |"; print "| ---: | ---: | ---: | ---: |"
    for (l = 0; l <= nl; l++) printf "| %d | %d | %.2f | %s |\n", l, nv[l], 1e3 * h[l], (l in t) ? sprintf("%.0f", t[l]) : "-"
  }' "${top}_times.csv" "${top}_regions.csv"
echo
# Per region: the mean and peak at each level and their relative change from the coarse level
# to the fine one; the Richardson value and GCI the command writes with the assumed order.
awk -F, 'FNR == 1 {delete c; for (i = 1; i <= NF; i++) c[$i] = i; ++file; next}
  file == 1 { l = $c["level"]; if (!($c["region"] in seen)) { seen[$c["region"]] = 1; names[++nr] = $c["region"] }
    m[l, $c["region"]] = $c["p_mean_Pa"]; k[l, $c["region"]] = $c["p_peak_Pa"]; if (l > nl) nl = l; next }
  { R[$c["region"]] = $c["p_mean_richardson_Pa"]; G[$c["region"]] = $c["mean_gci_fine"]; q = $c["mean_order"]; F = $c["safety_factor"] }
  END {
    printf "| region | p_mean coarse [Pa] | p_mean fine [Pa] | change [%%] | Richardson, order %g [Pa] | GCI, Fs %g [%%] | p_peak coarse [Pa] | p_peak fine [Pa] | change [%%] |\n", q, F
    print "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"
    for (i = 1; i <= nr; i++) { r = names[i]; a = m[0, r]; b = m[nl, r]; pa = k[0, r]; pb = k[nl, r]
      printf "| %s | %.1f | %.1f | %+.2f | %s | %s | %.1f | %.1f | %+.1f |\n", r, a, b, 100 * (b - a) / a,
        (R[r] == "" ? "-" : sprintf("%.1f", R[r])), (G[r] == "" ? "-" : sprintf("%.2f", 100 * G[r])), pa, pb, 100 * (pb - pa) / pa }
  }' "${top}_regions.csv" "${top}_regions_summary.csv"
