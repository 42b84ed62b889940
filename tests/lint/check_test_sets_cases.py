#!/usr/bin/env python3
"""tools/check_test_sets.py decides as it says, on made-up passes: a test no pass runs fails it,
a pytest file run with a setting of its own (EXACTCCD_SIMD) is not covered by the pip pass, one
with only the pip pass's settings is, and without the pip pass neither is; a parameterised
GoogleTest case is the same test whatever address its parameter comment shows.

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


def check(script, registered, ran, pip_dir, sanitizers=None):
    """Exit code of the script on a release pass (and a sanitizers pass: (registered, ran))."""
    with tempfile.TemporaryDirectory() as work:
        folder = pathlib.Path(work)
        write(folder, "release.registered.json", registered)
        write(folder, "release.ran.json", ran)
        if sanitizers:
            write(folder, "sanitizers.registered.json", sanitizers[0])
            write(folder, "sanitizers.ran.json", sanitizers[1])
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
    # A parameterised GoogleTest case as each build names it: its parameter's bytes hold an address.
    param = "Env/EveryEnvironment.Queries/upward"
    param_release = test(param + "  # GetParam() = 16-byte object <20-39 09-49 31-56 00-00>", ["/bin/t"])
    param_asan = test(param + "  # GetParam() = 16-byte object <60-F7 B5-30 4E-56 00-00>", ["/bin/t"])
    other_asan = test("Env/EveryEnvironment.Queries/downward  # GetParam() = 16-byte object <60-F7>", ["/bin/t"])
    cases = [
        ("every test ran", [unit, plain], [unit, plain], None, 0),
        ("a parameterised case skipped by the sanitizers and run by release under another comment",
         [unit, param_release], [unit, param_release], None, 0, ([unit, param_asan], [unit])),
        ("a parameterised case no pass ran", [unit], [unit], None, 1, ([unit, other_asan], [unit])),
        ("a test no pass ran", [unit, plain], [plain], pytests, 1),
        ("a pytest file left to the pip pass", [unit, plain], [unit], pytests, 0),
        ("a pytest file with its own setting left to the pip pass", [unit, plain, forced], [unit], pytests, 1),
        ("a pytest file left to a pip pass that did not run", [unit, plain], [unit], None, 1),
    ]
    failed = 0
    for what, registered, ran, pip_dir, expected, *sanitizers in cases:
        got = check(script, registered, ran, pip_dir, *sanitizers)
        print(f"{'ok' if got == expected else 'WRONG'}: {what}: exit {got} (expected {expected})")
        failed += got != expected
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
