"""The code's structure rules (docs/architecture.md, "Layers"), checked on the
source tree:
  - no include runs upward: a file in component A includes tubeform headers
    of A itself or of components in lower layers only (the layer table below
    is the one docs/architecture.md draws);
  - every component folder is in the table (a new folder must be placed);
  - no source or header file over 450 lines (one concern per file; the
    project aims at about 400);
  - the code is formatted by .clang-format (clang-format --dry-run --Werror),
    which also bounds lines at 120 columns;
  - the project stands alone: no file of the project's own folders (src,
    include, tests, scripts, studies, tools, options, docs, .ci) and no
    README.md or CMakeLists.txt cites the method specification kept outside
    the repository (the theory the code cites is in docs/theory.md and the
    docs beside it), and none names a tracker's "issue N": a doc or comment
    says what a thing is, not which issue brought it.
Usage: check_structure.py <unused> <unused> <source dir>
"""
import os
import re
import subprocess
import sys

from tfcheck import Checks

src = sys.argv[3]
k = Checks("structure")
LAYERS = [
    ["core"],
    ["fe", "mesh", "tool"],
    ["material", "step"],
    ["assembly"],
    ["body", "contact"],
    ["metrics"],
    ["io"],
    ["scenes"],
    ["driver"],
]
layer = {c: i for i, comps in enumerate(LAYERS) for c in comps}
include = re.compile(r'#include\s+"tubeform/([a-z_]+)/[^"]+"')
files = []
for top in ("src", "include/tubeform"):
    for root, _, names in os.walk(os.path.join(src, top)):
        files += [os.path.join(root, n) for n in names if n.endswith((".cpp", ".hpp"))]

upward, unknown, long_files = [], set(), []
for f in files:
    rel = os.path.relpath(f, src)
    parts = rel.split(os.sep)
    comp = parts[2] if parts[0] == "include" else parts[1]
    if comp.endswith(".cpp"):  # src/main.cpp: the application, above every layer
        comp = None
    elif comp not in layer:
        unknown.add(comp)
        continue
    text = open(f).read()
    for dep in include.findall(text):
        if dep not in layer:
            unknown.add(dep)
        elif comp is not None and dep != comp and layer[dep] >= layer[comp]:
            upward.append(f"{rel} includes {dep}/ (layer {layer[dep]} >= {layer[comp]} of {comp}/)")
    n = text.count("\n")
    if n > 450:
        long_files.append(f"{rel} ({n} lines)")

missing = f": missing {', '.join(sorted(unknown))}" if unknown else ""
k.check(not unknown, f"every component is placed in a layer{missing}")
k.check(not upward, f"no include runs upward ({len(files)} files)" + "".join("\n         " + u for u in upward))
k.check(not long_files, "no file over 450 lines" + "".join("\n         " + u for u in long_files))
tests = os.path.join(src, "tests")
code = files + [os.path.join(tests, n) for n in os.listdir(tests) if n.endswith((".cpp", ".hpp"))]
p = subprocess.run(["clang-format", "--dry-run", "--Werror", f"--style=file:{src}/.clang-format"] + code,
                   capture_output=True, text=True)
bad = sorted({line.split(":")[0] for line in p.stderr.splitlines() if "error:" in line})
k.check(p.returncode == 0, "formatted by .clang-format" + "".join("\n         " + os.path.relpath(b, src) for b in bad))

# Stands alone. The outside specification's file name is spelled in two pieces so that this file does not cite it.
outside = re.compile(re.escape("METHOD" + ".md"))
issue = re.compile(r"\bissues? #?[0-9]+", re.I)
roots = ["src", "include", "tests", "scripts", "studies", "tools", "options", "docs", ".ci"]
texts = [os.path.join(src, n) for n in ("README.md", "CMakeLists.txt") if os.path.exists(os.path.join(src, n))]
for top in roots:
    for root, dirs, names in os.walk(os.path.join(src, top)):
        dirs[:] = [d for d in dirs if d not in ("__pycache__", "build")]
        texts += [os.path.join(root, n) for n in names]
cites, issues = [], []
for f in texts:
    try:
        lines = open(f, encoding="utf-8").read().splitlines()
    except (UnicodeDecodeError, OSError):
        continue  # figures, HDF5 references: not text
    rel = os.path.relpath(f, src)
    cites += [f"{rel}:{i}" for i, line in enumerate(lines, 1) if outside.search(line)]
    for i, line in enumerate(lines):
        # A reference wrapped after "issue" continues on the next line, past its comment marker.
        nxt = re.sub(r"^\s*(#|//|\*)?\s*", "", lines[i + 1]) if i + 1 < len(lines) else ""
        m = issue.search(line + " " + nxt)
        if m and m.start() < len(line):
            issues.append(f"{rel}:{i + 1}: {m.group(0)}")
k.check(not cites, f"no file cites the outside specification ({len(texts)} files)"
        + "".join("\n         " + c for c in cites))
k.check(not issues, "no file names an issue by number" + "".join("\n         " + c for c in issues))
k.done()
