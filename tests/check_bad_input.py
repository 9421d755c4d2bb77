"""Bad input: a one-line error naming the option or file, exit code 1 (main's
collective error: not a crash, which Python reports as a negative code,
mpirun as 128 + N or PETSc's signal handler as exit 59 with "Caught signal",
nor a rank-local abort), no hang (timeout) and no core dump where tubeform
runs (the source directory), on 1 and 2 ranks; and an earlier result
file is left untouched by the failed run. Misspelled options, options
nothing reads (the option likely meant named where there is one; a solver
option of the factorization the run does not use), an option only other
scenes read (naming them: scenes/registry.cpp), values that are not
numbers and material constants not in MPa (E against the law's initial
yield stress, however the material is given) are such errors too
(-allow_unused lets a run go on with an unknown option or one only other scenes read:
checked four times, with the warning, once a die's motion option in a scene without
tools); options PETSc reads only after the check, the E / sigma_y0
bounds themselves and the docs' solver options pass, with PETSc's own
-options_left ("There are no unused options.") as the reference that each
was read. Also the stall watch
(-rmin_stall_increments): error, non-zero exit, results written and flagged. The cases and the text each refusal
must hold: tests/bad_input_cases.py."""
import hashlib
import os
import re
import shutil
import time
from concurrent.futures import ThreadPoolExecutor

import h5py

from bad_input_cases import bad_input_cases
from tfcheck import Checks, allow_core_dumps, args, core_dumps, crashed, out, run


def OptionsReadLater(src):
    """The names of OptionsReadLater, read from src/io/options_left.cpp."""
    text = open(os.path.join(src, "src", "io", "options_left.cpp")).read()
    body = text[text.index("OptionsReadLater()\n{"):]
    body = body[:body.index("return names;")]
    return re.findall(r'"(-[a-z0-9_]+)"', body)

tf, mpirun, src = args()
k = Checks("bad_input")
base = ["-options_file", f"{src}/options/pressure.opts", "-mesh_nt", 2, "-mesh_ntheta", 6, "-increments", 1]
# The same without the pressure scene's own option (-pressure_p), for the cases that name another scene: that scene
# would refuse it as an option only the pressure scene reads (scenes/registry.cpp); the tube's only where the body is
# one (a block's scene refuses them too).
other = ["-options_file", f"{src}/options/solver.opts", "-scene", "pressure", "-material", "aluminum",
         "-material_law", "elastic"] + base[2:]
tube = ["-tube_ro", 20, "-tube_t", 10]
TUBES = ("squaring", "flattening", "pressure", "slide")

# A good run leaves a result we must not lose.
run(tf, mpirun, 1, base + ["-output", out("keep.h5"), "-history_csv", out("keep.csv")])
digest = hashlib.sha256(open("keep.h5", "rb").read()).hexdigest()
# A flat die a millimetre above the tube (the base case's Ro = 20 mm): force control cannot start it.
with open(out("above.profile"), "w") as f:
    f.write("line 0 21 30 21\n")

cases = bad_input_cases(src, out)
with open(out("pa.opts"), "w") as fh:  # a material file in Pa throughout
    fh.write("-material_law swift -material_e 68.9e9 -material_nu 0.33 -material_sy 276e6 -material_k 407.9e6\n"
             "-material_n 0.08 -material_density 2.70e-9\n")
with open(out("sy_pa.opts"), "w") as fh:  # E in MPa, the stresses in Pa
    fh.write("-material_law swift -material_e 68900 -material_nu 0.33 -material_sy 276e6 -material_k 407.9e6\n"
             "-material_n 0.08 -material_density 2.70e-9\n")
with open(out("stray.opts"), "w") as fh:
    fh.write("-material_law ludwik -material_e 1000 -material_nu 0.3 -material_sy 10 -material_k 5 -material_n 0.5\n"
             "-material_density 1e-9\n-tube_t 3\n")
with open(out("incomplete.opts"), "w") as fh:
    fh.write("-material_law swift\n-material_e 1000\n-material_nu 0.3\n-material_sy 10\n-material_density 1e-9\n")
# Every case on 1 rank; on 2 ranks one of each kind (below), since mpirun
# takes ~2 s to wind down a failed job.
# Core files: looked for where tubeform runs, with the core size limit raised
# so that a crash can leave one; where none can appear (cores piped to a
# program), the crash check (exit code and marks) stands for them.
cores, why_none = allow_core_dumps()
print(f"       core dumps looked for in {cores[0]} ({cores[1]}*)" if cores else
      f"       core dumps cannot appear on this machine ({why_none}): the crash check stands for them")
# On 2 ranks one of each kind: option value, option choice, mesh file, output path, material file, a tool's option, a
# die's option of another motion word's kind (refused by the tool scenes' check, not while read).
kinds = (["-tube_t", "-1"], ["-material_law", "bogus"], ["-mesh_file", f"{src}/options/pressure.opts"],
         ["-output", out("keep.csv/out.h5")], ["-material", out("stray.opts")], ["-wall_thickness", "1.65"],
         ["-mat_mumps_icntl_14", "50"], ["-material", out("sy_pa.opts"), "-material_law", "swift"], ["-friction_mu", "0.1"],
         ["-scene", "squaring", "-die_angle", "abc"],
         ["-scene", "squaring", "-lower_die_motion", "mirror", "-lower_die_path", "1,1"])
selected = [c for c in cases if c[0] in kinds]
k.check(len(cases) == 214 and len(selected) == 11, f"{len(cases)} cases on 1 rank (214), {len(selected)} on 2 (11)")


def attempt(np_, extra):
    """Runs a case that must be refused, with the earlier result's paths as its outputs."""
    scene = extra[extra.index("-scene") + 1] if "-scene" in extra else "pressure"
    first = base if scene == "pressure" else other + (tube if scene in TUBES else [])
    return run(tf, mpirun, np_, first + ["-output", out("keep.h5"), "-history_csv", out("keep.csv")] + extra,
               check=False, timeout=60, report_hang=True)


def refused(np_, extra, needle, p):
    """Checks a refused case's run: the exit, the line, and that nothing crashed. The line is tubeform's error where
    it printed one: Open MPI may print a line of its own with "error" in it first (its shared file pointer's mmap
    file, when two cases open files of one name at once)."""
    said = (p.stderr + p.stdout).splitlines()
    lines = [l for l in said if l.startswith("tubeform: error")] or [l for l in said if "error" in l.lower()]
    crash = crashed(p)
    ok = p.returncode == 1 and not crash and len(lines) >= 1 and needle in lines[0]
    k.check(ok, f"np={np_} {' '.join(extra)}: exit {p.returncode}{', CRASH: ' + crash if crash else ''}, "
            f"message: {lines[0] if lines else '(none)'}")


def no_cores(t0, label):
    """No core dump since t0 (the cases run two at a time: a dump is charged to their batch)."""
    if not cores:
        return
    found = core_dumps(cores, t0)
    k.check(not found, f"{label}: no core dump ({', '.join(found) or 'none'})")
    for f in found:  # out of the source tree: the first kept here for a debugger, the others removed
        if os.path.exists(out("core.first")):
            os.remove(f)
        else:
            shutil.move(f, out("core.first"))


# The single-rank cases two at a time (the machine's two cores), the 2-rank ones one after another.
t0 = time.time()
with ThreadPoolExecutor(max_workers=2) as pool:
    done = list(pool.map(lambda c: attempt(1, c[0]), cases))
for (extra, needle), p in zip(cases, done):
    refused(1, extra, needle, p)
no_cores(t0, f"np=1, the {len(cases)} cases")
# The 2-rank cases NP2_AT_ONCE at a time: each is refused in a fraction of a second and then waits in mpirun's
# ~2 s wind-down after a non-zero exit, in which its ranks have exited and use no core (a core dump is charged to
# the batch, as the single-rank cases' are).
NP2_AT_ONCE = 5
typo = [c for c in cases if c[0][0] == "-tube_r"][0]  # (its 2-rank run, checked below, in the same batch)
t0 = time.time()
with ThreadPoolExecutor(max_workers=NP2_AT_ONCE) as pool:
    typo_np2 = pool.submit(run, tf, mpirun, 2, base + ["-output", out("typo.h5")] + typo[0], check=False, timeout=60)
    done = list(pool.map(lambda c: attempt(2, c[0]), selected))
for (extra, needle), p in zip(selected, done):
    refused(2, extra, needle, p)
no_cores(t0, f"np=2, the {len(selected)} cases")
k.check(hashlib.sha256(open("keep.h5", "rb").read()).hexdigest() == digest, "earlier result file unchanged")
k.check(not os.path.exists("keep.h5.partial"), "no .partial file left by a refused run")
p = typo_np2.result()
k.check(p.returncode == 1 and not crashed(p) and typo[1] in p.stderr + p.stdout,
        f"np=2 -tube_r 17: the same error on 2 ranks (exit {p.returncode}) {crashed(p)}")
p = run(tf, mpirun, 1, base + ["-output", out("allow.h5"), "-allow_unused"] + typo[0], check=False, timeout=60)
k.check(p.returncode == 0 and os.path.exists("allow.h5"), f"-allow_unused: the run goes on (exit {p.returncode})")
p = run(tf, mpirun, 1, base + ["-output", out("allow2.h5"), "-allow_unused", "-wall_thickness", "1.65"], check=False,
        timeout=60)
warned = [l for l in p.stdout.splitlines() if l.startswith("tubeform: warning: -wall_thickness 1.65: no scene")]
k.check(p.returncode == 0 and os.path.exists("allow2.h5") and len(warned) == 1,
        f"-allow_unused -wall_thickness 1.65: the run goes on (exit {p.returncode}), warning: {warned}")
p = run(tf, mpirun, 1, base + ["-output", out("allow3.h5"), "-allow_unused", "-target_load", "0.01"], check=False,
        timeout=60)
warned = [l for l in p.stdout.splitlines() if l.startswith("tubeform: warning: -target_load: read by the squaring")]
k.check(p.returncode == 0 and os.path.exists("allow3.h5") and len(warned) == 1,
        f"-allow_unused -target_load 0.01 (a pressure run): the run goes on (exit {p.returncode}), warning: {warned}")
# A die's option of another motion word's kind in a scene without tools: an option only other scenes read, not the
# dies' refusal (that is a press's: CheckMotionStrays).
p = run(tf, mpirun, 1, other + ["-scene", "column", "-output", out("allow4.h5"), "-allow_unused", "-lower_die_path",
                                "1,1"], check=False, timeout=60)
warned = [l for l in p.stdout.splitlines() if l.startswith("tubeform: warning: -lower_die_path: read by the squaring")]
k.check(p.returncode == 0 and os.path.exists("allow4.h5") and len(warned) == 1 and "tubeform: error" not in p.stderr + p.stdout,
        f"-allow_unused -lower_die_path 1,1 (a column run): the run goes on (exit {p.returncode}), warning: {warned}")

# Options that are read must pass: the E / sigma_y0 bounds themselves (python/tubeform_py/extremes.py's two ends); the
# options PETSc reads only after the check (OptionsReadLater in src/io/options_left.cpp: at a solve, when the
# result file opens, at the end), in two runs (the viewer options and the rest do not combine); the solver
# options of the docs and the README on the path each acts on. PETSc's own -options_left, at the end of each
# run, is the reference that every option given was read ("There are no unused options.").
later = ["-ksp_converged_reason", "-redundant_ksp_converged_reason", "-vec_view", "ascii:/dev/null", "-vec_view_stash",
         "-build_twosided", "allreduce", "-options_view", "-log", out("petsc_log"), "-citations", out("citations.txt"),
         "-get_total_flops"]
viewer = ["-viewer_type", "hdf5", "-viewer_view", "ascii:/dev/null", "-viewer_hdf5_base_dimension2", 0,
          "-viewer_hdf5_collective", 0, "-viewer_hdf5_default_timestepping", 0, "-viewer_hdf5_sp_output", 0,
          "-dm_plex_view_hdf5_storage_version", "1.0.0"]
solver = ["-redundant_mat_mumps_icntl_14", 50, "-redundant_mat_mumps_icntl_33", 1, "-redundant_mat_mumps_icntl_4", 1,
          "-redundant_pc_factor_mat_solver_type", "mumps", "-log_view", ":" + out("log_view.txt"), "-malloc_debug",
          "-malloc_dump", "-memory_view", "-ksp_view", "ascii:/dev/null"]
lu = ["-pc_type", "lu", "-pc_factor_mat_solver_type", "mumps", "-mat_mumps_icntl_14", 50, "-mat_mumps_icntl_33", 1]
squaring = ["-options_file", f"{src}/options/squaring.opts", "-stroke", 0.1, "-increments", 5, "-error_estimate", 0,
            "-unload", "none"]
accepted = [(1, base, ["-material_law", "ludwik", "-material_sy", 1500]),
            (1, base, ["-material_law", "ludwik", "-material_sy", 15]), (1, base, later), (1, base, viewer),
            (1, base, solver), (1, base, lu), (2, base, later), (2, base, solver),
            (1, squaring, ["-die_force", 0])]  # (the old spelling of the stroke: -die_force 0, not by force)
# (the single-rank ones two at a time, each its own -output and -history_csv (options/pressure.opts names one for
# all: two runs at once race to rename it into place); then the 2-rank ones one after another)
ones = [(i, b, extra) for i, (np_, b, extra) in enumerate(accepted) if np_ == 1]
with ThreadPoolExecutor(max_workers=2) as pool:
    ran = dict(zip([i for i, _, _ in ones], pool.map(lambda c: run(tf, mpirun, 1, c[1] + [
        "-output", out(f"accepted_{c[0]}.h5"), "-history_csv", out(f"accepted_{c[0]}.csv"), "-options_left"] + c[2],
        check=False, timeout=60), ones)))
for i, (np_, b, extra) in enumerate(accepted):
    p = ran[i] if np_ == 1 else run(tf, mpirun, np_, b + ["-output", out("accepted.h5"), "-options_left"] + extra,
                                     check=False, timeout=60)
    ok = p.returncode == 0 and "There are no unused options." in p.stdout
    lines = (p.stderr + p.stdout).splitlines()
    errors = [l for l in lines if "error" in l.lower()] + [l for l in lines if "Option left" in l]
    k.check(ok, f"np={np_} {' '.join(map(str, extra))}: accepted and every option read by the end (exit "
                f"{p.returncode}{', ' + errors[0] if errors else ''})")
k.check(set(OptionsReadLater(src)) == {o for o in later + viewer if str(o).startswith("-")} | {"-options_left"},
        "the runs above give every option of OptionsReadLater")

# A run that cannot advance (every increment cut to nothing, here by an
# absurd strain limit) stops at the stall watch: a one-line error naming the
# option, a non-zero exit on every rank, and its results up to the stall
# written and flagged (history attribute stalled = 1), nothing left .partial.
# (The stall's runs and those of the second pass's die inside the tube below, on 1 and 2 ranks, side by side: each
# 2-rank one waits in mpirun's ~2 s wind-down after its error exit. Each its own -history_csv: options/pressure.opts
# names one for all.)
with open(out("plate15.profile"), "w") as f:
    f.write("line 0 15 30 15\n")
STALL = base + ["-rmin_deps", "1e-12", "-rmin_stall_increments", "10"]
INSIDE = ["-options_file", f"{src}/options/squaring.opts", "-options_file", f"{src}/options/preset-fast.opts",
          "-mesh_ntheta", 12, "-error_estimate", 0, "-stroke", 1, "-model", "half", "-lower_die_motion", "fixed",
          "-pass2_stroke", 1, "-pass2_die_profile", out("plate15.profile")]
with ThreadPoolExecutor(max_workers=4) as pool:
    ends = {(what, np_): pool.submit(run, tf, mpirun, np_, opts + ["-output", out(f"{what}_np{np_}.h5"),
                                                                   "-history_csv", out(f"{what}_np{np_}.csv")],
                                     check=False, timeout=60)
            for np_ in (1, 2) for what, opts in (("stall", STALL), ("inside", INSIDE))}
for np_ in (1, 2):
    f = out(f"stall_np{np_}.h5")
    p = ends["stall", np_].result()
    lines = [l for l in (p.stderr + p.stdout).splitlines() if "error" in l.lower()]
    crash = crashed(p)
    ok = p.returncode == 1 and not crash and len(lines) >= 1 and "-rmin_stall_increments" in lines[0]
    k.check(ok, f"np={np_} stall: exit {p.returncode}{', CRASH: ' + crash if crash else ''}, "
            f"message: {lines[0] if lines else '(none)'}")
    with h5py.File(f, "r") as h:
        n = len(h["/history"]["stroke"])
        k.check(h["/history"].attrs["stalled"] == 1 and n == 11, f"np={np_} stall: results written and flagged ({n} history rows)")
    k.check(not os.path.exists(f + ".partial"), f"np={np_} stall: no .partial file left")
# A second pass whose fixed die would start inside the tube (a plate at y = -15 mm held in place under the
# paper's Ro = 17.5 mm tube) can only be seen at that pass's start: the run stops there, one line naming the
# die, exit 1 on every rank, the first pass's results written and flagged stopped, nothing left .partial.
for np_ in (1, 2):
    f = out(f"inside_np{np_}.h5")
    p = ends["inside", np_].result()
    lines = [l for l in (p.stderr + p.stdout).splitlines() if "error" in l.lower()]
    crash = crashed(p)
    ok = p.returncode == 1 and not crash and len(lines) == 1 and "pass2-lower-die" in lines[0] and f in lines[0]
    k.check(ok, f"np={np_} a fixed second-pass die inside the tube: exit {p.returncode}"
            f"{', CRASH: ' + crash if crash else ''}, message: {lines[0] if lines else '(none)'}")
    ok = os.path.exists(f) and not os.path.exists(f + ".partial")
    if ok:
        with h5py.File(f, "r") as h:
            stages = set(h["/history/stage"][:].astype(int))
            ok = h["/history"].attrs["stopped"] == 1 and stages == {0, 1}
    k.check(ok, f"np={np_} a fixed second-pass die inside the tube: the first pass's results written, flagged stopped")
k.done()
