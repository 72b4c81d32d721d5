#!/usr/bin/env python3
"""Checks that the includes follow the layer table of the developer guide.

Usage: scripts/check-layers.py [REPOSITORY_ROOT]

The table under "## The layers" in docs/scenarios.md is the rule: its first column names a
folder (or several), its second the folders that folder may include, in backticks ("(Eigen
only)": none). Checked:
- every `#include "FOLDER/..."` in a listed folder's .h, .cc and .in files names the folder
  itself or one its row allows;
- each allowed folder has a row above the one that allows it, so the table is an order of
  layers and no include can run back up or close a cycle;
- the drawing below the table (a code block, one line per layer from the top) holds each
  folder of the table once, and every folder a row allows lies on a line below that row's;
- every top-level folder whose CMakeLists.txt builds a library has a row;
- the backends' folders are included from no other folder except by the files that
  BACKEND_USERS lists (the backend registry); a listed file that no longer includes a backend
  fails too, so the list only shrinks.
Prints one line per broken rule, `file:line: what`, and exits 1 if there is any.
"""
import pathlib
import re
import sys

BACKENDS = ("massspring", "fem")
# Files outside the backends' folders that may include a backend's headers (docs/scenarios.md,
# "The layers").
BACKEND_USERS = ("cases/backends.cc",)
SUFFIXES = (".h", ".cc", ".in")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([a-z_]+)/')
FOLDER = re.compile(r"`([a-z_]+)/`")
DRAWN = re.compile(r"(?<![\w/])([a-z_]+)/")


def layer_section(root):
    """The layer table's rows, in order: (line, [folders], [allowed folders]); and the
    drawing's layers from the top: {folder: (line, layer index)}."""
    rows = []
    drawing = {}
    in_section = False
    in_drawing = False
    page = root / "docs" / "scenarios.md"
    for number, line in enumerate(page.read_text().splitlines(), 1):
        if line.startswith("## "):
            in_section = line.strip() == "## The layers"
            continue
        if not in_section:
            continue
        if line.startswith("```"):
            if in_drawing or not drawing:
                in_drawing = not in_drawing
            continue
        if in_drawing:
            layer = len({index for _, index in drawing.values()})
            for folder in DRAWN.findall(line):
                drawing.setdefault(folder, (number, layer))
            continue
        if not line.startswith("|"):
            continue
        cells = [cell.strip() for cell in line.strip().strip("|").split("|")]
        folders = FOLDER.findall(cells[0])
        if len(cells) < 2 or not folders:
            continue  # the header row and its rule
        rows.append((number, folders, FOLDER.findall(cells[1])))
    return rows, drawing


def includes(root, folder):
    """(path, line number, included folder) for every project include in the folder."""
    for path in sorted((root / folder).rglob("*")):
        if path.suffix not in SUFFIXES or not path.is_file():
            continue
        for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
            match = INCLUDE.match(line)
            if match and (root / match.group(1)).is_dir():
                yield path.relative_to(root).as_posix(), number, match.group(1)


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
    page = "docs/scenarios.md"
    problems = []
    rows, drawing = layer_section(root)
    if not rows:
        problems.append(f'{page}: no layer table under "## The layers"')
    if not drawing:
        problems.append(f'{page}: no drawing of the layers under "## The layers"')

    allowed = {}
    seen = set()
    for number, folders, may_include in rows:
        for other in may_include:
            if other not in seen:
                problems.append(f"{page}:{number}: {', '.join(folders)} may include {other}/, "
                                "which has no row above it (the table must be an order of layers)")
        for folder in folders:
            if not (root / folder).is_dir():
                problems.append(f"{page}:{number}: no folder {folder}/")
            allowed[folder] = set(may_include)
        seen.update(folders)
    for number, folders, may_include in rows:
        for folder in folders:
            if folder not in drawing:
                problems.append(f"{page}:{number}: {folder}/ is not in the drawing of the layers")
                continue
            for other in may_include:
                if other in drawing and drawing[other][1] <= drawing[folder][1]:
                    problems.append(f"{page}:{drawing[folder][0]}: the drawing puts {other}/ "
                                    f"on or above {folder}/, which may include it")
    for folder, (number, _) in drawing.items():
        if folder not in allowed:
            problems.append(f"{page}:{number}: {folder}/ is drawn but has no row in the table")

    for cmake in sorted(root.glob("*/CMakeLists.txt")):
        folder = cmake.parent.name
        if "add_library(" in cmake.read_text() and folder not in allowed:
            problems.append(f"{cmake.relative_to(root)}: builds a library, but {page} has no "
                            f"row for {folder}/")

    backend_users_seen = set()
    for folder, may_include in allowed.items():
        for path, number, included in includes(root, folder):
            if included != folder and included not in may_include:
                problems.append(f"{path}:{number}: includes {included}/, which {folder}/ may "
                                f"not include ({page}, \"The layers\")")
            if included in BACKENDS and included != folder:
                if path in BACKEND_USERS:
                    backend_users_seen.add(path)
                else:
                    problems.append(f"{path}:{number}: includes the backend {included}/ outside "
                                    "the registry (scripts/check-layers.py, BACKEND_USERS)")
    for path in BACKEND_USERS:
        if path not in backend_users_seen:
            problems.append(f"{path}: listed in BACKEND_USERS but includes no backend: drop it "
                            "from the list")

    for problem in problems:
        print(problem)
    if problems:
        return 1
    print(f"{sum(len(r[1]) for r in rows)} folders follow the {len(rows)} layers of {page}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
