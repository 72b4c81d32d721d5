#!/usr/bin/env python3
"""Writes the AAMA DXF test patterns in tests/pattern/data/ (docs/patterns.md, Formats):

  aama_chained_shuffled.dxf  two pieces whose boundaries are several entities (LINE, POLYLINE,
                             LWPOLYLINE, ARC, SPLINE) in shuffled order, some written backwards,
                             their joints 0.0004 mm apart (the file's printed precision), mm
  aama_graded_sizes.dxf      a front and a back in three sizes (34, 36, 38), a block per piece
                             and size, SIZE and SAMPLE SIZE text, mm
  aama_no_units.dxf          a front and a back drawn in inches, without $INSUNITS
  aama_gap.dxf               the chained front with one joint 5 mm apart (a real gap)

Run from the repository's root: python3 scripts/write-aama-test-patterns.py
The shapes are stated here and in the tests that read them (tests/pattern/test_aama_forms.cc).
"""
import math
import random
from pathlib import Path

OUT = Path(__file__).resolve().parent.parent / "tests" / "pattern" / "data"


def pairs(*items):
    return "".join(f"{code}\n{value}\n" for code, value in items)


def num(x):
    return f"{x:.4f}"


def header(insunits):
    body = pairs((0, "SECTION"), (2, "HEADER"))
    if insunits is not None:
        body += pairs((9, "$INSUNITS"), (70, insunits))
    return body + pairs((0, "ENDSEC"))


def line(a, b, layer=1):
    return pairs((0, "LINE"), (8, layer), (10, num(a[0])), (20, num(a[1])),
                 (11, num(b[0])), (21, num(b[1])))


def polyline(points, closed=False, layer=1):
    out = pairs((0, "POLYLINE"), (8, layer), (66, 1), (70, 1 if closed else 0))
    for p in points:
        out += pairs((0, "VERTEX"), (8, layer), (10, num(p[0])), (20, num(p[1])))
    return out + pairs((0, "SEQEND"), (8, layer))


def lwpolyline(points, layer=1):
    out = pairs((0, "LWPOLYLINE"), (8, layer), (90, len(points)), (70, 0))
    for p in points:
        out += pairs((10, num(p[0])), (20, num(p[1])))
    return out


def arc(centre, radius, start_deg, end_deg, layer=1):
    return pairs((0, "ARC"), (8, layer), (10, num(centre[0])), (20, num(centre[1])),
                 (40, num(radius)), (50, f"{start_deg:.6f}"), (51, f"{end_deg:.6f}"))


def spline(degree, control, knots, layer=1):
    out = pairs((0, "SPLINE"), (8, layer), (70, 8), (71, degree), (72, len(knots)),
                (73, len(control)), (74, 0))
    for k in knots:
        out += pairs((40, k))
    for p in control:
        out += pairs((10, num(p[0])), (20, num(p[1])))
    return out


def point(p, layer):
    return pairs((0, "POINT"), (8, layer), (10, num(p[0])), (20, num(p[1])))


def text(words, layer=1):
    return pairs((0, "TEXT"), (8, layer), (10, 0), (20, 0), (40, 5), (1, words))


def block(name, entities):
    return (pairs((0, "BLOCK"), (8, 0), (2, name), (70, 0), (10, 0), (20, 0)) + "".join(entities)
            + pairs((0, "ENDBLK")))


def dxf(insunits, blocks, entities=()):
    return (header(insunits) + pairs((0, "SECTION"), (2, "BLOCKS")) + "".join(blocks)
            + pairs((0, "ENDSEC"), (0, "SECTION"), (2, "ENTITIES")) + "".join(entities)
            + pairs((0, "ENDSEC"), (0, "EOF")))


def nudge(p, rng, size=0.0004):
    """A joint as a CAD system prints it: within its printed precision of the exact point."""
    return (p[0] + rng.choice((-size, size)), p[1] + rng.choice((-size, size)))


# The chained front: a hexagon, mm (area by the shoelace formula in the test).
FRONT = [(0, 0), (400, 0), (420, 300), (300, 560), (100, 560), (-20, 300)]


def chained_front(rng, gap=0.0):
    c = FRONT
    entities = [
        line(c[0], nudge(c[1], rng)),
        lwpolyline([c[3], nudge(c[2], rng), c[1]]),        # written backwards
        polyline([nudge(c[3], rng), c[4]]),
        line(nudge(c[5], rng), (c[4][0] + gap, c[4][1])),  # backwards; `gap` opens the joint
        line(c[5], nudge(c[0], rng)),
    ]
    rng.shuffle(entities)
    return entities + [point(p, 2) for p in c] + [line((200, 100), (200, 400), 7),
                                                  text("PIECE NAME: FRONT")]


# The chained back, mm: a straight bottom and right side, a neckline ARC bulging up (centre
# (200, 400), from (400, 500) counter-clockwise to (0, 500)), a left side SPLINE (cubic, two
# spans, bulging out to x < 0).
BACK_SPLINE = [(0, 500), (-40, 400), (-40, 250), (-40, 100), (0, 0)]
BACK_KNOTS = [0, 0, 0, 0, 0.5, 1, 1, 1, 1]


def chained_back(rng):
    r = math.hypot(200, 100)
    a1 = math.degrees(math.atan2(100, 200))
    entities = [
        line((0, 0), nudge((400, 0), rng)),
        line((400, 500), (400, 0)),  # backwards
        arc((200, 400), r, a1, 180 - a1),
        spline(3, BACK_SPLINE, BACK_KNOTS),
    ]
    rng.shuffle(entities)
    return entities + [line((200, 100), (200, 400), 7), text("PIECE NAME: BACK")]


def graded_piece(name, size, width, height):
    c = [(0, 0), (width, 0), (width, height), (0, height)]
    return block(f"{name}_{size}", [polyline(c, closed=True)] + [point(p, 2) for p in c]
                 + [line((width / 2, 50), (width / 2, height - 50), 7),
                    text(f"PIECE NAME: {name}"), text(f"SIZE: {size}")])


def main():
    OUT.mkdir(parents=True, exist_ok=True)
    rng = random.Random(34)
    files = {
        "aama_chained_shuffled.dxf": dxf(4, [block("FRONT_M", chained_front(rng)),
                                             block("BACK_M", chained_back(rng))]),
        "aama_gap.dxf": dxf(4, [block("FRONT_M", chained_front(rng, gap=5.0))]),
        # Three sizes, 20 mm wider and 10 mm longer a size: 34 is 400 x 600 mm.
        "aama_graded_sizes.dxf": dxf(
            4, [graded_piece(name, size, 400 + 20 * k, 600 + 10 * k)
                for k, size in enumerate(("34", "36", "38")) for name in ("FRONT", "BACK")],
            [text("SAMPLE SIZE: 36", 0)]),
        # A tank top's front and back in inches, 16 x 23.5 (40.64 x 59.69 cm), no $INSUNITS.
        "aama_no_units.dxf": dxf(None, [
            block("TANK_FRONT", [polyline([(0, 0), (16, 0), (16, 23.5), (0, 23.5)], closed=True),
                                 text("PIECE NAME: FRONT")]),
            block("TANK_BACK", [polyline([(0, 0), (16, 0), (16, 23.5), (0, 23.5)], closed=True),
                                text("PIECE NAME: BACK")])]),
    }
    for name, content in files.items():
        (OUT / name).write_text(content)
        print("wrote", OUT / name)


if __name__ == "__main__":
    main()
