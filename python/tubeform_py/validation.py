"""The validation set (docs/accuracy.md, "Validation beyond the paper"): its tubes, their materials and
squaring options, and the strokes each is reported at. tools/validate runs it; tools/calculix/converge.py
computes its CalculiX references and studies/estimate_levels.py its error estimate's levels."""
from . import tfruns

# Materials: E, nu, sy0, Ludwik K, n; the sources are given in docs/accuracy.md ("Validation").
MATERIALS = {
    "aluminum": None,  # the paper's Table 1 (-material aluminum)
    "copper": None,    # the paper's Table 1 (-material copper)
    "mild_steel": (210000, 0.30, 350, 500, 0.30),
    "stainless": (193000, 0.29, 260, 1200, 0.60),
    "brass": (105000, 0.35, 150, 700, 0.50),
    # The hold-out tubes' (HOLDOUT, below): a high-strength steel and a titanium alloy, of flow curves none of the
    # tubes above has (a yield stress of 500 and 800 MPa, little hardening).
    "hs_steel": (205000, 0.30, 500, 700, 0.12),
    "titanium": (110000, 0.34, 800, 600, 0.20),
}

# name: material, Ro, t, mu, stroke (mm). R/t 6-40, mu 0-0.35, strokes 3-6 mm.
CASES = {
    "al_11.7_mu0.05": ("aluminum", 17.5, 1.5, 0.05, 4.2),
    "al_37_mu0.05": ("aluminum", 18.5, 0.5, 0.05, 4.2),
    "al_37_mu0.35": ("aluminum", 18.5, 0.5, 0.35, 4.2),
    "al_6_mu0.2": ("aluminum", 15.0, 2.5, 0.20, 3.0),
    "al_40_mu0": ("aluminum", 20.0, 0.5, 0.00, 5.0),
    "cu_29_mu0.2": ("copper", 14.5, 0.5, 0.20, 4.2),
    "cu_8_mu0.1": ("copper", 12.0, 1.5, 0.10, 3.5),
    "steel_10_mu0.1": ("mild_steel", 20.0, 2.0, 0.10, 5.0),
    "steel_6_mu0.1": ("mild_steel", 18.0, 3.0, 0.10, 4.0),
    "steel_20_mu0.35": ("mild_steel", 20.0, 1.0, 0.35, 6.0),
    "stainless_15_mu0.2": ("stainless", 15.0, 1.0, 0.20, 3.0),
    "brass_25_mu0.1": ("brass", 12.5, 0.5, 0.10, 3.0),
    # Two thick walls added after the thick tubes above showed their error through the wall:
    # tubes a rule for the cells through the wall was not fitted to.
    "brass_7_mu0.2": ("brass", 14.0, 2.0, 0.20, 3.5),
    "stainless_9_mu0.05": ("stainless", 18.0, 2.0, 0.05, 4.0),
}
# Hold-out tubes: chosen after the error estimate and accuracy on demand were designed, and run only to check them
# against the method's own converged references (studies/estimate_levels.py; docs/accuracy.md, "Three hold-out tubes").
# No CalculiX reference: tools/validate does not run them.
HOLDOUT = {
    "hs_13_mu0.15": ("hs_steel", 16.0, 1.25, 0.15, 4.0),
    "ti_10_mu0.1": ("titanium", 15.0, 1.5, 0.10, 3.5),
    "al_50_mu0.25": ("aluminum", 20.0, 0.4, 0.25, 5.0),
}
# The strokes a tube is reported at: these below its stroke, and its stroke.
STROKES = tfruns.LOAD_AT


def spec(name):
    """A tube of the validation set or a hold-out one: (material, Ro, t, mu, stroke)."""
    if name not in CASES and name not in HOLDOUT:
        raise KeyError(f"{name}: not a tube of CASES or HOLDOUT (python/tubeform_py/validation.py)")
    return CASES[name] if name in CASES else HOLDOUT[name]


def case_options(name):
    """The tube's squaring run: its options (strings), without a preset."""
    mat, ro, t, mu, stroke = spec(name)
    opts = ["-options_file", "options/squaring.opts", "-tube_ro", ro, "-tube_t", t, "-friction_mu", mu,
            "-stroke", stroke, "-unload", "reverse", "-progress", 0, "-output_every", 100000, "-output_stroke", 0]
    if MATERIALS[mat] is None:
        opts += ["-material", mat]
    else:
        e, nu, sy, k, n = MATERIALS[mat]
        opts += ["-material", "custom", "-material_e", e, "-material_nu", nu, "-material_sy", sy, "-material_k", k,
                 "-material_n", n, "-material_density", 7.85e-9]
    return [str(o) for o in opts]


def reported(name):
    """The strokes the tube is reported at (STROKES below its stroke, then its stroke)."""
    stroke = spec(name)[4]
    return [u for u in STROKES if u < stroke - 1e-9] + [stroke]
