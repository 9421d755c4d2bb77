"""Whether two tubeform binaries give the same histories, bit for bit, on the documented examples: a change that
should not move the physics (a restructuring) is checked against a binary built from the commit before it.

    git worktree add /tmp/before <commit> && cmake -S /tmp/before -B /tmp/before/build && \
        cmake --build /tmp/before/build -j2 --target tubeform
    source scripts/env.sh
    /usr/bin/python3 tools/same_history.py /tmp/before/build/tubeform build/tubeform [--cases REGEX]

Runs each case (the default case, the unloadings, the die's own path and turn, a force-driven die on 1 and 2
ranks, passes turned, side dies, the lower die's path and pulse, the half and full models with either hold, the
slide scenes, and a checkpoint continued by a restart) with both binaries, in --dir (default results/same_history:
ref/ and new/), and compares every /history dataset (names, shapes, every byte of the values) and the /history
attributes, the CSV file byte for byte, the standard output with its wall times taken out (the progress lines
come every 10 s of wall time), the standard error and the exit code. One line per case; exit code 1 if any
differs. About four minutes on two cores.
"""
import argparse
import filecmp
import os
import re
import subprocess
import sys

import h5py
import numpy as np

SQ, DEFAULT, FAST = "-options_file options/squaring.opts", "-options_file options/preset-default.opts", \
    "-options_file options/preset-fast.opts"
QUICK = f"{SQ} {DEFAULT} -error_estimate 0"
CASES = [  # name, ranks, options
    ("default", 1, f"{SQ} {DEFAULT}"),
    ("default_ee0", 1, QUICK),
    ("unload_reverse", 1, f"{QUICK} -unload reverse"),
    ("unload_withdraw", 1, f"{QUICK} -unload withdraw"),
    ("unload_none", 1, f"{QUICK} -unload none"),
    ("die_path", 1, f"{SQ} {FAST} -lower_die_motion fixed -die_path 0,-2,0.5,-2,0.5,-3"),
    ("die_turn", 1, f"{SQ} {FAST} -lower_die_motion fixed -die_path 0,-2,0,-3 -die_path_turn 0,5 -die_pivot 0,24.75"),
    ("force_n1", 1, f"{QUICK} -die_force 110"),
    ("force_n2", 2, f"{QUICK} -die_force 110"),
    ("turned_n2", 2, f"{QUICK} -stroke 3 -pass2_stroke 3 -pass2_turn 90"),
    ("floor_turned", 1, f"{SQ} {FAST} -stroke 2 -lower_die flat -pass2_turn 90 -pass2_stroke 2"),
    ("side_flatten", 1, "-options_file options/flattening.opts -side_die flat -stroke 3"),
    ("side_pass2", 1, f"{SQ} -stroke 2 -pass2_stroke 2 -pass2_turn 90 -pass2_side_die flat -error_estimate 0"),
    ("side_force", 1, f"{SQ} {FAST} -stroke 3 -side_die flat -side_force 20"),
    ("lower_pulse", 1, f"{SQ} {FAST} -stroke 2 -lower_die_motion pulse -lower_die_pulse_amplitude 0.3 "
                       "-lower_die_pulse_period 0.5"),
    ("lower_path", 1, f"{SQ} {FAST} -stroke 2 -lower_die_motion path -lower_die_path 1,0,2,1"),
    ("half", 1, f"{SQ} {FAST} -model half"),
    ("full_rotation", 1, f"{SQ} {FAST} -model full -full_hold rotation"),
    ("full_pins", 1, f"{SQ} {FAST} -model full -full_hold pins"),
    ("offset", 1, f"{SQ} {FAST} -stroke 2 -die_offset 0.5"),
    ("slide", 1, "-options_file options/slide.opts"),
    ("slide_arc", 1, "-options_file options/slide_arc.opts"),
]
# A checkpoint written at increment 30 of a run stopped at 40, continued by a restart to the end.
RESTART = ("restart", f"{SQ} {FAST} -stroke 2 -die_offset 0.5")


def run(binary, ranks, options, stem, extra=()):
    cmd = (["mpirun", "-n", str(ranks)] if ranks > 1 else []) + [binary] + options.split() + list(extra)
    with open(stem + ".out", "w") as out, open(stem + ".err", "w") as err:
        rc = subprocess.run(cmd, stdin=subprocess.DEVNULL, stdout=out, stderr=err).returncode
    open(stem + ".rc", "w").write(f"{rc}\n")


def run_case(binary, where, name, ranks, options):
    s = os.path.join(where, name)
    run(binary, ranks, options, s, ["-output", s + ".h5", "-history_csv", s + ".csv"])


def run_restart(binary, where):
    name, options = RESTART
    s, ck = os.path.join(where, name), os.path.join(where, name + ".ck.h5")
    if os.path.exists(ck):
        os.remove(ck)
    files = ["-output", s + ".h5", "-checkpoint", ck]
    run(binary, 1, options, s + "_first", files + ["-history_csv", s + "_first.csv", "-checkpoint_every", "30",
                                                    "-rmin_max_increments", "40"])
    run(binary, 1, options, s, files + ["-history_csv", s + ".csv", "-restart", ck])


def text(path, where):
    t = open(path).read().replace(where, "DIR")
    t = "".join(line for line in t.splitlines(True) if " s so far" not in line)
    return re.sub(r"\d+(\.\d+)? s\b", "T s", t)


def differences(ref, new, stem):
    msgs = []
    a, b = os.path.join(ref, stem), os.path.join(new, stem)
    if os.path.exists(a + ".h5"):
        with h5py.File(a + ".h5", "r") as fa, h5py.File(b + ".h5", "r") as fb:
            ha, hb = fa["/history"], fb["/history"]
            if sorted(ha) != sorted(hb):
                msgs.append(f"datasets {sorted(set(ha) ^ set(hb))}")
            msgs += [f"{k} differs" for k in ha if k in hb and ha[k][()].tobytes() != hb[k][()].tobytes()]
            if sorted(ha.attrs) != sorted(hb.attrs):
                msgs.append(f"attributes {sorted(set(ha.attrs) ^ set(hb.attrs))}")
            msgs += [f"attribute {k} differs" for k in ha.attrs
                     if k in hb.attrs and not np.array_equal(np.asarray(ha.attrs[k]), np.asarray(hb.attrs[k]))]
    if os.path.exists(a + ".csv") and not filecmp.cmp(a + ".csv", b + ".csv", shallow=False):
        msgs.append("the CSV differs")
    msgs += [f"{ext} differs" for ext in (".out", ".err", ".rc") if text(a + ext, ref) != text(b + ext, new)]
    return msgs


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("ref", help="the binary before")
    p.add_argument("new", help="the binary after")
    p.add_argument("--cases", default=".", help="a regular expression: the cases whose name matches it")
    p.add_argument("--dir", default="results/same_history")
    o = p.parse_args()
    chosen = [c for c in CASES if re.search(o.cases, c[0])]
    restart = re.search(o.cases, RESTART[0]) is not None
    stems = [c[0] for c in chosen] + ([RESTART[0] + "_first", RESTART[0]] if restart else [])
    for binary, sub in ((o.ref, "ref"), (o.new, "new")):
        where = os.path.abspath(os.path.join(o.dir, sub))
        os.makedirs(where, exist_ok=True)
        for name, ranks, options in chosen:
            run_case(os.path.abspath(binary), where, name, ranks, options)
        if restart:
            run_restart(os.path.abspath(binary), where)
    ref, new = (os.path.abspath(os.path.join(o.dir, s)) for s in ("ref", "new"))
    bad = 0
    for stem in stems:
        msgs = differences(ref, new, stem)
        bad += bool(msgs)
        print(f"{stem:16s} " + ("same" if not msgs else "DIFFERS: " + "; ".join(msgs)))
    print(f"{len(stems) - bad} of {len(stems)} the same")
    sys.exit(1 if bad or not stems else 0)


if __name__ == "__main__":
    main()
