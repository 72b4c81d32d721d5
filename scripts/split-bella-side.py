#!/usr/bin/env python3
"""Writes FreeSewing's bella bodice with the back's side seam split in two (docs/dressing.md).

The front's side seam is interrupted by the bust dart: below it the front's edge 5 (64.90 mm),
above it edge 8 (107.04 mm). A seam side is a run of consecutive edges, so the back's side (one
cubic Bezier, 171.95 mm) is split at the same fraction of its arc length (64.90 / 171.94) by de
Casteljau's construction: the two halves trace the same curve, only the edge numbering of the
back changes (its side becomes edges 6 and 7, the armhole 8 and 9, and so on).

    scripts/split-bella-side.py data/patterns/freesewing_bella_cisFemaleAdult34_outline.svg \
        data/patterns/freesewing_bella_cisFemaleAdult34_side_split.svg
"""
import math
import sys

START = (219.21, 385.69)
SIDE = "C 219.21,299.73 221.9,213.77 221.9,213.77"
FRONT_BELOW, FRONT_ABOVE = ((264.62, 427.3), (267.31, 362.46)), ((287.5, 275.0), (240.58, 178.79))


def point(p, t):
    u = 1.0 - t
    w = (u * u * u, 3 * u * u * t, 3 * u * t * t, t * t * t)
    return tuple(sum(w[k] * p[k][i] for k in range(4)) for i in range(2))


def arc_length(p, t1, n=4000):
    pts = [point(p, t1 * k / n) for k in range(n + 1)]
    return sum(math.dist(a, b) for a, b in zip(pts, pts[1:]))


def lerp(a, b, t):
    return tuple(a[i] + t * (b[i] - a[i]) for i in range(2))


def main(source, target):
    svg = open(source, encoding="utf-8").read()
    if svg.count(SIDE) != 1:
        sys.exit(f"{source}: the back's side seam '{SIDE}' is not there exactly once")
    c = [float(v) for v in SIDE[2:].replace(",", " ").split()]
    p = [START, (c[0], c[1]), (c[2], c[3]), (c[4], c[5])]
    below = math.dist(*FRONT_BELOW)
    fraction = below / (below + math.dist(*FRONT_ABOVE))
    wanted, lo, hi = fraction * arc_length(p, 1.0), 0.0, 1.0
    for _ in range(50):  # bisection on the arc length
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if arc_length(p, mid) < wanted else (lo, mid)
    t = 0.5 * (lo + hi)
    a, b, cc = lerp(p[0], p[1], t), lerp(p[1], p[2], t), lerp(p[2], p[3], t)
    ab, bc = lerp(a, b, t), lerp(b, cc, t)
    m = lerp(ab, bc, t)
    f = lambda q: f"{q[0]:.4f},{q[1]:.4f}"
    split = f"C {f(a)} {f(ab)} {f(m)} C {f(bc)} {f(cc)} {f(p[3])}"
    open(target, "w", encoding="utf-8").write(svg.replace(SIDE, split))
    print(f"split at t = {t:.6f}, {f(m)} mm: {split}")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: split-bella-side.py BELLA.svg OUT.svg")
    main(sys.argv[1], sys.argv[2])
