"""The code's structure rules (docs/architecture.md, "Layers"), checked on the
source tree:
  - no include runs upward: a file in component A includes tubeform headers
    of A itself or of components in lower layers only (the layer table below
    is the one docs/architecture.md draws);
  - every component folder is in the table (a new folder must be placed);
  - no source or header file over 450 lines (one concern per file; the
    project aims at about 400);
  - no function defined in a .cpp file of src/ over 80 lines (the project
    aims at functions under about 80 lines, and the guard is that aim itself:
    a function that grows past it is split into named steps, not let pass);
  - no option's word is compared as a string literal in src/ or include/
    (`kind == "stroke"`): a choice is an enum or a named constant beside its
    registry (kVShape, kStrokeMotion, kCustomMaterial), so that a word is
    spelled once; a profile file's own tokens (tool/profile.cpp) are allowed.
    Planted: `name == "custom"` back in material_library.cpp -> FAILED;
  - the code is formatted by .clang-format (clang-format --dry-run --Werror),
    which also bounds lines at 120 columns;
  - the project stands alone: no file of the project's own folders (src,
    include, tests, scripts, studies, tools, python, options, docs, .ci) and no
    README.md or CMakeLists.txt cites the method specification kept outside
    the repository (the theory the code cites is in docs/theory.md and the
    docs beside it), and none names a tracker's "issue N": a doc or comment
    says what a thing is, not which issue brought it.
Usage: check_structure.py <unused> <unused> <source dir>
"""
import os
import re
import subprocess
import sys

from tfcheck import Checks

src = sys.argv[3]
k = Checks("structure")
LAYERS = [
    ["core"],
    ["fe", "mesh", "tool"],
    ["material", "step"],
    ["assembly"],
    ["body", "contact"],
    ["metrics"],
    ["io"],
    ["scenes"],
    ["driver"],
]
layer = {c: i for i, comps in enumerate(LAYERS) for c in comps}
include = re.compile(r'#include\s+"tubeform/([a-z_]+)/[^"]+"')
files = []
for top in ("src", "include/tubeform"):
    for root, _, names in os.walk(os.path.join(src, top)):
        files += [os.path.join(root, n) for n in names if n.endswith((".cpp", ".hpp"))]

upward, unknown, long_files = [], set(), []
for f in files:
    rel = os.path.relpath(f, src)
    parts = rel.split(os.sep)
    comp = parts[2] if parts[0] == "include" else parts[1]
    if comp.endswith(".cpp"):  # src/main.cpp: the application, above every layer
        comp = None
    elif comp not in layer:
        unknown.add(comp)
        continue
    text = open(f).read()
    for dep in include.findall(text):
        if dep not in layer:
            unknown.add(dep)
        elif comp is not None and dep != comp and layer[dep] >= layer[comp]:
            upward.append(f"{rel} includes {dep}/ (layer {layer[dep]} >= {layer[comp]} of {comp}/)")
    n = text.count("\n")
    if n > 450:
        long_files.append(f"{rel} ({n} lines)")


def blank_comments_and_literals(text):
    """The C++ text with comments, string and character literals (their
    insides) and preprocessor lines blanked; newlines kept, so line numbers stay."""
    out, i, n = [], 0, len(text)
    at_line_start = True
    while i < n:
        c = text[i]
        if at_line_start and c in " \t":
            out.append(c)
            i += 1
            continue
        if at_line_start and c == "#":  # a preprocessor line, with its continuations
            while i < n and (text[i] != "\n" or text[i - 1] == "\\"):
                out.append("\n" if text[i] == "\n" else " ")
                i += 1
            continue
        at_line_start = c == "\n"
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
        elif c == '"' or (c == "'" and not (i > 0 and text[i - 1].isalnum())):  # not a digit separator (1'000)
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1, n)
        else:
            out.append(c)
            i += 1
            continue
        out.append(re.sub(r"[^\n]", " ", text[i:j]))
        i = j
    return "".join(out)


def closing_brace(code, i):
    """The index of the brace that closes the one at code[i]."""
    depth = 0
    for j in range(i, len(code)):
        depth += {"{": 1, "}": -1}.get(code[j], 0)
        if depth == 0:
            return j
    return len(code) - 1


SCOPE = re.compile(r"(namespace|extern)\b|(template\s*<.*>\s*)?(class|struct|union)\b[^(]*$")
NAME = re.compile(r"((?:[A-Za-z_]\w*\s*::\s*)*(?:~\s*)?(?:operator\s*\(\s*\)|[A-Za-z_]\w*))\s*$")


def function_lengths(text):
    """(name, first line, lines) of each function defined at namespace or class
    scope in C++ source text; its lines run from the first of its signature to
    its closing brace (blank and comment lines included, as a reader sees it).
    A simple brace-matching scan, not a parser. Its limits: a block at
    namespace or class scope is taken for a function when the text before its
    brace (since the last ';', '{' or '}') holds a '(' with no '=' before it:
    a lambda assigned at namespace scope is not counted, and a brace inside a
    parenthesized initializer there (Foo x(Bar{1});) is taken for a function
    as long as that brace (harmless to a bound on length); braces that macros
    or #if branches open or close unbalanced would derail it (preprocessor
    lines are skipped, their braces unseen); raw string literals (R"(...)")
    are not recognized; lambdas and local classes count as part of the
    function that holds them.
    """
    code = blank_comments_and_literals(text)
    found, i, header, header_at = [], 0, "", 0
    classes = []  # the open namespaces and classes: a class's name, "" for a namespace
    while i < len(code):
        c = code[i]
        if c in ";}":  # a declaration ends, or a namespace or class closes
            if c == "}" and classes:
                classes.pop()
            header, i = "", i + 1
            continue
        if c != "{":
            if not header.strip():
                header_at = i
            header, i = header + c, i + 1
            continue
        h = " ".join(header.split())
        if SCOPE.match(h):  # namespaces and class bodies: their functions are scanned one by one
            m = re.match(r"(?:template\s*<.*>\s*)?(?:class|struct|union)\s+(\w+)", h)
            classes.append(m.group(1) if m else "")
            header, i = "", i + 1
            continue
        close = closing_brace(code, i)
        paren = h.find("(")
        after = h[h.rfind(")") + 1:] if paren >= 0 else ""
        if paren >= 0 and re.match(r"\s*:[^:]", after) and re.search(r"\w\s*$", h):
            header, i = header + code[i:close + 1], close + 1  # a brace initializer in a constructor's member list
            continue
        if paren >= 0 and "=" not in h[:paren]:
            if h[paren:paren + 3] == "()(":  # operator()(...)
                paren += 2
            m = NAME.search(h[:paren])
            name = "::".join([k for k in classes if k] + [re.sub(r"\s+", "", m.group(1)) if m else h[:paren]])
            first = code.count("\n", 0, header_at) + 1
            found.append((name, first, code.count("\n", 0, close) + 2 - first))
        header, i = "", close + 1
    return found


# Functions: the project aims at under about 80 lines, and the guard fails above that aim.
MAX_FUNCTION_LINES = 80
long_functions, n_functions = [], 0
for f in sorted(files):
    if f.endswith(".cpp") and os.path.relpath(f, src).startswith("src" + os.sep):
        for name, line, length in function_lengths(open(f).read()):
            n_functions += 1
            if length > MAX_FUNCTION_LINES:
                long_functions.append(f"{os.path.relpath(f, src)}:{line}: {name} ({length} lines)")

missing = f": missing {', '.join(sorted(unknown))}" if unknown else ""
k.check(not unknown, f"every component is placed in a layer{missing}")
k.check(not upward, f"no include runs upward ({len(files)} files)" + "".join("\n         " + u for u in upward))
k.check(not long_files, "no file over 450 lines" + "".join("\n         " + u for u in long_files))
k.check(not long_functions, f"no function over {MAX_FUNCTION_LINES} lines ({n_functions} functions in src/*.cpp)"
        + "".join("\n         " + u for u in long_functions))
# Choices are enums or named constants beside their registries (kVShape, kStrokeMotion, kCustomMaterial), not words
# compared where they are used. Allowed: the tokens of a profile file's own format (tool/profile.cpp).
WORD_COMPARED = re.compile(r'(==|!=)\s*"[A-Za-z_]+"')
FILE_TOKENS = {os.path.join("src", "tool", "profile.cpp")}
compared = [f"{os.path.relpath(f, src)}:{i}: {line.strip()}" for f in sorted(files)
            if os.path.relpath(f, src) not in FILE_TOKENS
            for i, line in enumerate(open(f).read().splitlines(), 1) if WORD_COMPARED.search(line)]
k.check(not compared, "no option's word compared as a string literal in src/ and include/"
        + "".join("\n         " + c for c in compared))
tests = os.path.join(src, "tests")
code = files + [os.path.join(tests, n) for n in os.listdir(tests) if n.endswith((".cpp", ".hpp"))]
p = subprocess.run(["clang-format", "--dry-run", "--Werror", f"--style=file:{src}/.clang-format"] + code,
                   capture_output=True, text=True)
bad = sorted({line.split(":")[0] for line in p.stderr.splitlines() if "error:" in line})
k.check(p.returncode == 0, "formatted by .clang-format" + "".join("\n         " + os.path.relpath(b, src) for b in bad))

# Stands alone. The outside specification's file name is spelled in two pieces so that this file does not cite it.
outside = re.compile(re.escape("METHOD" + ".md"))
issue = re.compile(r"\bissues? #?[0-9]+", re.I)
roots = ["src", "include", "tests", "scripts", "studies", "tools", "python", "options", "docs", ".ci"]
texts = [os.path.join(src, n) for n in ("README.md", "CMakeLists.txt") if os.path.exists(os.path.join(src, n))]
for top in roots:
    for root, dirs, names in os.walk(os.path.join(src, top)):
        dirs[:] = [d for d in dirs if d not in ("__pycache__", "build")]
        texts += [os.path.join(root, n) for n in names]
cites, issues = [], []
for f in texts:
    try:
        lines = open(f, encoding="utf-8").read().splitlines()
    except (UnicodeDecodeError, OSError):
        continue  # figures, HDF5 references: not text
    rel = os.path.relpath(f, src)
    cites += [f"{rel}:{i}" for i, line in enumerate(lines, 1) if outside.search(line)]
    for i, line in enumerate(lines):
        # A reference wrapped after "issue" continues on the next line, past its comment marker.
        nxt = re.sub(r"^\s*(#|//|\*)?\s*", "", lines[i + 1]) if i + 1 < len(lines) else ""
        m = issue.search(line + " " + nxt)
        if m and m.start() < len(line):
            issues.append(f"{rel}:{i + 1}: {m.group(0)}")
k.check(not cites, f"no file cites the outside specification ({len(texts)} files)"
        + "".join("\n         " + c for c in cites))
k.check(not issues, "no file names an issue by number" + "".join("\n         " + c for c in issues))
k.done()
