"""The code's structure rules (docs/architecture.md, "Layers"), checked on the
source tree:
  - no include runs upward: a file in component A includes tubeform headers
    of A itself or of components in lower layers only (the layer table below
    is the one docs/architecture.md draws);
  - every component folder is in the table (a new folder must be placed);
  - no source or header file over 450 lines (one concern per file; the
    project aims at about 400);
  - the code is formatted by .clang-format (clang-format --dry-run --Werror),
    which also bounds lines at 120 columns.
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
k.done()
