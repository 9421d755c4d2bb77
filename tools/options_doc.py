#!/usr/bin/python3
"""docs/options-reference.md from `tubeform -help`: every tubeform option with
its default and description, by section, and which scenes read the options
that not every scene does (the scene registry's lines under "tubeform:
scenes:"), so the reference cannot drift from the code (the test docs_options
checks it is up to date). A registry line that names no option of -help (a
misspelling) stops it.

    /usr/bin/python3 tools/options_doc.py [--check] [EXE]

--check: compare with the file instead of writing it (exit 1 if it differs).
"""
import argparse
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, "docs", "options-reference.md")
SCENE = re.compile(r"^  scene (?P<name>[a-z_]+): (?P<what>.*); reads also: (?P<reads>.*?)(?:; and the blocks: "
                   r"(?P<blocks>.*))?$")
LINE = re.compile(r"^  -(?P<name>[a-z0-9_]+):? <(?:now )?(?P<default>.*?)(?: : (?:formerly )?.*?)?>:? (?P<help>.*) "
                  r"\(tubeform\)$")


def options(exe):
    """[(section, [(name, default, help, choices)])] and [(scene, what, [the options only some scenes read: a name
    ending in '_' a prefix], [the sections only some scenes read])] from -help, run with no options (the built-in
    defaults)."""
    env = {k: v for k, v in os.environ.items() if k != "PETSC_OPTIONS"}
    p = subprocess.run([os.path.abspath(exe), "-help", "-options_left", "no"], capture_output=True, text=True, env=env, cwd="/")
    sections, current, scenes = [], None, []
    for line in p.stdout.splitlines():
        m = SCENE.match(line)
        if m:
            scenes.append((m.group("name"), m.group("what"), m.group("reads").split(),
                           (m.group("blocks") or "").split("; ") if m.group("blocks") else []))
            continue
        m = re.match(r"^tubeform: (.*):$", line)
        if m and m.group(1) == "scenes":  # (the registry's lines follow: SCENE)
            current = None
            continue
        if m:
            current = (m.group(1), [])
            sections.append(current)
            continue
        if line.startswith("----"):
            current = None
            continue
        m = LINE.match(line)
        if current is not None and m:
            text, _, choices = m.group("help").partition(" (choose one of) ")
            default = m.group("default").strip()
            if default in ("", "0.") and m.group("name") == "material_table":
                default = "none"
            current[1].append((m.group("name"), default or "none", text.strip(), choices.split()))
    if not sections or not scenes:
        sys.exit(f"tools/options_doc.py: no tubeform options or scenes in the -help output of {exe}")
    return sections, scenes


def readers(name, section, scenes):
    """The scenes that read option `name` (no dash) of `section` where not every scene does: those whose list names
    it, else those that list its section; [] where every scene does."""
    listed = [s for s, _, reads, _ in scenes if any(names(r, name) for r in reads)]
    return listed or [s for s, _, _, blocks in scenes if section in blocks]


def names(word, name):
    """Whether a `reads` word (with its dash; ending in '_': a prefix; "<N>": a later pass's number, 2 to 9) names
    option `name` (no dash)."""
    pattern = re.escape(word[1:]).replace(re.escape("<N>"), "[2-9]") + (".*" if word.endswith("_") else "")
    return re.fullmatch(pattern, name) is not None


def anchor(title):
    """The section's anchor as GitHub writes it."""
    return "#" + re.sub(r"[^a-z0-9_ -]", "", title.lower()).replace(" ", "-")


def heading(title):
    return title[0].upper() + title[1:]


def scene_sections(scene, sections, scenes):
    """The sections `scene` reads, linked: a whole one by its title, one where it reads only some of the options
    with their names (or, where it reads most, the names of those it does not)."""
    parts = []
    for title, opts in sections:
        mine = [n for n, *_ in opts if scene in (readers(n, title, scenes) or [scene])]
        if mine:
            link = f"[{heading(title)}]({anchor(heading(title))})"
            others = [n for n, *_ in opts if n not in mine]
            parts.append(link if not others else link + ": " + ", ".join(f"`-{n}`" for n in mine) if
                         len(mine) <= len(others) else link + ": all but " + ", ".join(f"`-{n}`" for n in others))
    return "; ".join(parts)


def markdown(sections, scenes):
    shown = {t for t, _ in sections}  # (-help lists the later passes' blocks by the second's)
    scenes = [(n, w, r, [b for b in blocks if b in shown]) for n, w, r, blocks in scenes]
    out = ["# Options reference", "",
           "Generated from `build/tubeform -help` by `/usr/bin/python3 tools/options_doc.py`",
           "(do not edit; the test `docs_options` fails when it is out of date). Defaults are the built-in",
           "ones: scene files and presets under `options/` set many of them. docs/options.md guides",
           "through the groups and names the doc that explains each; PETSc's own options (solver,",
           "`-log_view`, ...) are listed by `-help` too.", "",
           "## Scenes", "",
           "What each scene reads: every option of a section named, or of a section followed by names those",
           "named (or all but those named). An option marked *Only* below is read by the scenes it names: given to another scene it stops",
           "the run naming them (`-allow_unused` runs anyway, with a warning). The later passes' options",
           "(`-pass3_*` to `-pass9_*`) are the second pass's, renamed.", "",
           "| scene | what | reads |", "|---|---|---|"]
    for name, what, _, _ in scenes:
        out.append(f"| `{name}` | {what} | {scene_sections(name, sections, scenes)} |")
    out.append("")
    for title, opts in sections:
        out += [f"## {heading(title)}", "", "| option | default | meaning |", "|---|---|---|"]
        for name, default, text, choices in opts:
            meaning = text.replace("|", "\\|") + (" (one of: " + ", ".join(f"`{c}`" for c in choices) + ")"
                                                  if choices else "")
            only = readers(name, title, scenes)
            meaning += f" *Only {', '.join(only)}.*" if only else ""
            out.append(f"| `-{name}` | `{default}` | {meaning} |")
        out.append("")
    return "\n".join(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--check", action="store_true", help="compare with the file instead of writing it")
    ap.add_argument("exe", nargs="?", default=os.path.join(ROOT, "build", "tubeform"), help="the tubeform binary")
    a = ap.parse_args()
    if not os.access(a.exe, os.X_OK):
        sys.exit(f"tools/options_doc.py: {a.exe}: not an executable tubeform (build it: scripts/build)")
    sections, scenes = options(a.exe)
    every = [n for _, opts in sections for n, *_ in opts]
    stray = sorted({r for _, _, reads, _ in scenes for r in reads if not any(names(r, n) for n in every)})
    if stray:  # (a registry line that names no option: a misspelling, or an option renamed without its line)
        sys.exit(f"tools/options_doc.py: the scene registry's lists name no option of -help: {' '.join(stray)} "
                 "(src/scenes/registry.cpp)")
    text = markdown(sections, scenes)
    if a.check:
        old = open(OUT).read() if os.path.exists(OUT) else ""
        if old != text:
            sys.exit(f"{OUT} is out of date: run /usr/bin/python3 tools/options_doc.py")
        print(f"{OUT}: up to date ({text.count(chr(10) + '| `-')} options)")
        return
    with open(OUT, "w") as f:
        f.write(text)
    print(f"tools/options_doc.py: {OUT} ({text.count(chr(10) + '| `-')} options)")


if __name__ == "__main__":
    main()
