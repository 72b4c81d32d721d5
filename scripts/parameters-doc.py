#!/usr/bin/env python3
"""Writes docs/parameters.md from `tightfit --print-parameters --json`.

Usage: scripts/parameters-doc.py [path/to/tightfit] > docs/parameters.md
"""
import json
import subprocess
import sys


def allowed(pattern_description):
    """deal.II's pattern text, made readable: [Double 0...MAX_DOUBLE (inclusive)] -> >= 0."""
    text = pattern_description.strip("[]")
    text = text.replace("MAX_DOUBLE", "inf").replace("MAX_INT", "inf")
    text = text.replace(" (inclusive)", "").replace("...", " to ")
    if text.startswith("Selection "):
        return "one of: " + ", ".join(f"`{v.strip()}`" for v in text[len("Selection "):].split("|"))
    return text


def entries(section, path):
    for name, value in section.items():
        if isinstance(value, dict) and "default_value" in value:
            yield path, name, value
        elif isinstance(value, dict):
            yield from entries(value, path + [name])


def main():
    tightfit = sys.argv[1] if len(sys.argv) > 1 else "build/app/tightfit"
    listing = subprocess.run([tightfit, "--print-parameters", "--json"], check=True,
                             capture_output=True, text=True).stdout
    tree = json.loads(listing)
    print("# Parameters\n")
    print("Every entry of a case file (`.prm`), by subsection, in SI units. Made by")
    print("`scripts/parameters-doc.py > docs/parameters.md` from `tightfit --print-parameters --json`;")
    print("`tightfit --print-parameters` shows the same on screen, `--prm` as a case file to start")
    print("from. Override any entry on the command line with `--set \"Subsection/Entry=value\"`.\n")
    current = None
    for path, name, value in entries(tree, []):
        section = "/".join(path)
        if section != current:
            current = section
            print(f"\n## {section}\n")
            print("| entry | default | allowed | meaning |")
            print("|---|---|---|---|")
        doc = value["documentation"].replace("|", "\\|").replace("\n", " ")
        print(f"| {name} | `{value['default_value']}` | {allowed(value['pattern_description'])}"
              f" | {doc} |")


if __name__ == "__main__":
    main()
