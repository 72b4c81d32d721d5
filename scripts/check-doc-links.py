#!/usr/bin/env python3
"""Checks that every cross reference in README.md and docs/*.md resolves.

Usage: scripts/check-doc-links.py [REPOSITORY_ROOT]

Checked, in the text and in the code blocks alike:
- relative Markdown links and images, `[text](target)` and `![alt](target)`: the file exists
  (relative to the page), and an `#anchor` names a heading of the target page;
- file paths cited in the text (`cases/cylinder_T.prm`, `bodies/mesh_body.h`, `docs/model.md`,
  `scripts/test.sh`, ...): they exist in the repository; a bare page name (`parameters.md`)
  exists beside the page or in docs/;
- cited sections, `docs/model.md, "Friction"` or `[model.md](model.md), "Friction"`: the page
  has a heading, or a paragraph with a bold run-in title (`**Stalls.**`), that starts with the
  quoted title.
- figure paths cited without a link (`figures/stocking_pressure_front.png`): the file exists
  beside the page.
Also checked: every docs/ page that a comment in the code cites exists, and a section it cites
(`docs/model.md, "Friction"`, across a line break too) is a heading of that page.

Not checked: web addresses, and paths under build/ and output/ (a run writes them). A path
with a placeholder component (NNNN, CASE, DIR, ...) or a wildcard is skipped.
Prints one line per broken reference, `file:line: what`, and exits 1 if there is any.
"""
import pathlib
import re
import sys

SOURCE_FOLDERS = ("app", "bench", "bodies", "body", "cases", "contact", "core", "data", "docs", "fem", "fuzz",
                  "instruments", "io", "massspring", "pattern", "scripts", "tests")
CODE_SUFFIXES = (".h", ".cc", ".sh", ".py", ".txt", ".prm", ".cmake")

LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)\)")
PATH = re.compile(r"(?<![\w./-])((?:%s)/[A-Za-z0-9_.\-/]*[A-Za-z0-9_])" % "|".join(SOURCE_FOLDERS))
FIGURE = re.compile(r"(?<![\w./-])(figures/[A-Za-z0-9_.\-]*[A-Za-z0-9_])")
PAGE = re.compile(r"(?<![\w./-])([A-Za-z0-9_-]+\.md)\b")
SECTION = re.compile(r"((?:docs/)?[A-Za-z0-9_-]+\.md)(?:\]\([^)]*\))?\)?,? \(?\"([^\"]+)\"")
CODE_SECTION = re.compile(r"(docs/[A-Za-z0-9_-]+\.md),? \(?\"([^\"]+)\"")
HEADING = re.compile(r"^#+\s+(.*?)\s*$")
PLACEHOLDER = re.compile(r"^(?:[A-Z]+|N+|.*NNNN.*|.*\.\.\..*|.*[*<>{}].*)$")


def slug(title):
    """GitHub's anchor for a heading: lower case, punctuation dropped, spaces to hyphens."""
    title = re.sub(r"[`*_]", "", title.strip().lower())
    title = re.sub(r"[^\w\- ]", "", title)
    return title.replace(" ", "-")


def headings(page):
    titles, fenced = [], False
    for line in page.read_text(encoding="utf-8").splitlines():
        if line.startswith("```"):
            fenced = not fenced
        elif not fenced:
            match = HEADING.match(line)
            if match:
                titles.append(match.group(1))
    return titles


BOLD_LEAD = re.compile(r"^(?:[-*] )?\*\*([^*]+?)\.?\*\*")


def section_titles(page):
    """What a cited section may name: a heading, or a paragraph's bold run-in title
    (`**Stalls.** RK4 watches ...`); backticks dropped."""
    titles, fenced = [], False
    for line in page.read_text(encoding="utf-8").splitlines():
        if line.startswith("```"):
            fenced = not fenced
        elif not fenced:
            match = HEADING.match(line) or BOLD_LEAD.match(line)
            if match:
                titles.append(match.group(1).replace("`", ""))
    return titles


def cited_section_found(page, title):
    wanted = title.lstrip("# ").replace("`", "").strip().lower()
    return any(t.lower().startswith(wanted) for t in section_titles(page))


def has_placeholder(path):
    stem_parts = re.split(r"[/_.]", path)
    return any(PLACEHOLDER.match(part) for part in stem_parts if part)


def check_page(root, page, problems):
    text = page.read_text(encoding="utf-8")
    where = page.relative_to(root)
    cache = {}

    def titles_of(target):
        if target not in cache:
            cache[target] = headings(target)
        return cache[target]

    fenced = False
    for number, line in enumerate(text.splitlines(), start=1):
        if line.startswith("```"):
            fenced = not fenced
        reported = set()
        # In a code block `[...](...)` is code (a C++ lambda), not a link.
        for target in ([] if fenced else LINK.findall(line)):
            if re.match(r"^[a-z]+:", target):
                continue
            path, _, anchor = target.partition("#")
            resolved = (page.parent / path).resolve() if path else page
            if not resolved.exists():
                reported.add(pathlib.Path(path).name)
                problems.append(f"{where}:{number}: link to '{target}': no such file")
            elif anchor and resolved.suffix == ".md":
                if anchor not in {slug(t) for t in titles_of(resolved)}:
                    problems.append(f"{where}:{number}: link to '{target}': "
                                    f"{path or where} has no heading '#{anchor}'")
        for match in PATH.finditer(line):
            path = match.group(1)
            after = line[match.end():match.end() + 2]
            if has_placeholder(path) or after[:1] in ("*", "<", "{") or after == ".*":
                continue
            if pathlib.Path(path).name in reported:
                continue
            if not (root / path).exists():
                problems.append(f"{where}:{number}: cites '{path}', which does not exist")
        for figure in FIGURE.findall(line):
            if has_placeholder(figure) or pathlib.Path(figure).name in reported:
                continue
            if not (page.parent / figure).exists():
                problems.append(f"{where}:{number}: cites '{figure}', which does not exist")
        for name in set(PAGE.findall(line)) - reported:
            if not ((page.parent / name).exists() or (root / "docs" / name).exists()
                    or (root / name).exists()):
                problems.append(f"{where}:{number}: cites the page '{name}', which does not exist")

    # Cited sections may run across a line break: read them in the text with lines joined.
    joined = re.sub(r"\s*\n\s*", " ", text)
    line_starts = [0]
    for line in text.splitlines(keepends=True):
        line_starts.append(line_starts[-1] + len(line))
    # The offset of each joined character in `text`, to name the line a citation starts on.
    offsets, j = [], 0
    for match in re.finditer(r"\s*\n\s*|.", text, flags=re.S):
        offsets.append(match.start())
    for match in SECTION.finditer(joined):
        name, title = match.group(1), match.group(2)
        target = root / name if "/" in name else page.parent / name
        if not target.exists():
            target = root / "docs" / name
        if not target.exists():
            continue  # reported above
        if not cited_section_found(target, title):
            start = offsets[match.start()] if match.start() < len(offsets) else len(text)
            number = sum(1 for s in line_starts[1:] if s <= start) + 1
            problems.append(f"{where}:{number}: cites the section \"{title}\" of {name}, "
                            f"which has no such heading")


# The checker's own test, whose made-up pages cite missing ones on purpose.
NOT_CHECKED = {pathlib.Path("tests/docs/link_checker_finds_broken.sh")}


def check_code(root, problems):
    for file in sorted(root.rglob("*")):
        relative = file.relative_to(root)
        if relative in NOT_CHECKED:
            continue
        if (not file.is_file() or file.suffix not in CODE_SUFFIXES
                or relative.parts[0] not in SOURCE_FOLDERS or relative.parts[0] == "docs"):
            continue
        try:
            text = file.read_text(encoding="utf-8")
        except UnicodeDecodeError:
            continue
        for number, line in enumerate(text.splitlines(), start=1):
            for page in re.findall(r"(?<![\w./-])(docs/[A-Za-z0-9_-]+\.md)", line):
                if not (root / page).exists():
                    problems.append(f"{relative}:{number}: cites '{page}', which does not exist")
        # Cited sections, the comment's lines joined (comment markers dropped).
        lines = text.splitlines()
        joined = " ".join(re.sub(r"^\s*(?://+|#+|\*)?\s*", "", l) for l in lines)
        starts, at = [], 0
        for l in lines:
            starts.append(at)
            at += len(re.sub(r"^\s*(?://+|#+|\*)?\s*", "", l)) + 1
        for match in CODE_SECTION.finditer(joined):
            page, title = root / match.group(1), match.group(2)
            if not page.exists():
                continue  # reported above
            if not cited_section_found(page, title):
                number = sum(1 for s in starts if s <= match.start())
                problems.append(f"{relative}:{number}: cites the section \"{title}\" of "
                                f"{match.group(1)}, which has no such heading")


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
    pages = [root / "README.md"] + sorted((root / "docs").glob("*.md"))
    problems = []
    for page in pages:
        check_page(root, page, problems)
    check_code(root, problems)
    for problem in problems:
        print(problem)
    if problems:
        print(f"{len(problems)} broken cross references in README.md, docs/ and the code's comments")
        return 1
    print(f"every cross reference in README.md and the {len(pages) - 1} pages of docs/ resolves")
    return 0


if __name__ == "__main__":
    sys.exit(main())
