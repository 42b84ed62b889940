#!/usr/bin/env python3
"""tools/check_test_sets.py decides as it says, on made-up passes: a test no pass runs fails it,
a pytest file run with a setting of its own (EXACTCCD_SIMD) is not covered by the pip pass, one
with only the pip pass's settings is, and without the pip pass neither is.

usage: check_test_sets_cases.py REPOSITORY_ROOT
"""
import json
import pathlib
import subprocess
import sys
import tempfile


def test(name, command, environment=()):
    t = {"name": name, "command": command}
    if environment:
        t["properties"] = [{"name": "ENVIRONMENT", "value": list(environment)}]
    return t


def write(folder, name, tests):
    (folder / name).write_text(json.dumps({"kind": "ctestInfo", "tests": tests}), encoding="utf-8")


def check(script, registered, ran, pip_dir):
    with tempfile.TemporaryDirectory() as work:
        folder = pathlib.Path(work)
        write(folder, "release.registered.json", registered)
        write(folder, "release.ran.json", ran)
        args = [sys.executable, str(script), str(folder)] + (["--pip-pass", str(pip_dir)] if pip_dir else [])
        return subprocess.run(args, capture_output=True, text=True).returncode


def main():
    root = pathlib.Path(sys.argv[1])
    script = root / "tools" / "check_test_sets.py"
    pytests = root / "python" / "tests"
    unit = test("unit.a", ["/bin/true"])
    plain = test("python.test_batch", ["python3", "-m", "pytest", "-q", str(pytests / "test_batch.py")],
                 ["PYTHONPATH=/x", "EXACTCCD_CLI=/y", "MPLBACKEND=Agg"])
    forced = test("python.test_batch_simd_sse2", ["python3", "-m", "pytest", "-q", str(pytests / "test_batch.py")],
                  ["PYTHONPATH=/x", "EXACTCCD_SIMD=sse2"])
    cases = [
        ("every test ran", [unit, plain], [unit, plain], None, 0),
        ("a test no pass ran", [unit, plain], [plain], pytests, 1),
        ("a pytest file left to the pip pass", [unit, plain], [unit], pytests, 0),
        ("a pytest file with its own setting left to the pip pass", [unit, plain, forced], [unit], pytests, 1),
        ("a pytest file left to a pip pass that did not run", [unit, plain], [unit], None, 1),
    ]
    failed = 0
    for what, registered, ran, pip_dir, expected in cases:
        got = check(script, registered, ran, pip_dir)
        print(f"{'ok' if got == expected else 'WRONG'}: {what}: exit {got} (expected {expected})")
        failed += got != expected
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
