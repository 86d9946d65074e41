#!/usr/bin/env python3
"""Spot-check of doc/design.md against the tree: every name it quotes exists.

The design page is a map; a map that names moved files or renamed functions
misleads a newcomer more than no map. Every `backticked` token of the page
is classified and checked:

- a path (has a '/' or a source extension, no space; `{h,cpp}` and `*`
  expand): a path from the repository root must exist; a shorter one must be
  the tail of some file of the tree;
- `Class::member` (optionally `hsrod::`, optionally with an argument list):
  the class is declared in the project's sources and the member appears
  there as `Class::member` or as `member(` in a file that declares the class
  (classes of LIGGGHTS itself are listed in EXTERNAL_CLASSES);
- `Suite.*` / `Suite.Test`: a GoogleTest suite or test of tests/;
- a single identifier or `name()`: the word occurs in the project's sources
  or CMake files (a function, a library, a ctest name, a keyword).

Tokens with spaces (input-script fragments) are skipped.
Usage: check_design_doc.py REPO_ROOT. Prints every stale name; exit 1 if any.
"""
import fnmatch
import os
import re
import sys

DOC = "doc/design.md"
SOURCE_DIRS = ["drag-models", "liggghts-package", "calibration", "tests", "examples", "scripts"]
TOP_LEVEL = tuple(d + "/" for d in SOURCE_DIRS + ["doc"])
SKIP_DIRS = {"build", "third_party-build", "__pycache__", ".git"}
CODE_EXT = (".h", ".cpp", ".C", ".H", ".py", ".sh", ".txt", ".cmake")
PATH_EXT = CODE_EXT + (".md", ".json", ".csv", ".yaml")
EXTERNAL_CLASSES = {"SignalHandler"}  # LIGGGHTS' own classes the page names


def tree_files(root):
    out = []
    for top in SOURCE_DIRS + ["doc"]:
        for base, dirs, files in os.walk(os.path.join(root, top)):
            dirs[:] = [d for d in dirs if d not in SKIP_DIRS and not d.startswith("build")]
            for name in files:
                out.append(os.path.relpath(os.path.join(base, name), root))
    out.append("CMakeLists.txt")
    return out


def expand_braces(token):
    m = re.search(r"\{([^{}]*)\}", token)
    if not m:
        return [token]
    out = []
    for alt in m.group(1).split(","):
        out += expand_braces(token[:m.start()] + alt + token[m.end():])
    return out


def check_path(token, files):
    problems = []
    for pattern in expand_braces(token.rstrip("/")):
        if pattern.startswith(TOP_LEVEL) or pattern == "CMakeLists.txt":
            hit = [f for f in files if fnmatch.fnmatchcase(f, pattern)
                   or f.startswith(pattern + "/")]
        else:
            hit = [f for f in files if fnmatch.fnmatchcase(f, "*/" + pattern)
                   or ("/" + pattern + "/") in ("/" + f)]
        if not hit:
            problems.append(f"path `{pattern}` matches no file of the tree")
    return problems


def main(root):
    files = tree_files(root)
    code = {}
    for f in files:
        if f.endswith(CODE_EXT) or os.path.basename(f) == "CMakeLists.txt":
            if f.startswith("doc/"):
                continue
            with open(os.path.join(root, f), encoding="utf-8", errors="replace") as fh:
                code[f] = fh.read()
    everything = "\n".join(code.values())
    with open(os.path.join(root, DOC), encoding="utf-8") as fh:
        doc = fh.read()
    tokens = set(re.findall(r"`([^`\n]+)`", doc))
    # Paths in running text too ("(liggghts-package/src/styles/x.cpp)"): a
    # path rooted at a top folder, outside code fences' drawings.
    prose = re.sub(r"```.*?```", "", doc, flags=re.S)
    prose = re.sub(r"`[^`\n]+`", "", prose)
    roots = "|".join(re.escape(t) for t in TOP_LEVEL)
    tokens |= {m.rstrip(".,;:") for m in re.findall(rf"(?<![\w/.-])(?:{roots})[\w./{{}},*-]*\.\w+", prose)}
    tokens = sorted(tokens)
    problems = []
    checked = 0
    for raw in tokens:
        token = re.sub(r"\(.*\)$", "", raw.strip())
        if " " in token or not token:
            continue
        member = re.fullmatch(r"(?:hsrod::)?([A-Z]\w*)::(~?\w+)", token)
        suite = re.fullmatch(r"([A-Z]\w*)\.(\*|\w+)", token)
        checked += 1
        if member:
            cls, name = member.groups()
            if cls in EXTERNAL_CLASSES:
                continue
            declaring = [t for t in code.values() if re.search(rf"\b(class|struct)\s+{cls}\b", t)]
            if not declaring:
                problems.append(f"`{raw}`: no class or struct {cls} in the sources")
            elif not (re.search(rf"\b{cls}::{name}\b", everything)
                      or any(re.search(rf"\b{name}\s*\(", t) for t in declaring)):
                problems.append(f"`{raw}`: {cls} has no member {name}")
        elif suite and not token.endswith(PATH_EXT):
            name, test = suite.groups()
            tests = "\n".join(t for f, t in code.items() if f.startswith("tests/"))
            pattern = rf"\b(TEST|TEST_F|TEST_P)\(\s*{name}\s*,"
            if test != "*":
                pattern += rf"\s*{test}\b"
            if not re.search(pattern, tests):
                problems.append(f"`{raw}`: no GoogleTest {token} in tests/")
        elif "/" in token or token.endswith(PATH_EXT):
            if token.startswith("../"):
                problems.append(f"`{raw}`: the page cites a file outside the repository")
            elif "<" not in token:
                problems.extend(f"`{raw}`: {p}" for p in check_path(token, files))
        elif re.fullmatch(r"\w+", token):
            if not re.search(rf"\b{re.escape(token)}\b", everything):
                problems.append(f"`{raw}`: the name {token} occurs nowhere in the sources")
        else:
            checked -= 1
    for p in problems:
        print(f"{DOC}: {p}")
    print(f"design doc: {checked} names checked, {len(problems)} stale")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "."))
