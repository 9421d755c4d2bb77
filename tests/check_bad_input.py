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
(-allow_unused lets a run go on with an unknown option: checked twice, with
the warning); options PETSc reads only after the check, the E / sigma_y0
bounds themselves and the docs' solver options pass, with PETSc's own
-options_left ("There are no unused options.") as the reference that each
was read. Also the stall watch
(-rmin_stall_increments): error, non-zero exit, results written and flagged."""
import hashlib
import os
import re
import shutil
import time
from concurrent.futures import ThreadPoolExecutor

import h5py

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
# would refuse it as an option only the pressure scene reads (scenes/registry.cpp).
other = ["-options_file", f"{src}/options/solver.opts", "-scene", "pressure", "-tube_ro", 20, "-tube_t", 10,
         "-material", "aluminum", "-material_law", "elastic"] + base[2:]

# A good run leaves a result we must not lose.
run(tf, mpirun, 1, base + ["-output", out("keep.h5"), "-history_csv", out("keep.csv")])
digest = hashlib.sha256(open("keep.h5", "rb").read()).hexdigest()
# A flat die a millimetre above the tube (the base case's Ro = 20 mm): force control cannot start it.
with open(out("above.profile"), "w") as f:
    f.write("line 0 21 30 21\n")

cases = [
    (["-tube_t", "-1"], "-tube_t"),
    (["-tube_t", "30"], "-tube_t"),
    (["-mesh_nt", "0"], "-mesh_nt"),
    (["-mesh_nt", "0", "-mesh_wall_strain", "0.02", "-mesh_nt_min", "0"], "-mesh_nt_min"),
    (["-mesh_nt", "0", "-mesh_wall_strain", "2"], "-mesh_wall_strain"),
    (["-element", "auto", "-element_bar_nt", "0"], "-element_bar_nt"),
    (["-element", "qm7"], "-element"),
    (["-material_nu", "0.5"], "-material_nu"),
    (["-material_law", "bogus"], "-material_law"),
    (["-scene", "nonsense"], "-scene"),
    (["-increments", "0"], "-increments"),
    (["-rmin_stall_increments", "5"], "-rmin_stall_increments"),
    (["-dynamics", "explicit"], "-dynamics"),
    (["-factorization", "lu"], "-factorization"),
    (["-plastic_update", "implicit"], "-plastic_update"),
    (["-plastic_update", "radial", "-material_law", "ludwik", "-hardening", "chaboche", "-material_kinematic",
      "20000,200"],
     "-plastic_update radial: isotropic J2 only"),
    (["-error_estimate_factorization", "petsc"], "-error_estimate_factorization"),
    (["-punch_speed", "0"], "-punch_speed"),
    (["-dynamics_time", "-1"], "-dynamics_time"),
    (["-material_density", "0"], "-material_density"),
    (["-mesh_file", "no/such/mesh.msh"], "no/such/mesh.msh"),
    (["-mesh_file", f"{src}/options/pressure.opts"], "pressure.opts"),
    (["-output", out("keep.csv/out.h5")], "-output"),          # parent is a file
    (["-history_csv", out("keep.csv/h.csv")], "-history_csv"),
    (["-rmin_event_tol", "0"], "-rmin_event_tol"),
    (["-rmin_dphi", "3"], "-rmin_dphi"),
    # A scene's own refusals, in its scene (another scene refuses the option as not its own before its value).
    (["-scene", "slide", "-slide_back", "-1"], "-slide_back -1.: must be a non-negative distance"),
    (["-scene", "bending", "-bending_strain", "0"], "-bending_strain 0.: must be non-zero"),
    (["-die_angle", "40"], "-die_angle"),
    # The V-die's own refusals (its shape kind's reader and checker, tool/shape_v.cpp), under the upper die's prefix.
    (["-scene", "squaring", "-die_angle", "abc"], "-die_angle abc: not a number"),
    (["-scene", "squaring", "-die_r_apex", "20"], "-die_r_apex 20.: must lie in [0, -tube_ro)"),  # (Ro = 20 mm)
    (["-scene", "squaring", "-die_u_close", "-1"], "-die_u_close -1., -die_r_edge 0.: must be non-negative"),
    (["-friction_mu", "0.1"], "-friction_mu: read by the squaring, flattening and slide scenes, not by this run's "
     "pressure scene"),
    (["-scene", "squaring", "-pressure_u", "0.1"], "-pressure_u: read by the pressure scene, not by this run's "
     "squaring scene"),
    (["-scene", "flattening", "-die_angle", "80"], "-die_angle: read by the squaring scene"),
    (["-scene", "squaring", "-model", "quarter", "-lower_die", "flat"], "-model quarter"),
    (["-scene", "squaring", "-lower_die", "flat", "-unload", "withdraw"], "-unload withdraw"),
    (["-scene", "squaring", "-lower_die", "no/such/die.profile"], "-lower_die no/such/die.profile"),
    # (none is the side dies' word, not the lower die's: a file of that name)
    (["-scene", "squaring", "-lower_die", "none"], "-lower_die none: cannot read the file"),
    (["-lower_die_motion", "up"], "-lower_die_motion"),
    (["-springback", "plastic"], "-springback"),
    (["-scene", "squaring", "-pass2_stroke", "2", "-unload", "none"], "give -unload reverse or withdraw"),
    (["-scene", "squaring", "-pass2_stroke", "2", "-pass2_unload", "none", "-pass3_stroke", "3"],
     "give -pass2_unload reverse or withdraw"),
    (["-scene", "squaring", "-pass2_stroke", "2", "-pass2_unload", "out"], "-pass2_unload"),
    (["-scene", "squaring", "-pass2_unload", "none"], "give -pass2_stroke"),
    (["-scene", "squaring", "-pass2_stroke", "2", "-pass2_unload", "withdraw", "-pass2_lower_die", "flat"],
     "-pass2_unload withdraw: not with the half model"),
    (["-scene", "squaring", "-side_die", "flat", "-pass2_stroke", "2", "-pass2_unload", "withdraw"],
     "-side_die flat: side dies are not withdrawn (-pass2_unload withdraw)"),
    (["-scene", "squaring", "-pass2_stroke", "2", "-pass2_lower_die_motion", "path"], "-pass2_lower_die_motion"),
    (["-scene", "column", "-unload", "withdraw"], "-unload: read by the squaring and flattening scenes"),
    (["-scene", "squaring", "-lower_die_motion", "path", "-lower_die_path", "1,0,2,1", "-pass2_stroke", "2"],
     "give the second pass's, -pass2_lower_die_motion"),
    (["-scene", "tension", "-springback", "elastic"], "-springback: read by the squaring, flattening and bending"),
    (["-scene", "flattening", "-stroke_corner_radius", "3"], "-stroke_corner_radius: read by the squaring scene"),
    (["-scene", "squaring", "-pass2_lower_die_motion", "fixed"], "-pass2_lower_die_motion, -pass2_side_die"),
    (["-scene", "squaring", "-model", "quarter", "-pass2_stroke", "2", "-pass2_lower_die_motion", "fixed"],
     "in every pass"),
    (["-scene", "squaring", "-pass2_lower_die", "flat"], "give -pass2_stroke"),
    (["-lower_die", "flat"], "presses with no dies"),  # the base case is the pressure scene
    (["-scene", "squaring", "-pass2_stroke", "9"], "-pass2_stroke 9"),  # past the closed cavity
    (["-scene", "squaring", "-model", "half", "-mesh_file", f"{src}/meshes/thick_cylinder_4x8.msh"],
     "does not reach below the x axis"),
    (["-scene", "squaring", "-die_force", "-5"], "-die_force -5"),
    (["-die_force", "100"], "presses with no dies"),
    (["-scene", "squaring", "-die_force", "100", "-model", "half"], "-lower_die_motion fixed"),
    (["-scene", "squaring", "-die_force", "100", "-pass2_stroke", "2", "-unload", "none"], "follows the first pass's release"),
    (["-scene", "squaring", "-pass2_stroke", "2", "-pass2_turn", "400"], "the tube turns by -360 to 360 degrees"),
    (["-scene", "squaring", "-pass2_stroke", "2", "-pass2_turn", "45", "-model", "half"], "needs the full model"),
    (["-scene", "squaring", "-pass2_stroke", "2", "-pass2_turn", "45", "-full_hold", "pins"], "needs the full model"),
    (["-scene", "squaring", "-pass2_turn", "90"], "give -pass2_stroke"),
    (["-scene", "squaring", "-pass2_stroke", "2", "-pass2_turn", "90", "-model", "half"], "use -model full"),
    (["-scene", "squaring", "-pass2_stroke", "2", "-pass2_turn", "90", "-lower_die", "flat", "-full_hold", "pins"],
     "off that axis"),
    (["-scene", "squaring", "-side_die", "flat", "-die_force", "100"], "side dies are not with -die_force"),
    (["-scene", "squaring", "-side_die", "flat", "-pass2_stroke", "2", "-pass2_die_motion", "force",
      "-pass2_die_force", "100"], "side dies are not with -pass2_die_force in their pass"),
    (["-scene", "squaring", "-lower_die_motion", "fixed", "-pass2_side_die", "flat", "-pass2_die_path", "0,-3"],
     "-pass2_die_path: not with side dies in its pass"),
    (["-scene", "squaring", "-pass2_side_die", "flat"], "give -pass2_stroke"),
    (["-scene", "squaring", "-side_force", "20"], "need the pass's side dies, -side_die"),
    (["-scene", "squaring", "-side_die", "flat", "-side_force", "-1"], "-side_force -1"),
    (["-scene", "squaring", "-pass2_stroke", "2", "-pass2_side_force", "20"], "dies, -pass2_side_die (or -side_die)"),
    (["-scene", "squaring", "-side_die", "flat", "-side_force", "20", "-die_offset", "0.5"],
     "side dies pressing by a force in the first pass, whose two sides"),
    (["-scene", "squaring", "-lower_die", "flat", "-pass2_stroke", "2", "-pass2_side_die", "flat", "-pass2_turn", "90",
      "-pass2_side_force", "20"], "side dies pressing by a force in the second pass, whose two sides of the tube differ"),
    (["-scene", "squaring", "-pass2_stroke", "2", "-pass2_side_die", "flat", "-pass2_side_force", "-3"], "-3"),
    (["-scene", "squaring", "-pass2_side_force", "20"], "-pass2_side_force, -pass2_unload: give -pass2_stroke"),
    (["-scene", "squaring", "-side_die", "flat", "-pass2_stroke", "2", "-pass2_side_force", "20", "-pass2_turn", "45"],
     "the second pass is held by the rotation hold"),
    (["-scene", "squaring", "-die_offset", "0.5", "-model", "half"], "-die_offset 0.5: a die off the axis"),
    (["-scene", "squaring", "-die_offset", "nan"], "-die_offset nan"),
    (["-scene", "squaring", "-die_offset", "0.5", "-full_hold", "pins"], "with -full_hold pins"),
    (["-scene", "squaring", "-full_hold", "rotation"], "-full_hold rotation: only the full model"),
    (["-scene", "squaring", "-full_hold", "roll"], "-full_hold"),
    (["-scene", "squaring", "-die_offset", "0.5", "-die_force", "100", "-lower_die_motion", "fixed"],
     "-die_force 100.: the first pass is held by the rotation hold"),
    (["-scene", "squaring", "-lower_die_motion", "fixed", "-pass2_turn", "45", "-pass2_die_force", "100"],
     "-pass2_die_force 100.: the second pass is held by the rotation hold"),
    (["-scene", "tension", "-die_offset", "0.5"], "presses with no dies"),
    (["-scene", "flattening", "-die_offset", "0.5"], "-die_offset 0.5: the squaring scene's die"),
    (["-scene", "squaring", "-pass2_die_offset", "0.5"], "-pass2_die_offset, -pass2_side_force, -pass2_unload: give"),
    (["-scene", "squaring", "-pass2_stroke", "2", "-pass2_die_offset", "inf"], "-pass2_die_offset inf"),
    (["-scene", "squaring", "-pass2_stroke", "2", "-pass2_die_offset", "0.5", "-model", "half"], "0.5: a die off"),
    (["-scene", "squaring", "-pass2_stroke", "2", "-pass2_die_offset", "0.5", "-full_hold", "pins"], "with -full_hold pins"),
    (["-scene", "squaring", "-pass2_stroke", "2", "-pass3_stroke", "2", "-pass3_die_offset", "0.5", "-model",
      "quarter"], "-pass3_die_offset 0.5: a die off the axis"),
    (["-scene", "flattening", "-pass2_stroke", "2", "-pass2_die_offset", "0.5"], "-pass2_die_offset 0.5: the squaring"),
    (["-scene", "squaring", "-lower_die_motion", "fixed", "-pass2_die_motion", "path", "-pass2_die_path", "0,-1",
      "-pass2_die_offset", "0.5"], "-pass2_die_path: not with -pass2_die_offset"),
    (["-scene", "squaring", "-die_path", "0,-1,0.5"], "-die_path: the squaring scene's upper die through x,y pairs"),
    (["-scene", "flattening", "-die_path", "0,-1"], "-die_path: the squaring scene's upper die"),
    (["-scene", "squaring", "-lower_die_motion", "fixed", "-die_path", "0,0"], "other than the one before it"),
    (["-scene", "squaring", "-lower_die_motion", "fixed", "-die_path", "0,nan"], "each point must be a pair"),
    (["-scene", "squaring", "-lower_die_motion", "fixed", "-die_path", "0,-1,0.5,1"], "the last point's y 1"),
    (["-scene", "squaring", "-die_path", "0,-1"], "give -lower_die_motion fixed"),
    (["-scene", "squaring", "-lower_die_motion", "fixed", "-die_path", "0,-1", "-stroke_path", "1,2"],
     "-die_path: in place of -stroke"),
    (["-scene", "squaring", "-lower_die_motion", "fixed", "-die_path", "0,-1", "-die_offset", "0.5"],
     "a path sideways is its own offset"),
    (["-scene", "squaring", "-lower_die_motion", "fixed", "-die_path", "0.5,-1", "-model", "half"],
     "-die_path: a die off the axis"),
    (["-scene", "squaring", "-lower_die_motion", "fixed", "-die_path", "0.5,-1", "-full_hold", "pins"],
     "-die_path with -full_hold pins"),
    (["-scene", "squaring", "-lower_die_motion", "fixed", "-die_path", "0,-1,0,-2", "-die_path_turn", "5"],
     "-die_path_turn: 1 angles for 2 -die_path points"),
    (["-scene", "squaring", "-lower_die_motion", "fixed", "-die_path", "0,-1", "-die_path_turn", "100"],
     "each turn must be a number of degrees within"),
    (["-scene", "squaring", "-lower_die_motion", "fixed", "-die_path", "0,-1,0,-1", "-die_path_turn", "2,2"],
     "or turned otherwise (-die_path_turn)"),
    (["-scene", "squaring", "-die_pivot", "0,20"], "-die_path_turn and -die_pivot: the turns along a -die_path"),
    (["-scene", "squaring", "-lower_die_motion", "fixed", "-die_path", "0,-1", "-die_pivot", "1"],
     "-die_pivot: one point x,y"),
    (["-scene", "squaring", "-lower_die_motion", "fixed", "-die_path", "0,-1", "-die_path_turn", "3", "-model",
      "half"], "-die_path_turn: a die off the axis"),
    (["-scene", "squaring", "-lower_die_motion", "fixed", "-die_path", "0,-1", "-die_pivot", "0,20"],
     "-die_pivot: the point the die turns about; give its turns"),
    # The upper die's motion (-die_motion): a word it takes, and only the options of the kind chosen (the old
    # spellings: -die_path means path, -die_force other than 0 force).
    (["-scene", "squaring", "-die_motion", "spiral"], "Unknown option spiral for -die_motion"),
    (["-scene", "squaring", "-die_motion", "force", "-die_force", "100", "-die_path", "0,-1"],
     "-die_path: an option of -die_motion path, not of -die_motion force"),
    (["-scene", "squaring", "-lower_die_motion", "fixed", "-die_path", "0,-1", "-die_force", "100"],
     "-die_force: an option of -die_motion force, not of -die_motion path"),
    (["-scene", "squaring", "-die_motion", "stroke", "-die_pivot", "0,1"],
     "-die_pivot: an option of -die_motion path, not of -die_motion stroke"),
    (["-scene", "squaring", "-die_motion", "force"], "-die_force: give the force"),
    (["-scene", "squaring", "-die_motion", "path"], "-die_path: the points of -die_motion path"),
    (["-scene", "flattening", "-model", "full", "-full_hold", "rotation"], "plates do not hold"),
    (["-scene", "squaring", "-pass2_stroke", "2", "-pass2_side_die", out("none.profile")],
     f"-pass2_side_die {out('none.profile')}: cannot read"),
    (["-scene", "squaring", "-side_die", out("none.profile")], "-side_die"),
    (["-scene", "tension", "-side_die", "flat"], "presses with no dies"),
    (["-scene", "squaring", "-stroke_path", "3,-1,4"], "-stroke_path: -1"),
    (["-scene", "squaring", "-stroke_path", "3,3,4"], "other than the one before"),
    (["-scene", "squaring", "-stroke_path", "3,0"], "must be positive"),
    (["-scene", "squaring", "-stroke_path", "3,4", "-die_force", "10"], "-stroke_path: not with -die_force"),
    (["-scene", "column", "-stroke_path", "1,2"], "-stroke_path: the column scene"),
    (["-scene", "squaring", "-die_force", "100", "-unload", "withdraw"], "-unload withdraw moves the die back"),
    (["-scene", "squaring", "-die_force", "100", "-stroke_corner_radius", "4"], "-stroke_corner_radius"),
    (["-scene", "squaring", "-die_force", "100", "-die_profile", out("above.profile")],
     "touches no node of the body at its start"),
    (["-scene", "bending", "-mesh_nt", "3"], "needs an even number of elements"),
    (["-rmin_yield", "bogus"], "-rmin_yield"),
    (["-rmin_yield_tol", "0"], "-rmin_yield_tol"),
    (["-rmin_dphi_rise", "1.5"], "-rmin_dphi_rise"),
    (["-output_stroke", "-0.1"], "-output_stroke"),
    (["-checkpoint_every", "-1", "-checkpoint", out("ck_bad.h5")], "-checkpoint_every"),
    (["-checkpoint_every", "5"], "needs -checkpoint"),
    (["-checkpoint", out("keep.csv/ck.h5")], "-checkpoint"),  # parent is a file
    (["-friction_max_unsettled", "0"], "-friction_max_unsettled"),
    (["-output_stroke", "10"], "-output_stroke"),
    (["-unload_increments", "-1"], "-unload_increments"),
    (["-time_limit", "-1"], "-time_limit"),
    (["-progress", "-1"], "-progress"),
    # Misspelled options name the nearest known one and the options it is listed with by -help; numbers that
    # are not numbers name the option.
    (["-tube_r", "17"], "-tube_r: unknown option; did you mean -tube_ro, one of the scene and geometry options?"),
    (["-frction_mu", "0.3"], "did you mean -friction_mu, one of the contact and friction options?"),
    (["-rmin_depps", "0.001"], "did you mean -rmin_deps, one of the incremental driver (r_min method) options?"),
    (["-scene", "squaring", "-die_anglee", "80"], "did you mean -die_angle, one of the upper die shape options?"),
    (["-scene", "squaring", "-die_pth", "0,-1"], "did you mean -die_path, one of the upper die motion options?"),
    (["-scene", "squaring", "-lower_die_pth", "1,1"], "did you mean -lower_die_path, one of the lower die motion options?"),
    (["-scene", "squaring", "-pass3_strok", "2"], "did you mean -pass3_stroke, one of the tube model and passes options?"),
    (["-tube_ro", "abc"], "-tube_ro abc: not a number"),
    (["-mesh_nt", "4.5"], "-mesh_nt 4.5: not a whole number"),
    # A die built for a 15 mm tube around a mesh of radius 20: it would start 5 mm inside.
    (["-scene", "squaring", "-mesh_file", f"{src}/meshes/thick_cylinder_4x8.msh", "-tube_ro", "15", "-tube_t", "5"],
     "the V-die starts inside the body: node"),
    (["-max_energy_error", "0"], "-max_energy_error"),
    (["-rmin_deps_yield", "-1"], "-rmin_deps_yield"),
    # The material library (options/materials): an unknown name lists the library; a material file that is
    # missing, sets an option that is no material constant, or leaves one out names the file and the option.
    (["-material", "steel"], "-material steel: not in the material library"),
    (["-material", out("no_such_material.opts")], "no_such_material.opts: no such file"),
    (["-material", out("stray.opts")], "-tube_t is not a constant"),
    (["-material", out("incomplete.opts")], "does not set -material_k"),
    # Kinematic hardening without backstresses, or with backstresses that outgrow the flow curve.
    (["-hardening", "chaboche", "-material_law", "ludwik"], "-hardening chaboche needs -material_kinematic"),
    (["-hardening", "chaboche", "-material_law", "ludwik", "-material_kinematic", "1e6,0"],
     "-material_kinematic: the backstresses outgrow the flow curve"),
    # Hill's yield: r-values that are not positive, both forms at once.
    (["-material_r", "1.5,1,-1"], "r-values must be positive"),
    (["-material_r", "1.5,1,0.7", "-material_hill", "0.5,0.5,0.5,1.5"], "-material_r and -material_hill"),
    # Options nothing reads, judged once the mesh and the solver are set up (a stand-in factored, so that MUMPS
    # has read its options), before anything is written: the likely option named where there is one; a solver
    # option of the factorization the run does not use names the one it does.
    (["-wall_thickness", "1.65"],
     "-wall_thickness 1.65: no scene, tool or PETSc object of this run reads it; did you mean -tube_t, one of the "
     "scene and geometry options?"),
    (["-ksp_veiw"], "-ksp_veiw: no scene, tool or PETSc object of this run reads it; did you mean -ksp_view?"),
    (["-foo_bar", "2"], "-foo_bar 2: no scene, tool or PETSc object of this run reads it (build/tubeform -help"),
    (["-redundant_mat_mumps_icntl_999", "1"], "-redundant_mat_mumps_icntl_999 1: no scene, tool or PETSc object"),
    (["-ksp_view_pre"], "-ksp_view_pre: no scene, tool or PETSc object"),  # PETSc 3.18's KSPSetUp reads it not
    (["-mat_mumps_icntl_14", "50"], "-mat_mumps_icntl_14 50: acts only on the distributed factorization"),
    (["-pc_factor_mat_solver_type", "petsc"], "give -redundant_pc_factor_mat_solver_type"),
    # Material constants not in MPa (t/mm^3), however given: the options, a file, the library, a table, Hill,
    # backstresses. E against the law's initial yield stress: 50 to 5000 (the bounds themselves pass: below).
    (["-material_e", "68.9e9"], "-material_e 6.89e+10: stiffer than any solid"),  # Pa, elastic law
    (["-material_law", "ludwik", "-material_e", "68.9e9"],
     "-material_e 6.89e+10 against the initial yield stress 165.3 MPa (-material_sy, -material aluminum): E / "
     "sigma_y0 = 4.168e+08 lies outside 50 to 5000"),  # Pa, the paper's aluminum
    (["-material_law", "ludwik", "-material_e", "69"],
     "-material_e 69 against the initial yield stress 165.3 MPa (-material_sy, -material aluminum)"),  # GPa
    (["-material_law", "ludwik", "-material_sy", "165.3e6"], "E / sigma_y0 = 0.0004537 lies outside 50 to 5000"),
    (["-material_law", "ludwik", "-material_sy", "1501"], "E / sigma_y0 = 49.97 lies outside 50 to 5000"),
    (["-material_law", "ludwik", "-material_sy", "14.99"], "E / sigma_y0 = 5003 lies outside 50 to 5000"),
    (["-material", "dc04", "-material_law", "swift", "-material_e", "210"], "(-material_sy, -material dc04)"),
    (["-material_law", "table", "-material_table", "0,200e6,0.1,300e6"], "(the first stress of -material_table"),
    (["-material", "s355_cyclic", "-material_law", "table", "-hardening", "chaboche", "-material_e", "197.41"],
     "the initial yield stress 338.8 MPa (the first stress of -material_table, -material s355_cyclic)"),
    (["-material_law", "ludwik", "-material_hill", "500,500,500,1500"],
     "(-material_sy, -material_hill, -material aluminum, in tension along the tube)"),
    (["-material_law", "ludwik", "-material_k", "673.5e6"], "-material_k 6.735e+08: the flow stress at a plastic"),
    (["-material_density", "2700"], "-material_density 2700: outside 1e-10 to 2e-07 t/mm^3"),
    (["-material", out("pa.opts"), "-material_law", "swift"], "-material_e 6.89e+10: stiffer than any solid"),
    (["-material", out("sy_pa.opts"), "-material_law", "swift"], f"-material {out('sy_pa.opts')})"),
]
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
# On 2 ranks one of each kind: option value, option choice, mesh file, output path, material file, a tool's option.
kinds = (["-tube_t", "-1"], ["-material_law", "bogus"], ["-mesh_file", f"{src}/options/pressure.opts"],
         ["-output", out("keep.csv/out.h5")], ["-material", out("stray.opts")], ["-wall_thickness", "1.65"],
         ["-mat_mumps_icntl_14", "50"], ["-material", out("sy_pa.opts"), "-material_law", "swift"], ["-friction_mu", "0.1"],
         ["-scene", "squaring", "-die_angle", "abc"])
selected = [c for c in cases if c[0] in kinds]
k.check(len(cases) == 185 and len(selected) == 10, f"{len(cases)} cases on 1 rank (185), {len(selected)} on 2 (10)")


def attempt(np_, extra):
    """Runs a case that must be refused, with the earlier result's paths as its outputs."""
    scene = extra[extra.index("-scene") + 1] if "-scene" in extra else "pressure"
    return run(tf, mpirun, np_, (base if scene == "pressure" else other) + ["-output", out("keep.h5"), "-history_csv",
                                                                             out("keep.csv")] + extra,
               check=False, timeout=60, report_hang=True)


def refused(np_, extra, needle, p):
    """Checks a refused case's run: the exit, the line, and that nothing crashed."""
    lines = [l for l in (p.stderr + p.stdout).splitlines() if "error" in l.lower()]
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
accepted = [(1, ["-material_law", "ludwik", "-material_sy", 1500]), (1, ["-material_law", "ludwik", "-material_sy", 15]),
            (1, later), (1, viewer), (1, solver), (1, lu), (2, later), (2, solver),
            (1, ["-die_force", 0])]  # (the old spelling of the stroke: -die_force 0, not by force)
# (the single-rank ones two at a time, each its own -output and -history_csv (options/pressure.opts names one for
# all: two runs at once race to rename it into place); then the 2-rank ones one after another)
ones = [(i, extra) for i, (np_, extra) in enumerate(accepted) if np_ == 1]
with ThreadPoolExecutor(max_workers=2) as pool:
    ran = dict(zip([i for i, _ in ones], pool.map(lambda c: run(tf, mpirun, 1, base + [
        "-output", out(f"accepted_{c[0]}.h5"), "-history_csv", out(f"accepted_{c[0]}.csv"), "-options_left"] + c[1],
        check=False, timeout=60), ones)))
for i, (np_, extra) in enumerate(accepted):
    p = ran[i] if np_ == 1 else run(tf, mpirun, np_, base + ["-output", out("accepted.h5"), "-options_left"] + extra,
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
