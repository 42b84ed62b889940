#!/usr/bin/env python3
"""CI runs every registered test: the set tools/test.sh runs equals the set registered.

tools/test.sh records, for each ctest pass, the tests its build registers and those the pass
runs (`ctest --show-only=json-v1`, without and with the pass's selection), as
SETS_DIR/<pass>.registered.json and SETS_DIR/<pass>.ran.json. A registered test is run when
some pass ran it by name (GoogleTest's parameter comment left out: it may hold addresses); or,
when the pip pass ran (--pip-pass), when it is a pytest run of one file of the suite that pass
runs whole (python/tests) with no environment beyond what that pass sets itself (a test with
its own setting, such as EXACTCCD_SIMD, is not: the pip pass runs pytest without it); or when
EXEMPT names it with a reason. Exits 1 listing every other one.

usage: check_test_sets.py SETS_DIR [--pip-pass PYTEST_DIR]
"""
import json
import pathlib
import re
import sys

# What the pip pass (tools/test_pip_install.sh) sets for its pytest run: the installed package
# in place of PYTHONPATH, the same programs and data (EXACTCCD_SAMPLE_QUERIES_DIR: its default,
# the shared sample beside the checkout), the same plotting backend and bytecode setting.
PIP_PASS_ENVIRONMENT = {"PYTHONPATH", "EXACTCCD_CLI", "EXACTCCD_DATA", "EXACTCCD_TEST_DATA",
                        "EXACTCCD_SAMPLE_QUERIES_DIR", "EXACTCCD_FALLING_CLOTH_CPP", "MPLBACKEND",
                        "PYTHONDONTWRITEBYTECODE"}

# Registered tests that no CI pass runs, each with its reason (a pattern on the test's name).
EXEMPT = {}


# GoogleTest's discovery appends "  # GetParam() = ..." to a parameterised test's name; for a
# parameter it cannot print, that is the parameter's bytes, pointers among them, which differ
# from one build to the next. A test is its name without that comment.
PARAMETER_COMMENT = re.compile(r"\s+# GetParam\(\) = .*$")


def test_name(name):
    return PARAMETER_COMMENT.sub("", name)


def tests_of(path):
    return {test_name(t["name"]): t for t in json.loads(path.read_text(encoding="utf-8")).get("tests", [])}


def environment_keys(test):
    for prop in test.get("properties", []):
        if prop.get("name") == "ENVIRONMENT":
            return {entry.split("=", 1)[0] for entry in prop.get("value", [])}
    return set()


def pip_pass_runs(test, pytest_dir):
    """True when the pip pass's whole-suite pytest run covers this test."""
    command = test.get("command") or []
    if "pytest" not in command:
        return False
    files = [pathlib.Path(c) for c in command if c.endswith(".py")]
    if len(files) != 1 or files[0].parent.resolve() != pytest_dir.resolve():
        return False
    return environment_keys(test) <= PIP_PASS_ENVIRONMENT


def uncovered(sets_dir, pytest_dir):
    registered, ran = {}, set()
    for path in sorted(sets_dir.glob("*.registered.json")):
        registered.update(tests_of(path))
    for path in sorted(sets_dir.glob("*.ran.json")):
        ran.update(tests_of(path))
    missing = []
    for name, test in sorted(registered.items()):
        if name in ran or (pytest_dir and pip_pass_runs(test, pytest_dir)):
            continue
        if any(re.fullmatch(pattern, name) for pattern in EXEMPT):
            continue
        missing.append(name)
    return registered, ran, missing


def main():
    args = sys.argv[1:]
    if len(args) not in (1, 3) or (len(args) == 3 and args[1] != "--pip-pass"):
        print(__doc__, file=sys.stderr)
        return 2
    sets_dir = pathlib.Path(args[0])
    pytest_dir = pathlib.Path(args[2]) if len(args) == 3 else None
    if not any(sets_dir.glob("*.registered.json")):
        print(f"check_test_sets: no recorded pass in {sets_dir}")
        return 2
    registered, ran, missing = uncovered(sets_dir, pytest_dir)
    for name in missing:
        print(f"registered but run by no CI pass: {name}")
    for pattern, reason in EXEMPT.items():
        print(f"not run by CI: {pattern}: {reason}")
    print(f"check_test_sets: {len(registered)} registered, {len(ran)} run by ctest passes, "
          f"{len(missing)} run by none")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
