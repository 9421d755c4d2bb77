#!/usr/bin/python3
"""docs/options-reference.md from `tubeform -help`: every tubeform option with
its default and description, by section, so the reference cannot drift from
the code (the test docs_options checks it is up to date).

    /usr/bin/python3 tools/options_doc.py [--check] [EXE]

--check: compare with the file instead of writing it (exit 1 if it differs).
"""
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, "docs", "options-reference.md")
LINE = re.compile(r"^  -(?P<name>[a-z0-9_]+):? <(?:now )?(?P<default>.*?)(?: : (?:formerly )?.*?)?>:? (?P<help>.*) "
                  r"\(tubeform\)$")


def options(exe):
    """[(section, [(name, default, help, choices)])] from -help, run with no options (the built-in defaults)."""
    env = {k: v for k, v in os.environ.items() if k != "PETSC_OPTIONS"}
    p = subprocess.run([os.path.abspath(exe), "-help", "-options_left", "no"], capture_output=True, text=True, env=env, cwd="/")
    sections, current = [], None
    for line in p.stdout.splitlines():
        m = re.match(r"^tubeform: (.*):$", line)
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
    if not sections:
        sys.exit(f"tools/options_doc.py: no tubeform options in the -help output of {exe}")
    return sections


def markdown(sections):
    out = ["# Options reference", "",
           "Generated from `build/tubeform -help` by `/usr/bin/python3 tools/options_doc.py`",
           "(do not edit; the test `docs_options` fails when it is out of date). Defaults are the built-in",
           "ones: scene files and presets under `options/` set many of them. docs/options.md guides",
           "through the groups and names the doc that explains each; PETSc's own options (solver,",
           "`-log_view`, ...) are listed by `-help` too.", ""]
    for title, opts in sections:
        out += [f"## {title[0].upper() + title[1:]}", "", "| option | default | meaning |", "|---|---|---|"]
        for name, default, text, choices in opts:
            meaning = text.replace("|", "\\|") + (" (one of: " + ", ".join(f"`{c}`" for c in choices) + ")"
                                                  if choices else "")
            out.append(f"| `-{name}` | `{default}` | {meaning} |")
        out.append("")
    return "\n".join(out)


def main():
    args = [a for a in sys.argv[1:] if a != "--check"]
    exe = args[0] if args else os.path.join(ROOT, "build", "tubeform")
    text = markdown(options(exe))
    if "--check" in sys.argv:
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
