#!/usr/bin/env python3
"""The project's structure rules, checked on every source file of the tree.

- every source file <= 500 lines; a LIGGGHTS fix's .cpp <= 350 lines;
- every function <= 120 lines (C++: a definition at namespace scope, from
  its header line to its closing brace; Python: ast's extent), except in
  generated data files (a "Do not edit: regenerate" header: one static
  table per function);
- comments say why, not history: no "issue N" or "session N" references, no
  citation of the project brief kept outside this repository (its file name,
  HISTORY), in C++ comments, Python '#' comments and docstrings, and the '#'
  comments of CMake, shell and LIGGGHTS scripts (*.in and in.* under tests/
  and examples/); an identifier glued to its number (the campaign "session4")
  is not a reference;
- liggghts-package/src: support/, screen/ and the styles' helpers do not
  include a style's header (only app/ registers styles).

Usage: check_structure.py REPO_ROOT. Prints every violation; exit 1 if any.
"""
import ast
import os
import re
import sys

MAX_FILE_LINES = 500
MAX_FIX_LINES = 350
MAX_FUNCTION_LINES = 120
SOURCE_DIRS = ["drag-models", "liggghts-package", "calibration", "tests", "examples", "scripts", ".ci"]
CXX = (".cpp", ".h", ".C", ".H", ".hpp")
SKIP_DIRS = {"build", "third_party-build", "__pycache__", ".git"}
HISTORY = re.compile(r"\bissues?(\s+#?|\s*#)\d+|\bsession[- ]\d+|(?<!doc/)\bDESIGN\.md\b", re.IGNORECASE)
LIGGGHTS_DIRS = ("tests/", "examples/")


def is_liggghts_script(rel):
    name = os.path.basename(rel)
    return rel.startswith(LIGGGHTS_DIRS) and (name.endswith(".in") or name.startswith("in."))


def is_hash_commented(rel):
    """CMake, shell and LIGGGHTS scripts: '#' starts a comment."""
    name = os.path.basename(rel)
    return name == "CMakeLists.txt" or name.endswith((".cmake", ".sh")) or is_liggghts_script(rel)


def hash_comment_history(rel, text):
    """History references in the text after a line's first '#'."""
    out = []
    for k, l in enumerate(text.splitlines(), 1):
        if "#" in l:
            m = HISTORY.search(l[l.index("#"):])
            if m:
                out.append((k, f"{rel}:{k}: history comment or outside citation '{m.group(0)}'"))
    return out


def docstring_history(rel, tree, lines):
    """History references in module, class and function docstrings, by line."""
    out = []
    for node in ast.walk(tree):
        if not isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)):
            continue
        if ast.get_docstring(node) is None:
            continue
        doc = node.body[0]
        for k in range(doc.lineno, doc.end_lineno + 1):
            m = HISTORY.search(lines[k - 1])
            if m:
                out.append((k, f"{rel}:{k}: history in a docstring '{m.group(0)}'"))
    return out


def source_files(root):
    for top in SOURCE_DIRS:
        for base, dirs, files in os.walk(os.path.join(root, top)):
            dirs[:] = [d for d in dirs if d not in SKIP_DIRS and not d.startswith("build")]
            for name in sorted(files):
                path = os.path.join(base, name)
                if (name.endswith(CXX + (".py", ".sh", ".cmake")) or name == "CMakeLists.txt"
                        or is_liggghts_script(os.path.relpath(path, root))):
                    yield path


def strip_cxx(text):
    """Code with comments and string/char literals blanked (newlines kept),
    and the comments' text, line by line."""
    code, comments = [], []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            comments.append(text[i:j])
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            comments.append(text[i:j])
            code.append("\n" * text.count("\n", i, j))
            i = j
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            code.append(c + "\n" * text.count("\n", i, j) + c)
            i = j + 1
        else:
            code.append(c)
            i += 1
    return "".join(code), comments


OPENERS = re.compile(r"\b(namespace|extern)\b[^;{}()]*$|\b(class|struct|union|enum)\b[^;{}]*$")


def cxx_functions(code):
    """(header line, length) of every brace block at namespace scope whose
    header has a parameter list, i.e. a function definition."""
    out = []
    depth = 0           # depth of function-or-class blocks
    scope = []          # per open brace: True if it is a namespace-like scope
    start_line = None
    header = ""
    line = 1
    for ch in code:
        if ch == "\n":
            line += 1
            header += " "
            continue
        if ch == "{":
            transparent = bool(re.search(r"\b(namespace|extern)\b[^;{}()]*$", header)) and depth == 0
            scope.append(transparent)
            if not transparent:
                if depth == 0 and "(" in header and not re.search(r"\b(class|struct|union|enum)\b[^;{}()]*$", header):
                    start_line = header_line
                depth += 1
            header = ""
        elif ch == "}":
            transparent = scope.pop() if scope else True
            if not transparent:
                depth -= 1
                if depth == 0 and start_line is not None:
                    out.append((start_line, line - start_line + 1))
                    start_line = None
            header = ""
        elif ch == ";":
            if depth == 0:
                header = ""
        else:
            if depth == 0 and not header.strip() and not ch.isspace():
                header_line = line
            if depth == 0:
                header += ch
    return out


def main(root):
    problems = []
    for path in source_files(root):
        rel = os.path.relpath(path, root)
        with open(path, encoding="utf-8", errors="replace") as f:
            text = f.read()
        lines = text.count("\n") + (0 if text.endswith("\n") else 1)
        is_fix = rel.startswith("liggghts-package/src/styles/fix_") and rel.endswith(".cpp")
        limit = MAX_FIX_LINES if is_fix else MAX_FILE_LINES
        if lines > limit:
            problems.append(f"{rel}: {lines} lines (limit {limit})")
        generated = "Do not edit: regenerate" in text[:2000]
        if rel.endswith(CXX):
            code, comments = strip_cxx(text)
            for start, length in ([] if generated else cxx_functions(code)):
                if length > MAX_FUNCTION_LINES:
                    problems.append(f"{rel}:{start}: function of {length} lines (limit {MAX_FUNCTION_LINES})")
            for comment in comments:
                m = HISTORY.search(comment)
                if m:
                    problems.append(f"{rel}: history comment or outside citation '{m.group(0)}' in: {comment.strip()[:90]}")
            if rel.startswith("liggghts-package/src/") and not rel.startswith("liggghts-package/src/app/"):
                folder = rel.split("/")[2]
                for inc in re.findall(r'#include\s+"((?:fix|compute)_[a-z_]+\.h)"', text):
                    owner = os.path.join(root, "liggghts-package/src/styles", inc)
                    if folder != "styles" and os.path.exists(owner):
                        problems.append(f"{rel}: includes the style header {inc} (support code must not)")
        elif rel.endswith(".py"):
            try:
                tree = ast.parse(text)
            except SyntaxError as e:
                problems.append(f"{rel}: does not parse: {e}")
                continue
            for node in ast.walk(tree):
                if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                    length = node.end_lineno - node.lineno + 1
                    if length > MAX_FUNCTION_LINES:
                        problems.append(f"{rel}:{node.lineno}: function {node.name} of {length} lines "
                                        f"(limit {MAX_FUNCTION_LINES})")
            found = dict(hash_comment_history(rel, text))
            for k, message in docstring_history(rel, tree, text.splitlines()):
                found.setdefault(k, message)
            problems.extend(found[k] for k in sorted(found))
        elif is_hash_commented(rel):
            problems.extend(message for _, message in hash_comment_history(rel, text))
    for p in problems:
        print(p)
    print(f"structure: {len(problems)} violation(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "."))
