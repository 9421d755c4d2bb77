"""The option documents cannot drift from the code. Options are described once:
docs/options-reference.md, which must be what tools/options_doc.py generates
from this build's -help; docs/options.md is a guide to the option groups that
links to it, and docs/guide.md points to it. So:
  - the reference is up to date (the generator's own --check, which also
    refuses a scene registry line naming no option);
  - the guide names only options tubeform has (a renamed or removed option
    fails here), other than PETSc's own and the misspellings it shows as
    examples of what is refused;
  - the guide holds no second table of every option, and links to each of
    the reference's sections (by its anchor);
  - docs/guide.md and docs/README.md link to the reference;
  - no section of the reference twice (an anchor would reach only the first).
Exact checks on text: nothing here has a tolerance.
"""
import os
import re
import subprocess

from tfcheck import Checks, args

tf, mpirun, src = args()
k = Checks("docs_options")
docs = os.path.join(src, "docs")
p = subprocess.run(["/usr/bin/python3", os.path.join(src, "tools", "options_doc.py"), "--check", tf],
                   capture_output=True, text=True)
k.check(p.returncode == 0, f"docs/options-reference.md up to date: {(p.stdout + p.stderr).strip()}")
reference = open(os.path.join(docs, "options-reference.md")).read()
ref = set(re.findall(r"^\| `-([a-z0-9_]+)`", reference, re.M))
k.check(len(ref) > 50, f"{len(ref)} tubeform options in the reference")

guide = open(os.path.join(docs, "options.md")).read()
# PETSc's own options (the solver's, the viewers', the run's start and end) and the misspellings the guide shows.
PETSC = re.compile(r"(ksp|pc|mat|redundant|vec|viewer|dm|log|options|citations|get_total|build_twosided|help)(_|$)")
EXAMPLES = {"tube_r", "frction_mu", "wall_thickness"}
named, prefixes = set(), set()
for name, star in re.findall(r"`-([a-z][a-z0-9_]*)(\*?)", guide):
    (prefixes if star else named).add(name)  # `-pressure_*`: a group of options by its prefix
unknown = sorted(n for n in named - ref - EXAMPLES if not PETSC.match(n))
unknown += sorted(f"{p}*" for p in prefixes if not PETSC.match(p) and not any(r.startswith(p) for r in ref))
k.check(not unknown, f"the guide names only existing options (unknown: {unknown})")
k.check(len(named & ref) > 50, f"the guide names {len(named & ref)} of the options")
tables = [line[:60] for line in guide.splitlines() if line.startswith("| `-")]
k.check(not tables, f"the guide has no table of options, the reference is that ({len(tables)} rows: {tables[:3]})")
sections = re.findall(r"^## (.+)$", reference, re.M)
twice = sorted({x for x in sections if sections.count(x) > 1})
k.check(not twice, f"each of the reference's sections once (twice: {twice})")
anchors = [re.sub(r"[^a-z0-9_ -]", "", s.lower()).replace(" ", "-") for s in sections]
missing = [a for a in anchors if f"options-reference.md#{a})" not in guide]
k.check(sections and not missing, f"the guide links each of the reference's {len(sections)} sections (missing: {missing})")
for name in ("guide.md", "README.md"):
    text = open(os.path.join(docs, name)).read() if os.path.exists(os.path.join(docs, name)) else ""
    k.check("options-reference.md" in text, f"docs/{name} links to the options reference")
k.done()
