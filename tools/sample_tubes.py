#!/usr/bin/python3
"""A robustness sample of a preset on tubes nobody tuned it for: random tubes
(a fixed seed) and four fixed ones, one rank, one run at a time, each run's
answer, estimate, warnings and self-checks in one table.

    /usr/bin/python3 tools/sample_tubes.py [--preset default] [--seed 2026] [--count 16] [--time-limit 240]
                                             [--cases r01,a] [--table] [--against default]

Each random tube is drawn uniformly in R/t 5-60 (Ro 12-25 mm), E 70-210 GPa,
nu 0.28-0.36, E/sigma_y 150-1500, Ludwik K 0.5-4 sigma_y, n 0.1-1, mu 0-0.4
and a stroke from 2 mm to 0.3 Ro. The fixed ones: the mild steel of the validation
set (20/2, mu 0.1 and 0.4), a thin aluminum-like tube (25/0.45, mu 0.2) and
a thick, strongly hardening wall (15/2.8, mu 0.35). Runs are cached in
results/sample/<preset>/ (another --seed: results/sample/<preset>_<seed>/;
delete a case's .log to run it again); the table is
written to results/sample/<preset>/table.md and printed. Wall times are of a
shared machine: compare increments and factorizations.

--against PRESET compares the cached runs with those of a finer preset on the
same tubes (a proxy reference, not an independent one: twice the resolution,
the same method): the load at the end of loading and C/t loaded and after
springback, each difference beside this preset's estimate; an estimate
smaller than its difference is marked, since the finer run's own error would
have to cancel it for the estimate to bound the true error.
"""
import argparse
import os
import random
import re
import subprocess
import sys
import time

# The helper package python/tubeform_py (python/README.md).
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "python"))
from tubeform_py import tfruns  # noqa: E402
from tubeform_py.tubes import draw_tube, options, parse  # noqa: E402

FIXED = {  # name: E, nu, sigma_y, K, n, Ro, t, mu, stroke
    "a": (210000, 0.30, 350, 500, 0.30, 20, 2.0, 0.10, 5.0),
    "b": (210000, 0.30, 350, 500, 0.30, 20, 2.0, 0.40, 5.0),
    "c": (70000, 0.33, 100, 300, 0.40, 25, 0.45, 0.20, 5.0),
    "d": (200000, 0.30, 250, 1000, 0.50, 15, 2.8, 0.35, 3.5),
}
KEYS = ("E", "nu", "sy", "K", "n", "ro", "t", "mu", "stroke")


# Ranges of the random tubes: (R/t, mu, shortest stroke mm, longest stroke / Ro); --wide takes the wider
# ranges (R/t from 4, mu to 0.5, strokes from 1 mm to 0.35 Ro, 1 or 2 ranks).
RANGES = {False: ((5, 60), (0, 0.4), 2, 0.3), True: ((4, 60), (0, 0.5), 1, 0.35)}


DEFAULT_SEED = 2026  # the sample of docs/notes/random-sample.md, cached in results/sample/<preset>/


def draw(seed, count, wide=False):
    """The random tubes, drawn in a fixed order per case (draw_tube; with wide, then the ranks), and the fixed ones
    (not with wide)."""
    rng = random.Random(seed)
    rt, mu, s_lo, s_hi = RANGES[wide]
    cases = {}
    for i in range(count):
        c = draw_tube(rng, rt, mu, (s_lo, s_hi))
        c["np"] = rng.choice((1, 2)) if wide else 1
        cases[f"r{i + 1:02d}"] = c
    if not wide:
        cases.update({k: dict(zip(KEYS, v), np=1) for k, v in FIXED.items()})
    return cases


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--preset", default="default", choices=("fast", "default", "accurate"))
    ap.add_argument("--seed", type=int, default=DEFAULT_SEED)
    ap.add_argument("--count", type=int, default=16)
    ap.add_argument("--time-limit", type=float, default=240, help="each run's -time_limit (s)")
    ap.add_argument("--cases", default="", help="only these (comma-separated names: r01, ..., a, b, c, d)")
    ap.add_argument("--table", action="store_true", help="tabulate what is cached, run nothing")
    ap.add_argument("--wide", action="store_true", help="the wider ranges (R/t 4-60, mu 0-0.5, strokes "
                    "1 mm-0.35 Ro, 1 or 2 ranks), cached apart (results/sample/<preset>_wide_<seed>/)")
    ap.add_argument("--against", choices=("fast", "default", "accurate"),
                    help="compare the cached runs with a finer preset's cached runs (run nothing)")
    a = ap.parse_args()
    cases = draw(a.seed, a.count, a.wide)
    if a.cases:
        unknown = set(a.cases.split(",")) - set(cases)
        if unknown:
            sys.exit(f"tools/sample_tubes.py: --cases: unknown {sorted(unknown)}; known: {', '.join(cases)}")
        cases = {k: v for k, v in cases.items() if k in a.cases.split(",")}
    def cache(preset):
        # (a draw of its own per seed: another seed's runs under the same case names are other tubes)
        own = f"_wide_{a.seed}" if a.wide else (f"_{a.seed}" if a.seed != DEFAULT_SEED else "")
        return os.path.join(tfruns.root, "results", "sample", preset + own)

    out = cache(a.preset)
    if a.against:
        return compare(cases, out, cache(a.against), a.preset, a.against)
    os.makedirs(out, exist_ok=True)
    head = ("| case | R/t | E/sy | n | mu | stroke | exit | wall s | increments | factorizations | load N/mm | C/t "
            "loaded | after springback | estimate: load %, C/t | warns | energy % | internal work % | unsettled | "
            "inconsistent | past an event |")
    lines = [head, "|" + "---|" * (head.count(" | ") + 1)]
    for name, c in cases.items():
        log_path = os.path.join(out, f"{name}.log")
        if not a.table and not os.path.exists(log_path):
            cmd = ["mpirun", "-n", str(c["np"]), tfruns.EXE] + options(c, a.preset, os.path.join(out, f"{name}.h5"),
                                                              a.time_limit)
            t0 = time.time()
            p = subprocess.run(cmd, cwd=tfruns.root, env=tfruns.env, capture_output=True, text=True)
            with open(log_path, "w") as f:
                f.write(" ".join(cmd) + "\n" + p.stdout + p.stderr +
                        f"\nexit {p.returncode} wall {time.time() - t0:.1f}\n")
        if not os.path.exists(log_path):
            continue
        log = open(log_path).read()
        r = parse(log)
        end = re.search(r"exit (-?\d+) wall (\S+)", log)
        label = name + (" (2 ranks)" if c["np"] == 2 else "")
        lines.append(f"| {label} | {c['ro'] / c['t']:.1f} | {c['E'] / c['sy']:.0f} | {c['n']:.2f} | {c['mu']:.2f} | "
                     f"{c['stroke']:.2f} | {end.group(1)} | {end.group(2)} | {r['increments']} | "
                     f"{r['factorizations']} | {r['load']} | {r['ct']} | {r['ct_back']} | {r['est_load']}, "
                     f"{r['est_ct']} | {r['warns']} | {r['energy']} | {r['internal']} | {r['unsettled']} | "
                     f"{r['inconsistent']} | {r['past']}{' ' + r['error'] if r['error'] else ''} |")
        print(lines[-1], flush=True)
    with open(os.path.join(out, "table.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines[:2]))


def verdict(ok_load, ok_ct):
    """'yes' when both estimates are at least their differences, else which one is not."""
    if ok_load and ok_ct:
        return "yes"
    return f"load {'yes' if ok_load else 'NO'}, C/t {'yes' if ok_ct else 'NO'}"


def compare(cases, out, ref_dir, preset, against):
    """The table of --against: this preset's answer against the finer preset's, beside this preset's estimate."""
    head = (f"| case | R/t | mu | load: {preset} N/mm | {against} | difference % | estimate % | C/t loaded: "
            f"difference | after springback | estimate | estimates at least the differences |")
    lines = [head, "|" + "---|" * (head.count(" | ") + 1)]
    counts = {"cases": 0, "load": 0, "ct": 0}
    for name, c in cases.items():
        paths = [os.path.join(d, f"{name}.log") for d in (out, ref_dir)]
        if not all(os.path.exists(p) for p in paths):
            continue
        r, f = (parse(open(p).read()) for p in paths)
        if not all(x[k] for x in (r, f) for k in ("load", "ct", "ct_back", "est_load", "est_ct")):
            cells = [name, f"{c['ro'] / c['t']:.1f}", f"{c['mu']:.2f}", "not finished on both"]
            lines.append("| " + " | ".join(cells + [""] * (head.count(" | ") + 1 - len(cells))) + " |")
            continue
        dp = abs(float(r["load"]) / float(f["load"]) - 1) * 100
        dc, db = abs(float(r["ct"]) - float(f["ct"])), abs(float(r["ct_back"]) - float(f["ct_back"]))
        ok_p, ok_c = float(r["est_load"]) >= dp, float(r["est_ct"]) >= max(dc, db)
        counts["cases"] += 1
        counts["load"] += ok_p
        counts["ct"] += ok_c
        lines.append(f"| {name} | {c['ro'] / c['t']:.1f} | {c['mu']:.2f} | {r['load']} | {f['load']} | {dp:.2f} | "
                     f"{r['est_load']} | {dc:.4f} | {db:.4f} | {r['est_ct']} | "
                     f"{verdict(ok_p, ok_c)} |")
    print("\n".join(lines))
    print(f"estimates at least the differences: load on {counts['load']} of {counts['cases']} tubes, "
          f"C/t on {counts['ct']} of {counts['cases']}")


if __name__ == "__main__":
    main()
