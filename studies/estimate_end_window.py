#!/usr/bin/python3
"""The end of loading's estimate over its last trial increments: what reading it there, instead of at the last row
alone, does to the shipped estimate's bound and alarms and to accuracy on demand (docs/accuracy.md, "The error
estimate"; docs/notes/estimate-companions.md, "The end of loading over its last trial increment").

From the cached runs of studies/estimate_levels.py alone (plan preset and reference; demand), starting none: the
end of loading's load and C/t estimates are taken from the history's row-by-row columns error_load and
error_c_over_t, the largest over the loading's last k trial increments (k 0: the last row's alone, the estimate
before the window; k 1: the shipped one), the other strokes' as the run wrote them (--interior: each over +- k / 2
trial increments of the rows around it too):

    /usr/bin/python3 studies/estimate_end_window.py --tubes al_11.7_mu0.05,... [--demands al_6_mu0.2,...] [--interior]

A demand's file is its last level's; its trial increments are read from its printed levels (the preset's 200 where
none refined them).
"""
import argparse
import json
import os
import re

import h5py
import numpy as np

import estimate_levels as E

TRIALS = {"fast": 100, "default": 200}  # options/preset-*.opts, -increments
WINDOWS = (0, 1, 2)  # trial increments


def end_estimates(h5, trials, k, at=None, a=None):
    """The largest of the loading's error_load and error_c_over_t over its last k trial increments (k 0: its last
    row's); with `at` (an interior stroke) and its attributes' values `a` (load, C/t), over +- k / 2 of them around it."""
    with h5py.File(h5, "r") as h:
        H = h["/history"]
        load = H["stage"][:] == 0
        u, el, ec = H["stroke"][:][load], H["error_load"][:][load], H["error_c_over_t"][:][load]
    w = k * (u[-1] - u[0]) / trials
    if at is not None:
        inside = (np.abs(u - at) <= w / 2 + 1e-12) & (el >= 0)
        return max([a[0]] + list(el[inside])), max([a[1]] + list(ec[inside]))
    inside = (u >= u[-1] - w - 1e-12) & (el >= 0)
    inside[-1] = True
    return el[inside].max(), ec[inside].max()


def interior(h5, trials, k, st, a, on):
    """The interior strokes' load and C/t estimates: as written, or (on) over +- k / 2 trial increments."""
    us = [f"{u:g}" for u in st[:-1]]
    got = [(a[f"error_load_at_{x}"], a[f"error_c_over_t_at_{x}"]) for x in us]
    if on:
        got = [end_estimates(h5, trials, k, u, g) for u, g in zip(st[:-1], got)]
    return [g[0] for g in got], [g[1] for g in got]


def presets(tubes, misses, on):
    print(E.HEAD)
    for k in WINDOWS:
        cells, runs = [], []
        for t in tubes:
            ref = E.reference(t)
            for preset in E.PRESETS:
                h5 = os.path.join(E.OUT, t, E.preset_tag(preset) + ".h5")
                if ref is None or not E.done(h5[:-3]):
                    continue
                st = E.strokes(t)
                P, C, S, _ = E.values(h5, st)
                with h5py.File(h5, "r") as h:
                    a = dict(h["/history"].attrs)
                el, ec = end_estimates(h5, TRIALS[preset], k)
                il, ic = interior(h5, TRIALS[preset], k, st, a, on)
                est = il + [el] + ic + [ec, a["error_unloaded_c_over_t"]]
                got = E.judge(t, preset, st, ref, np.array(P + C + [S]), np.array(est))
                cells, runs = cells + got[0], runs + [got[1]]
        E.table((f"the end over its last {k} trial increment(s)" if k else "the end's last row alone") +
                (", the other strokes over +- k / 2" if on and k else ""), cells, runs, misses)


def demands(tubes, target, on):
    print("\n| tube | final level's trial increments | largest load error | estimate: " +
          " | ".join(f"k {k}" for k in WINDOWS) + " |\n" + "|---" * (3 + len(WINDOWS)) + "|")
    for t in tubes:
        h5 = os.path.join(E.OUT, t, f"demand_{target:g}.h5")
        ref = E.reference(t)
        if ref is None or not os.path.exists(h5):
            print(f"| {t} | no reference or no demand cached | |")
            continue
        with open(h5[:-3] + ".json") as f:
            trials = ([200] + [int(x) for l in json.load(f)["lines"] for x in re.findall(r"(\d+) trial increments", l)])
        st = E.strokes(t)
        P, _, _, _ = E.values(h5, st)
        err = np.abs((np.array(P) - ref["value"][:len(st)]) / ref["value"][:len(st)]).max()
        with h5py.File(h5, "r") as h:
            a = dict(h["/history"].attrs)
        est = [max(interior(h5, trials[-1], k, st, a, on)[0] + [end_estimates(h5, trials[-1], k)[0]]) for k in WINDOWS]
        print(f"| {t} | {trials[-1]} | {100 * err:.2f} % | " + " | ".join(f"{100 * e:.2f} %" for e in est) + " |")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--tubes", required=True)
    ap.add_argument("--demands", default="", help="tubes whose demand_<target>.h5 is cached")
    ap.add_argument("--target", type=float, default=0.005)
    ap.add_argument("--misses", action="store_true")
    ap.add_argument("--interior", action="store_true", help="the reported strokes inside the loading windowed too")
    a = ap.parse_args()
    presets(a.tubes.split(","), a.misses, a.interior)
    if a.demands:
        demands(a.demands.split(","), a.target, a.interior)


if __name__ == "__main__":
    main()
