"""The docs' references resolve: a reader who follows one lands somewhere.
  - every relative link [..](path#anchor) of README.md, docs/*.md and
    docs/notes/*.md names a file that exists, and its anchor a heading there;
  - every section cited in the text as `X.md, "Title"` (or `X.md "Title"`)
    is a heading or a bold paragraph lead ("**Title.**") of X.md, whole or cut
    only before its first " (", ": " or ", " (a number "6." may be left off),
    and every
    "theory.md, section N" a numbered section of docs/theory.md;
  - every path of the project's folders a user doc names (README.md,
    docs/*.md: `tests/check_turn.py`, options/dies/plate.profile, ...) exists;
    a placeholder (`src/tool/shape_<kind>.cpp`) is not a path;
  - docs/README.md, the index, links every doc of docs/, and
    docs/notes/README.md every note;
  - the sources (src/, include/), tests, tools, scripts, studies, Python
    helpers and options files cite docs that exist and sections they have
    (comments wrapped over lines are joined, as are C++ string literals
    continued over lines, their \" read as ").
The notes are records at their commits: their plain paths may name files
since removed, so only their links and cited sections are checked.
Exact checks on text: nothing here has a tolerance.
"""
import glob
import os
import re

from tfcheck import Checks, args

_, _, src = args()
k = Checks("docs_links")
FOLDERS = "docs|tests|scripts|tools|studies|python|src|include|meshes|options|\\.ci"
user = [os.path.join(src, "README.md")] + sorted(glob.glob(os.path.join(src, "docs", "*.md")))
notes = sorted(glob.glob(os.path.join(src, "docs", "notes", "*.md")))
files = set()
for root, dirs, names in os.walk(src):
    dirs[:] = [d for d in dirs if not d.startswith(".git") and d not in ("build", "__pycache__", "Testing")]
    files.update(os.path.relpath(os.path.join(root, n), src) for n in names)


def text(path):
    """The doc's text without its code blocks (commands, not references)."""
    return re.sub(r"```.*?```", "", open(path, encoding="utf-8").read(), flags=re.S)


def anchor(heading):
    """GitHub's anchor of a heading: lower case, punctuation dropped, spaces to hyphens."""
    return re.sub(r"[^a-z0-9_ -]", "", heading.strip().lower()).replace(" ", "-")


def titles(path):
    """A doc's headings and bold paragraph leads, the sections the text cites, each as it may be cited: whole, or
    up to its first " (", ": " or ", " (the options it is about, a subtitle), a numbered heading without its
    number: a title cut anywhere else is refused (it may name another section)."""
    t = text(path)
    names = set()
    for h in re.findall(r"^#+ (.+)$", t, re.M) + re.findall(r"\*\*([^*]+)\*\*", t):
        for full in (h.strip(" ."), re.sub(r"^[0-9]+[a-z]?\. ", "", h.strip(" ."))):
            names.update({full, full.split(" (")[0], full.split(": ")[0], full.split(", ")[0]})
    return names


def resolve(doc, name):
    """The file a doc means by name: beside it, from the project's root, or under docs/."""
    for c in (os.path.join(os.path.dirname(doc), name), os.path.join(src, name), os.path.join(src, "docs", name)):
        if os.path.exists(c):
            return c
    return None


bad_links, bad_cited, bad_paths, n_links, n_cited, n_paths = [], [], [], 0, 0, 0
for doc in user + notes:
    rel = os.path.relpath(doc, src)
    t = text(doc)
    for link in re.findall(r"\]\(([^)\s]+)\)", t):
        if re.match(r"[a-z]+:", link):
            continue  # a web address
        n_links += 1
        name, _, frag = link.partition("#")
        target = os.path.normpath(os.path.join(os.path.dirname(doc), name)) if name else doc
        if not os.path.exists(target):
            bad_links.append(f"{rel}: {link} (no such file)")
        elif frag and target.endswith(".md") and frag not in {anchor(h) for h in re.findall(r"^#+ (.+)$", text(target), re.M)}:
            bad_links.append(f"{rel}: {link} (no such heading)")
    flat = re.sub(r"\s+", " ", t)
    for name, title in re.findall(r"([\w./-]+\.md)\)?,? \"([^\"]+)\"", flat):
        target = resolve(doc, name)
        n_cited += 1
        title = title.strip(" .,")
        if not target:
            bad_cited.append(f'{rel}: {name}, "{title}" (no such file)')
        elif title not in titles(target):
            bad_cited.append(f'{rel}: {name}, "{title}" (no such section)')
    for num in re.findall(r"theory\.md,? sections? ([0-9]+[a-z]?)", flat):
        n_cited += 1
        if not re.search(rf"^## {num}\. ", text(os.path.join(src, "docs", "theory.md")), re.M):
            bad_cited.append(f"{rel}: theory.md, section {num} (no such section)")
    if doc in notes:
        continue
    for path in re.findall(rf"(?<![\w/.<-])((?:{FOLDERS})/[\w./-]*\w)(?![\w<*])", t):
        n_paths += 1
        if not (path in files or os.path.exists(os.path.join(src, path)) or resolve(doc, path)
                or any(f.endswith("/" + path) for f in files)):
            bad_paths.append(f"{rel}: {path}")
cite = re.compile(r"(docs/[\w./-]+\.md)\)?,? \"([^\"]+)\"")
SOURCES = ("src", "include", "tests", "tools", "scripts", "studies", "python", "options")
n_sources = 0
for rel in sorted(f for f in files if f.split(os.sep)[0] in SOURCES
                  and not f.endswith((".h", ".png", ".pdf", ".h5", ".dxf", ".msh", ".csv"))):
    try:
        t = open(os.path.join(src, rel), encoding="utf-8").read()
    except (UnicodeDecodeError, OSError):
        continue  # not text
    if rel.endswith((".cpp", ".hpp")):  # (a literal continued on the next line, and its escaped quotes)
        n_sources += 1
        t = re.sub(r'"\s*\n\s*"', "", t).replace('\\"', '"')
    flat = re.sub(r"\s*\n\s*(#|//|\*)?\s*", " ", t)
    for name in re.findall(r"(docs/[\w./-]+\.md)", flat):
        n_cited += 1
        if not os.path.exists(os.path.join(src, name)):
            bad_cited.append(f"{rel}: {name} (no such file)")
    for name, title in cite.findall(flat):
        n_cited += 1
        title = title.strip(" .,")
        if os.path.exists(os.path.join(src, name)) and title not in titles(os.path.join(src, name)):
            bad_cited.append(f'{rel}: {name}, "{title}" (no such section)')
k.check(n_links > 50 and not bad_links, f"{n_links} links resolve" + "".join("\n         " + b for b in bad_links))
k.check(n_cited > 50 and n_sources > 100 and not bad_cited, f"{n_cited} cited sections exist ({n_sources} C++ sources "
        f"read)" + "".join("\n         " + b for b in bad_cited))
k.check(n_paths > 50 and not bad_paths, f"{n_paths} paths the user docs name exist"
        + "".join("\n         " + b for b in bad_paths))

for index, docs in ((os.path.join(src, "docs", "README.md"), user[1:]),
                    (os.path.join(src, "docs", "notes", "README.md"), notes)):
    links = {os.path.normpath(os.path.join(os.path.dirname(index), x.partition("#")[0]))
             for x in re.findall(r"\]\(([^)\s#]+)", text(index))}
    missing = [os.path.relpath(d, src) for d in docs if d != index and os.path.normpath(d) not in links]
    k.check(not missing, f"{os.path.relpath(index, src)} links each of its {len(docs) - 1} docs (missing: {missing})")
k.done()
