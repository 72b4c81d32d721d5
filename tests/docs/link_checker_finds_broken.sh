#!/usr/bin/env bash
# scripts/check-doc-links.py on a small made-up repository with one broken reference of each
# kind it checks: it must name every one (and pass the references that resolve).
#   link_checker_finds_broken.sh CHECKER SCRATCH_DIR
set -u
checker=$1
root=$2
rm -rf "$root"
mkdir -p "$root/docs/figures" "$root/core"
touch "$root/docs/figures/shown.png"
cat >"$root/README.md" <<'PAGE'
# Readme
The manual: [docs/a.md](docs/a.md), [its friction](docs/a.md#friction), `core/here.h`.
PAGE
cat >"$root/docs/a.md" <<'PAGE'
# A
## Friction
**Stalls.** A bold run-in title.

![shown](figures/shown.png) and figures/shown.png; [b.md](b.md), "Friction"; a.md, "Stalls".
Broken: [x](b.md#no-heading), ![f](figures/missing.png), [y](missing.md), `core/missing.h`.
Also figures/unlinked.png, the page gone.md and [b.md](b.md), "No such section".
PAGE
cat >"$root/docs/b.md" <<'PAGE'
# B
## Friction
PAGE
cat >"$root/core/here.h" <<'CODE'
// The law (docs/a.md, "Friction"), the run-in title (docs/a.md, "Stalls"), and a section
// that moved (docs/a.md, "Gone
// section") and a page that did not exist (docs/nothere.md).
CODE
output=$(python3 "$checker" "$root" 2>&1)
status=$?
fail() { printf '%s\n--- checker output:\n%s\n' "$1" "$output"; exit 1; }
[ "$status" -eq 1 ] || fail "expected exit status 1, got $status"
for expected in \
  "docs/a.md:6: link to 'b.md#no-heading': b.md has no heading '#no-heading'" \
  "docs/a.md:6: link to 'figures/missing.png': no such file" \
  "docs/a.md:6: link to 'missing.md': no such file" \
  "docs/a.md:6: cites 'core/missing.h', which does not exist" \
  "docs/a.md:7: cites 'figures/unlinked.png', which does not exist" \
  "docs/a.md:7: cites the page 'gone.md', which does not exist" \
  "docs/a.md:7: cites the section \"No such section\" of b.md" \
  "core/here.h:2: cites the section \"Gone section\" of docs/a.md" \
  "core/here.h:3: cites 'docs/nothere.md', which does not exist"; do
  grep -qF -- "$expected" <<<"$output" || fail "not reported: $expected"
done
count=$(grep -c ":[0-9]*: " <<<"$output")
[ "$count" -eq 9 ] || fail "expected exactly the 9 broken references, got $count"
echo "the checker names all 9 broken references and passes the rest"
