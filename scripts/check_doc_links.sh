#!/usr/bin/env bash
# Checks that every document reference in README.md and docs/*.md resolves inside the repository:
#  - markdown links [text](target): relative to the document's folder; http(s)/mailto links are
#    skipped; a #fragment pointing into a markdown file must name one of its headings (GitHub's
#    anchor form: lower case, punctuation dropped, spaces as hyphens); a target that leaves the
#    repository or is an absolute path fails;
#  - repository paths written in the text, with or without backticks (docs/..., scripts/...,
#    rtl/..., model/..., tests/..., tb/... and any other top-level folder of the tree): relative to
#    the repository root; a path with '*' must match at least one file;
#  - absolute paths under /work/ or /home/ (a file of one machine, not of the repository).
# Prints FILE:LINE: REFERENCE: WHY for each failure and exits 1 when there is one, 0 otherwise.
#   scripts/check_doc_links.sh [REPO_ROOT]          (default: the repository holding this script)
set -euo pipefail
root="${1:-$(cd "$(dirname "$0")/.." && pwd)}"
[ -d "$root" ] || { echo "check_doc_links: $root: not a directory" >&2; exit 2; }
exec /usr/bin/python3 - "$root" <<'PY'
import glob
import os
import re
import subprocess
import sys

root = os.path.realpath(sys.argv[1])
docs = [os.path.join(root, "README.md")] + sorted(glob.glob(os.path.join(root, "docs", "*.md")))
docs = [d for d in docs if os.path.isfile(d)]
if not docs:
    print(f"check_doc_links: {root}: no README.md or docs/*.md", file=sys.stderr)
    sys.exit(2)

# Top-level folders whose paths are checked: the usual ones (also once they are gone, so that a
# document still naming a moved folder fails) and every top-level folder of the tree.
prefixes = {"docs", "scripts", "rtl", "model", "tests", "tb", "app", "tools", "cmake"}
# Folders git ignores (build/, out/: what runs write) hold no repository paths.
def ignored(name):
    return subprocess.run(["git", "-C", root, "check-ignore", "-q", name + "/"],
                          stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL).returncode == 0
for name in os.listdir(root):
    if os.path.isdir(os.path.join(root, name)) and not name.startswith(".") \
            and not name.startswith("build") and not ignored(name):
        prefixes.add(name)
prefix_alt = "|".join(sorted(map(re.escape, prefixes), key=len, reverse=True))
path_re = re.compile(r"(?<![\w./~$-])((?:%s)/[\w./*+-]*)" % prefix_alt)
link_re = re.compile(r"!?\[[^\]]*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
abs_re = re.compile(r"(?<![\w.-])(/(?:work|home)/[\w./*+-]+)")


def slug(heading):
    s = heading.strip().lower()
    s = re.sub(r"[^\w\- ]", "", s)
    return s.replace(" ", "-")


anchors_cache = {}


def anchors(path):
    if path not in anchors_cache:
        found, seen, fenced = set(), {}, False
        with open(path, encoding="utf-8") as f:
            for line in f:
                if line.lstrip().startswith("```"):
                    fenced = not fenced
                    continue
                m = re.match(r"#{1,6}\s+(.*?)\s*#*\s*$", line)
                if m and not fenced:
                    base = slug(re.sub(r"[`*_]", "", m.group(1)))
                    n = seen.get(base, 0)
                    seen[base] = n + 1
                    found.add(base if n == 0 else f"{base}-{n}")
        anchors_cache[path] = found
    return anchors_cache[path]


def inside(path):
    return path == root or path.startswith(root + os.sep)


failures = 0


def fail(doc, lineno, ref, why):
    global failures
    failures += 1
    print(f"{os.path.relpath(doc, root)}:{lineno}: {ref}: {why}")


for doc in docs:
    here = os.path.dirname(doc)
    with open(doc, encoding="utf-8") as f:
        lines = f.read().split("\n")
    for lineno, line in enumerate(lines, 1):
        link_spans = []
        for m in link_re.finditer(line):
            link_spans.append(m.span(1))
            target = m.group(1)
            if re.match(r"[a-zA-Z][a-zA-Z0-9+.-]*:", target):  # http:, https:, mailto:, ...
                continue
            file_part, _, frag = target.partition("#")
            if file_part.startswith("/"):
                fail(doc, lineno, target, "absolute path (links must be relative)")
                continue
            resolved = os.path.realpath(os.path.join(here, file_part)) if file_part else doc
            if not inside(resolved):
                fail(doc, lineno, target, "points outside the repository")
            elif not os.path.exists(resolved):
                fail(doc, lineno, target, "does not exist")
            elif frag and resolved.endswith(".md") and frag not in anchors(resolved):
                fail(doc, lineno, target, f"no heading with anchor #{frag} in "
                     + os.path.relpath(resolved, root))
        for m in path_re.finditer(line):
            if any(a <= m.start(1) < b for a, b in link_spans):
                continue  # a link target, checked above relative to the document
            ref = m.group(1).rstrip(".,:;")
            if not ref or ref.endswith("/.."):
                continue
            full = os.path.join(root, ref)
            if "*" in ref:
                if not glob.glob(full):
                    fail(doc, lineno, ref, "matches no file")
            elif not os.path.exists(full):
                fail(doc, lineno, ref, "does not exist")
        for m in abs_re.finditer(line):
            fail(doc, lineno, m.group(1), "absolute path of one machine, not a repository path")

sys.exit(1 if failures else 0)
PY
