"""The -progress line: a long run says where it is without
-monitor's line per increment. The fast preset's squaring run (about 1.5 s
on 2 ranks) with a line every 0.05 s must print several lines, once each (rank
0 only), with the loading's percent and stroke rising and every percent in
[0, 100]; -progress 0 prints none. The interval is a wall-clock one, so the
count is only bounded below (3 lines of a run 30 intervals long: a loaded
machine slows the run and adds lines, never removes them).
"""
import re

from tfcheck import Checks, args, out, run

tf, mpirun, src = args()
k = Checks("progress")
base = ["-options_file", f"{src}/options/squaring.opts", "-options_file", f"{src}/options/preset-fast.opts",
        "-output", out("progress.h5")]
LINE = re.compile(r"^tubeform: (loading|unloading) +(\d+) % \(stroke (\S+)\), (\d+) increments, .* left in the \1$")
p = run(tf, mpirun, 2, base + ["-progress", "0.05"])
lines = [l for l in p.stdout.splitlines() if l.startswith("tubeform: loading") or l.startswith("tubeform: unloading")]
parsed = [LINE.match(l) for l in lines]
k.check(len(lines) >= 3 and all(parsed), f"{len(lines)} progress lines, all of the documented form")
k.check(len(set(lines)) == len(lines), "each line printed once (rank 0 only)")
load = [(int(m.group(2)), float(m.group(3)), int(m.group(4))) for m in parsed if m and m.group(1) == "loading"]
k.check(len(load) >= 2 and all(0 <= pc <= 100 for pc, _, _ in load),
        f"{len(load)} loading lines (at least 2), percent within [0, 100]")
k.check(all(a[0] <= b[0] and a[1] <= b[1] and a[2] < b[2] for a, b in zip(load, load[1:])),
        "percent, stroke and increments rise from line to line")
p = run(tf, mpirun, 2, base + ["-progress", "0"])
k.check(not any(l.startswith("tubeform: loading") for l in p.stdout.splitlines()), "-progress 0: no lines")
k.done()
