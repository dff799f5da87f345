#!/usr/bin/env python3
"""Checks that docs/architecture.md names only files and code that exist.

    python3 scripts/check_architecture.py [DOC ...]     (default: docs/architecture.md)

The module map is only useful while it is true. Every `backticked` token is read:
  - a path (it has a `/`, or ends in .cpp/.h/.py/.sh/.cmake): it must exist in the tree, as written
    from the repository root, under radiosity/, or (without an extension) as NAME.cpp or NAME.h
    there; a bare file name anywhere in the tree; output files (out/, ../shared/, a build
    directory) are not looked for;
  - a code name (camelCase, PascalCase with a lower-case letter, snake_case with an underscore, or
    A::b; optionally with `()`): each part must occur as a word in the project's source files.
Exits 1 listing each missing name with its line; prints one summary line otherwise.
"""
import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SOURCE_DIRS = ["radiosity", "meshing", "viewer", "bench", "tests", "scripts", "tools", ".ci"]
PATH_SUFFIXES = (".cpp", ".h", ".py", ".sh", ".cmake")
NOT_IN_TREE = ("out/", "../", "build", "/tmp", "http", "$", "~")
CODE_NAME = re.compile(r"^[A-Za-z_]\w*(::~?\w+)*(\(\))?$")


def tracked_files():
    listed = subprocess.run(["git", "-C", str(ROOT), "ls-files"], check=True, capture_output=True,
                            text=True).stdout.split()
    return set(listed)


def source_words():
    words = set()
    for directory in SOURCE_DIRS:
        for path in (ROOT / directory).rglob("*"):
            if path.is_file() and path.suffix in (".cpp", ".h", ".py", ".sh", ".txt", ".cmake", ""):
                try:
                    words.update(re.findall(r"\w+", path.read_text(errors="replace")))
                except OSError:
                    pass
    return words


def path_exists(token, files, folders):
    if "/" not in token:  # a file named within its module's row: anywhere in the tree
        return token in {Path(f).name for f in files}
    token = token.rstrip("/")
    candidates = [token, "radiosity/" + token]
    if not token.endswith(PATH_SUFFIXES):
        candidates += [c + ext for c in candidates[:2] for ext in (".cpp", ".h")]
    return any(c in files or c in folders for c in candidates)


def is_code_name(token):
    if not CODE_NAME.match(token):
        return False
    bare = token.removesuffix("()")
    if "::" in bare:
        return True
    if "_" in bare.strip("_") and bare.lower() == bare:
        return True  # snake_case
    return bool(re.search(r"[a-z][A-Z]", bare)) or bool(re.match(r"[A-Z][a-z]+[A-Z]", bare))


def main():
    docs = [Path(a) for a in sys.argv[1:]] or [ROOT / "docs/architecture.md"]
    files = tracked_files()
    folders = {str(Path(f).parent) for f in files}
    folders |= {str(p) for f in files for p in Path(f).parents}
    words = source_words()
    missing, checked = [], 0
    for doc in docs:
        for number, line in enumerate(doc.read_text().splitlines(), 1):
            for token in re.findall(r"`([^`\s][^`]*)`", line):
                token = token.strip()
                if " " in token or token.startswith("-") or token == "/":
                    continue  # a command line, an option, a formula
                if "/" in token or token.endswith(PATH_SUFFIXES):
                    if token.startswith(NOT_IN_TREE) or "*" in token or "<" in token:
                        continue
                    if token.startswith("radiosity::"):
                        continue
                    checked += 1
                    if not path_exists(token, files, folders):
                        missing.append(f"{doc.name}:{number}: no file or folder `{token}`")
                elif is_code_name(token):
                    checked += 1
                    parts = [p for p in re.split(r"::|\(\)", token) if p]
                    absent = [p for p in parts if p.lstrip("~") not in words]
                    if absent:
                        missing.append(f"{doc.name}:{number}: `{token}` is not in the sources")
    if missing:
        print("check_architecture: the module map names what the code does not have:",
              file=sys.stderr)
        for item in missing:
            print("  " + item, file=sys.stderr)
        sys.exit(1)
    print(f"check_architecture: {checked} names in {', '.join(d.name for d in docs)} all exist")


if __name__ == "__main__":
    main()
