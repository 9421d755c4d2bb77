"""A full disk: the run stops with one line naming the file it could not
write, a non-zero exit, and the earlier results of the same name byte for
byte unchanged (nothing is renamed into place), on 1 and 2 ranks, with no
crash and no hang.

The disk is a 4 MB tmpfs mounted here by the test (as root, as CI runs). On
it, a first run (the paper's tube on the fast preset to 0.3 mm) leaves
complete results; then, under the same names:
  - the field steps: a filler leaves 2.3 MB free and the run writes a field
    step at every increment: once a step would leave less than the 1 MB the
    run keeps free for HDF5 (and the 1 MB it holds back to close the file),
    it stops naming -output; what it wrote so far stays in <output>.partial,
    readable;
  - the history CSV: with -output on the ordinary disk, the filler leaves
    20 kB for a CSV of about 60 kB: a write fails (ENOSPC) and the run stops
    naming -history_csv; the truncated CSV is removed, never renamed (before,
    CSV writes were unchecked: a truncated CSV was renamed into place as
    complete);
  - another writer fills the disk to the last byte while the run goes (a
    filler started once the run has written its first rows): whichever write
    meets it first, the run stops with one line naming -output or
    -history_csv, exit 1 (no crash: a result file closed on a full disk used
    to end one rank in a segmentation fault at MPI_Finalize, two ranks in a
    hang), and the earlier results unchanged. (A field step's HDF5 call that
    meets the disk filled after its room was checked named no option, about 1
    run in 70 of this race: "HDF5 call failed: *dset".)
  - the estimate's own write: the run's results are in place when the
    companion fills the disk (tests/test_companion.cpp, mode fill: 100 kB
    left); the estimate cannot be added to them (that takes a copy of the
    file): exit 0, one line saying so, the results complete without the
    estimate, nothing left beside them.
When mount is refused (not root), the CSV case runs on /dev/full instead (its
.partial is a link to it: every write fails with ENOSPC) and the cases that
need a small file system are skipped; the output says so.
"""
import hashlib
import os
import shutil
import subprocess
import sys
import time

import h5py

from tfcheck import Checks, args, crashed, out, run

tf, mpirun, src = args()
companion = sys.argv[4]
k = Checks("full_disk")
CASE = ["-options_file", f"{src}/options/squaring.opts", "-options_file", f"{src}/options/preset-fast.opts",
        "-progress", "0"]
DISK = out("full_disk")
TIMEOUT = 120  # s: these runs take seconds; a hang is killed and fails


def digest(paths):
    return {p: hashlib.sha256(open(p, "rb").read()).hexdigest() for p in paths}


def clear(*names):
    for n in names:
        for q in (n, n + ".partial", n + ".partial.room", n + ".estimate.partial"):
            if os.path.islink(q) or os.path.exists(q):
                os.remove(q)


def fill(leave):
    """Fills the disk with a filler file so that `leave` bytes stay free."""
    filler = os.path.join(DISK, "filler")
    if os.path.exists(filler):
        os.remove(filler)
    left = shutil.disk_usage(DISK).free - leave if leave >= 0 else 1 << 40
    fd = os.open(filler, os.O_CREAT | os.O_WRONLY)
    try:
        while left > 0:  # (unbuffered: to the last byte, when leave is 0)
            left -= os.write(fd, b"\0" * min(left, 65536))
    except OSError:  # ENOSPC: full
        pass
    os.close(fd)


def stopped(np_, what, opts, names, needle, partial=None):
    """Runs the case that meets the full disk; checks one line with `needle`, exit 1, the earlier `names` unchanged."""
    before = digest(names)
    p = run(tf, mpirun, np_, CASE + opts, check=False, timeout=TIMEOUT, report_hang=True)
    lines = [l for l in (p.stdout + p.stderr).splitlines() if l.startswith("tubeform: error")]
    crash = crashed(p)
    same = digest(names) == before
    ok = p.returncode == 1 and not crash and len(lines) == 1 and any(n in lines[0] for n in needle)
    readable = ""
    if partial:
        try:
            with h5py.File(partial, "r") as h:
                readable = f", {partial.split('/')[-1]} readable ({h['/time'].shape[0]} field steps)"
        except OSError as e:
            ok, readable = False, f", {partial} unreadable: {e}"
    k.check(ok and same, f"np={np_} {what}: exit {p.returncode}{', ' + crash if crash else ''}, earlier results "
            f"{'unchanged' if same else 'CHANGED'}{readable}; {lines}")
    return p


os.makedirs(DISK, exist_ok=True)
mounted = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=4m", "tmpfs", DISK], capture_output=True, text=True)
try:
    if mounted.returncode != 0:
        print(f"mount refused ({mounted.stderr.strip()}): the CSV case runs on /dev/full; the cases that need a small "
              "file system are skipped")
        for np_ in (1, 2):
            h5, csv = out(f"full_np{np_}.h5"), out(f"full_np{np_}.csv")
            clear(h5, csv, h5[:-3] + ".xmf")
            run(tf, mpirun, 1, CASE + ["-stroke", "0.3", "-output", h5, "-history_csv", csv])
            os.symlink("/dev/full", csv + ".partial")
            stopped(np_, "the history CSV on /dev/full", ["-stroke", "1.5", "-output", h5, "-history_csv", csv],
                    [h5, csv, h5[:-3] + ".xmf"], ["-history_csv " + csv])
            k.check(not os.path.lexists(csv + ".partial"), f"np={np_}: the failed CSV removed")
    else:
        for np_ in (1, 2):
            h5, csv = os.path.join(DISK, "r.h5"), os.path.join(DISK, "r.csv")
            xmf = h5[:-3] + ".xmf"
            earlier = [h5, csv, xmf]
            for f in os.listdir(DISK):
                os.remove(os.path.join(DISK, f))
            run(tf, mpirun, 1, CASE + ["-stroke", "0.3", "-output", h5, "-history_csv", csv])

            fill(2_300_000)
            stopped(np_, "field steps on a full disk", ["-stroke", "1.5", "-output_every", "1", "-output", h5,
                                                        "-history_csv", csv], earlier, ["-output " + h5],
                    partial=h5 + ".partial")
            k.check(not os.path.exists(h5 + ".partial.room"), f"np={np_}: the room held for closing given back")

            clear(h5, csv, xmf)
            fill(4_000_000)
            away = out(f"full_np{np_}.h5")
            clear(away, away[:-3] + ".xmf")
            run(tf, mpirun, 1, CASE + ["-stroke", "0.3", "-output", away, "-history_csv", csv])
            fill(20_000)
            stopped(np_, "the history CSV on a full disk", ["-stroke", "1.5", "-output", away, "-history_csv", csv],
                    [csv, away, away[:-3] + ".xmf"], ["-history_csv " + csv], partial=away + ".partial")
            k.check(not os.path.exists(csv + ".partial"), f"np={np_}: the truncated CSV removed, not renamed")

            # Another writer fills the disk while the run goes.
            clear(h5, csv, xmf)
            fill(4_000_000)
            run(tf, mpirun, 1, CASE + ["-stroke", "0.3", "-output", h5, "-history_csv", csv])
            before = digest(earlier)
            cmd = ([mpirun, "-n", str(np_)] if np_ > 1 else []) + [tf] + CASE + [
                "-stroke", "1.5", "-output", h5, "-history_csv", csv]
            proc = subprocess.Popen(cmd, cwd=src, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
            t0 = time.time()
            while not os.path.exists(csv + ".partial") and proc.poll() is None and time.time() - t0 < 60:
                time.sleep(0.005)
            time.sleep(0.2)
            fill(-1)  # to the last byte
            try:
                text, _ = proc.communicate(timeout=TIMEOUT)
            except subprocess.TimeoutExpired:
                proc.kill()
                text, _ = proc.communicate()
                text += "\n(a hang: killed)"
            lines = [l for l in text.splitlines() if l.startswith("tubeform: error")]
            same = digest(earlier) == before
            ok = (proc.returncode == 1 and len(lines) == 1 and
                  any(n in lines[0] for n in ("-output " + h5, "-history_csv " + csv)))
            k.check(ok and same, f"np={np_} the disk filled during the run: exit {proc.returncode}, earlier results "
                    f"{'unchanged' if same else 'CHANGED'}; {lines or text.splitlines()[-3:]}")

            # The estimate's copy meets the full disk.
            clear(h5, csv, xmf)
            fill(4_000_000)
            p = run(companion, mpirun, np_, ["fill"] + CASE + ["-stroke", "0.5", "-output", h5, "-history_csv", csv],
                    check=False, timeout=TIMEOUT, report_hang=True)
            said = [l for l in (p.stdout + p.stderr).splitlines() if "error estimate is not in" in l]
            errors = [l for l in (p.stdout + p.stderr).splitlines() if l.startswith("tubeform: error")]
            with h5py.File(h5, "r") as h:
                a = h["/history"].attrs
                whole = a["stopped"] == 0 and "error_load" not in a and h["/history/stroke"][-1] >= 0.5 - 1e-9
            left = [q for q in os.listdir(DISK) if q.endswith("partial") or q.endswith(".room")]
            k.check(p.returncode == 0 and len(said) == 1 and not errors and whole and not left,
                    f"np={np_} the estimate's copy on a full disk: exit {p.returncode}, results complete without it"
                    f"{', left ' + str(left) if left else ''}; {said}")
finally:
    if mounted.returncode == 0:
        subprocess.run(["umount", DISK])
k.done()
