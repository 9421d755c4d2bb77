"""The option documents cannot drift from the code: docs/options-reference.md
must be what scripts/options_doc.py generates from this build's -help, and
the guide docs/options.md must name every tubeform option and no option
tubeform does not have (a renamed or removed option fails here).
"""
import os
import re
import subprocess

from tfcheck import Checks, args

tf, mpirun, src = args()
k = Checks("docs_options")
p = subprocess.run(["/usr/bin/python3", os.path.join(src, "scripts", "options_doc.py"), "--check", tf],
                   capture_output=True, text=True)
k.check(p.returncode == 0, f"docs/options-reference.md up to date: {(p.stdout + p.stderr).strip()}")
ref = set(re.findall(r"^\| `-([a-z0-9_]+)`", open(os.path.join(src, "docs", "options-reference.md")).read(), re.M))
guide = set()
for line in open(os.path.join(src, "docs", "options.md")).read().splitlines():
    if line.startswith("| `-"):
        guide |= set(re.findall(r"`-([a-z0-9_]+)", line.split("|")[1]))
k.check(len(ref) > 50, f"{len(ref)} tubeform options in the reference")
k.check(not ref - guide, f"every option in the guide (missing: {sorted(ref - guide)})")
k.check(not guide - ref, f"the guide names only existing options (unknown: {sorted(guide - ref)})")
k.done()
