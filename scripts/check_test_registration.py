#!/usr/bin/env python3
"""Checks that a build registers every test the sources define, each with one known label.

    python3 scripts/check_test_registration.py BUILD_DIR

A test folder dropped from the build (a missing dependency such as VTK, RADIOSITY_TESTS=OFF
cached in the build directory, a CMakeLists that stops adding a folder) or a renamed label would
otherwise let ctest pass on fewer tests than the project has. Sources are read as text:
  - every TEST / TEST_F / TEST_P in tests/**/*.cpp must be run by a registered test: one whose
    --gtest_filter is `Suite.Name` or `Prefix/Suite.Name/Param` (gtest_discover_tests, with any
    TEST_PREFIX), or one that runs the executable built from its file whole (add_test);
  - every `add_test(NAME name` in tests/**/CMakeLists.txt must be registered (`${var}` in a name
    matches any text, and at least one registered test must match it);
  - every registered test carries exactly one of the labels unit, integration, slow.
Exits 1 with the missing tests, grouped by folder, or the mislabelled ones; prints one summary
line otherwise.
"""
import json
import re
import subprocess
import sys
from collections import defaultdict
from pathlib import Path

LABELS = {"unit", "integration", "slow"}
TEST_MACRO = re.compile(r"^\s*(TEST|TEST_F|TEST_P)\(\s*(\w+)\s*,\s*(\w+)\s*\)", re.MULTILINE)
ADD_TEST = re.compile(r"add_test\(\s*NAME\s+([^\s)]+)")
ADD_EXECUTABLE = re.compile(r"add_executable\(\s*(\w+)\s+([^)]*)\)")


def registered_tests(build: Path):
    """Each registered test's labels, the GoogleTest filters the registered tests run, and the
    executables run whole (no filter: every test in their sources runs)."""
    out = subprocess.run(["ctest", "--test-dir", str(build), "--show-only=json-v1"],
                         check=True, capture_output=True, text=True).stdout
    tests, filters, whole = {}, set(), set()
    for test in json.loads(out).get("tests", []):
        labels = []
        for prop in test.get("properties", []):
            if prop.get("name") == "LABELS":
                labels = prop.get("value", [])
        tests[test["name"]] = labels
        command = test.get("command", [])
        given = [a[len("--gtest_filter="):] for a in command if a.startswith("--gtest_filter=")]
        if given:
            filters.update(given)
        else:
            whole.update(Path(a).name for a in command)
    return tests, filters, whole


def test_executables(tests_dir: Path):
    """Source file (path) -> the test executable built from it, from add_executable(...)."""
    built = {}
    for lists in tests_dir.rglob("CMakeLists.txt"):
        for name, sources in ADD_EXECUTABLE.findall(lists.read_text()):
            for source in sources.split():
                if source.endswith(".cpp"):
                    built[(lists.parent / source).resolve()] = name
    return built


def source_tests(tests_dir: Path):
    found = []  # (folder, file, suite, name)
    for cpp in sorted(tests_dir.rglob("*.cpp")):
        text = cpp.read_text(errors="replace")
        for kind, suite, name in TEST_MACRO.findall(text):
            found.append((cpp.relative_to(tests_dir).parts[0], cpp, suite, name, kind))
    return found


def cmake_test_names(tests_dir: Path):
    found = []  # (folder, CMakeLists, pattern)
    for lists in sorted(tests_dir.rglob("CMakeLists.txt")):
        for name in ADD_TEST.findall(lists.read_text()):
            pattern = "".join(".+" if part.startswith("${") else re.escape(part)
                              for part in re.split(r"(\$\{[^}]*\})", name) if part)
            found.append((lists.relative_to(tests_dir).parts[0], lists, name,
                          re.compile(pattern + r"\Z")))
    return found


def is_registered(cpp, suite, name, kind, filters, whole, executables):
    if executables.get(cpp.resolve()) in whole:
        return True
    full = f"{suite}.{name}"
    if full in filters:
        return True
    if kind == "TEST_P":  # Prefix/Suite.Name/Param
        return any(f"/{full}/" in f or f.startswith(f"{full}/") or f.endswith(f"/{full}")
                   for f in filters)
    return False


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: check_test_registration.py BUILD_DIR")
    build = Path(sys.argv[1])
    tests_dir = Path(__file__).resolve().parent.parent / "tests"
    if not (build / "CTestTestfile.cmake").exists():
        sys.exit(f"check_test_registration: {build} has no tests (configure it with "
                 "-DRADIOSITY_TESTS=ON)")
    tests, filters, whole = registered_tests(build)
    names = set(tests)
    executables = test_executables(tests_dir)

    missing = defaultdict(list)
    for folder, cpp, suite, name, kind in source_tests(tests_dir):
        if not is_registered(cpp, suite, name, kind, filters, whole, executables):
            missing[folder].append(f"{cpp.name}: {suite}.{name}")
    for folder, lists, name, pattern in cmake_test_names(tests_dir):
        if not any(pattern.match(n) for n in names):
            missing[folder].append(f"CMakeLists.txt: add_test {name}")

    mislabelled = [f"{n}: labels {tests[n] or 'none'}" for n in sorted(names)
                   if len(set(tests[n]) & LABELS) != 1]

    if missing or mislabelled:
        for folder, items in sorted(missing.items()):
            print(f"check_test_registration: tests/{folder}: {len(items)} test(s) defined in the "
                  f"sources but not registered in {build} (was the folder left out of the build, "
                  f"or a dependency such as VTK not found?):", file=sys.stderr)
            for item in items[:10]:
                print(f"  {item}", file=sys.stderr)
            if len(items) > 10:
                print(f"  ... and {len(items) - 10} more", file=sys.stderr)
        if mislabelled:
            print(f"check_test_registration: {len(mislabelled)} test(s) without exactly one of the "
                  f"labels {sorted(LABELS)}:", file=sys.stderr)
            for item in mislabelled[:20]:
                print(f"  {item}", file=sys.stderr)
        sys.exit(1)
    counts = defaultdict(int)
    for labels in tests.values():
        for label in set(labels) & LABELS:
            counts[label] += 1
    print(f"check_test_registration: {len(names)} tests registered in {build}, every source test "
          f"among them (" + ", ".join(f"{counts[l]} {l}" for l in sorted(LABELS)) + ")")


if __name__ == "__main__":
    main()
