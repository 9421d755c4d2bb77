"""A tube drawn at random and its squaring run: the tube (draw_tube), the run's options (options) and what the
run's last lines say (parse). tools/sample_tubes.py and the soak (soaklib, tools/soak) draw their tubes here."""
import re


def draw_tube(rng, rt, mu, stroke, esy=(150, 1500), n=(0.1, 1)):
    """One random tube from rng, its numbers drawn in a fixed order (R/t, Ro, E, nu, E/sy, K/sy, n, mu, stroke):
    R/t, mu, E/sy and n uniform in their (low, high), Ro in 12-25 mm, E in 70-210 GPa, nu in 0.28-0.36, the Ludwik
    K in 0.5-4 sigma_y, the stroke uniform from stroke[0] mm to stroke[1] x Ro. The soak (soaklib) draws its
    tubes here."""
    r, ro = rng.uniform(*rt), rng.uniform(12, 25)
    e, nu, esy_, kf, n_, mu_ = (rng.uniform(70000, 210000), rng.uniform(0.28, 0.36), rng.uniform(*esy),
                                rng.uniform(0.5, 4), rng.uniform(*n), rng.uniform(*mu))
    s = rng.uniform(stroke[0], stroke[1] * ro)
    return dict(E=e, nu=nu, sy=e / esy_, K=kf * e / esy_, n=n_, ro=ro, t=ro / r, mu=mu_, stroke=s)


def options(c, preset, out, time_limit):
    """The run's options: the squaring case, the preset, the tube c (its "law", if it names one, as
    -material_law), the time limit and the output."""
    law = ["-material_law", c["law"]] if "law" in c else []
    o = (["-options_file", "options/squaring.opts", "-options_file", f"options/preset-{preset}.opts", "-material",
          "custom"] + law +
         ["-material_e", c["E"], "-material_nu", c["nu"], "-material_sy", c["sy"], "-material_k", c["K"], "-material_n",
          c["n"], "-tube_ro", c["ro"], "-tube_t", c["t"], "-friction_mu", c["mu"], "-stroke", c["stroke"],
          "-time_limit", time_limit, "-output", out])
    return [f"{x:.6g}" if isinstance(x, float) else str(x) for x in o]


def parse(log):
    """What the run's last lines say (tubeform's answer, estimate, self-checks)."""
    def num(pattern):
        m = re.search(pattern, log)
        return m.group(1) if m else ""
    errors = [l for l in log.splitlines() if l.startswith("tubeform: error")]
    return {
        "cells": num(r"mesh (\d+ cells \([^)]*\), \w+)"), "increments": num(r"done, (\d+) increments"),
        "factorizations": num(r"increments, (\d+) factorizations"),
        "load": num(r"load at the end of loading \(U = [^)]*\) (\S+) N/mm"),
        "ct": num(r"tubeform: loaded: C/t (\S+),"), "ct_back": num(r"tubeform: after springback \([^)]*\): C/t (\S+),"),
        "est_load": num(r"estimated error.*?: load (\S+) %"), "est_ct": num(r"estimated error.*?, C/t (\S+)"),
        "warns": "yes" if "estimated error passes" in log else "no",
        "energy": num(r"energy balance within (\S+) %"), "internal": num(r"internal work within (\S+) %"),
        "past": num(r"compromises: (\d+) steps past"), "unsettled": num(r"(\d+) unsettled"),
        "inconsistent": num(r"(\d+) with inconsistent"),
        "error": errors[0][len("tubeform: error: "):] if errors else "",
    }
