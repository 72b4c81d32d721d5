#!/usr/bin/env python3
"""Writes the triangles of a garment VTU (tightfit's io/vtu_writer.cc) as gnuplot polygons.

The VTU holds raw appended, zlib-compressed binary arrays (VTK's XML format); this reads them
with Python's standard library alone (no VTK), so the figure needs only python3 and gnuplot.

Usage: vtu_triangles.py GARMENT.vtu OUT.dat VMAX [LEVELS [ARRAY]]
  VMAX    top of the colour scale, in ARRAY's unit (the bottom is 0)
  LEVELS  colour levels (default 48)
  ARRAY   a point-data scalar (default pressure_Pa)
OUT.dat: a first comment line "# alpha A", then LEVELS gnuplot data sets (index 0 to
LEVELS - 1, separated by two blank lines). Set k holds the triangles whose mean vertex value
lies in [k, k + 1) VMAX / LEVELS, each as three lines "x_cm y_cm z_cm value" and a blank
line; an empty set holds one triangle of zero area at the origin. gnuplot 5.4 draws
`with polygons` in one colour per plot, so the figure plots each set in its level's colour.
"""
import re
import struct
import sys
import zlib

NUMPY_TYPES = {"Float64": "d", "Float32": "f", "Int64": "q", "Int32": "i", "UInt8": "B",
               "UInt32": "I", "UInt64": "Q", "Int8": "b"}


def attributes(tag):
    return dict(re.findall(r'(\w+)="([^"]*)"', tag))


def read_vtu(path):
    data = open(path, "rb").read()
    head, _, appended = data.partition(b"<AppendedData")
    text = head.decode("latin-1")
    file_attributes = attributes(re.search(r"<VTKFile[^>]*>", text).group(0))
    if file_attributes.get("compressor", "") not in ("", "vtkZLibDataCompressor"):
        sys.exit(f"{path}: compressor {file_attributes['compressor']} not supported")
    compressed = "compressor" in file_attributes
    header_code = "Q" if file_attributes.get("header_type", "UInt32") == "UInt64" else "I"
    header_size = struct.calcsize(header_code)
    raw = appended[appended.index(b"_") + 1:]

    def decode(offset, type_name):
        position = int(offset)
        if compressed:
            n_blocks = struct.unpack_from("<" + header_code, raw, position)[0]
            header = struct.unpack_from(f"<{3 + n_blocks}{header_code}", raw, position)
            position += header_size * (3 + n_blocks)
            payload = b""
            for size in header[3:]:
                payload += zlib.decompress(raw[position:position + size])
                position += size
        else:
            n_bytes = struct.unpack_from("<" + header_code, raw, position)[0]
            payload = raw[position + header_size:position + header_size + n_bytes]
        code = NUMPY_TYPES[type_name]
        return struct.unpack(f"<{len(payload) // struct.calcsize(code)}{code}", payload)

    arrays = {}
    sections = re.split(r"(<PointData|<Cells|<Points|<FieldData|<CellData)", text)
    section = ""
    for part in sections:
        if part.startswith("<"):
            section = part[1:]
            continue
        for tag in re.findall(r"<DataArray[^>]*>", part):
            a = attributes(tag)
            if "offset" not in a:
                continue
            name = a.get("Name", "")
            arrays[(section, name)] = (decode(a["offset"], a["type"]),
                                       int(a.get("NumberOfComponents", "1")))
    alpha = arrays.get(("FieldData", "alpha"), ([float("nan")], 1))[0][0]
    return arrays, alpha


def main():
    if len(sys.argv) not in (4, 5, 6):
        sys.exit(__doc__)
    value_max = float(sys.argv[3])
    n_levels = int(sys.argv[4]) if len(sys.argv) >= 5 else 48
    array_name = sys.argv[5] if len(sys.argv) == 6 else "pressure_Pa"
    arrays, alpha = read_vtu(sys.argv[1])
    points = next(v for (s, _), v in arrays.items() if s == "Points")[0]
    connectivity = arrays[("Cells", "connectivity")][0]
    values = arrays[("PointData", array_name)][0]
    levels = [[] for _ in range(n_levels)]
    for t in range(0, len(connectivity), 3):
        corners = connectivity[t:t + 3]
        mean = sum(values[v] for v in corners) / 3.0
        level = min(n_levels - 1, max(0, int(mean / value_max * n_levels)))
        block = ""
        for v in corners:
            x, y, z = (100.0 * c for c in points[3 * v:3 * v + 3])
            block += f"{x:.5g} {y:.5g} {z:.5g} {mean:.6g}\n"
        levels[level].append(block)
    with open(sys.argv[2], "w") as out:
        out.write(f"# alpha {alpha}\n")
        for k, blocks in enumerate(levels):
            if k > 0:
                out.write("\n\n")
            out.write("\n".join(blocks) if blocks else "0 0 0 0\n0 0 0 0\n0 0 0 0\n")


if __name__ == "__main__":
    main()
