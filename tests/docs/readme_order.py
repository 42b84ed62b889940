"""The README's commands in the order a newcomer meets them, from a clean clone of this
repository, reusing the project's build (seconds, not a second build):

1. The two commands: `bash tools/demo.sh` configures build/, builds only its own targets
   (`--target` in its cmake --build line) and then runs; CI runs it itself (.ci/run). Here its
   configure and build steps are run on BUILD (nothing to build when built), and the build's own
   description (CMake's file API, asked for by this script) must show that
   `cmake --install` needs nothing else: every install rule of a target that is not OPTIONAL
   installs one of the demo's targets or a target they depend on. (The bug of issue 29:
   `cmake --install build` after the demo failed, its Python module not built.)
2. C++: `cmake --install BUILD --prefix PREFIX` (the README's `cmake --install build`, with a
   prefix), then the README's C++ example (docs/examples/first_query.cpp of the clone) built as a
   user's project with find_package(exactccd) against PREFIX and run.
3. Python: the README's install commands are run by tools/test_pip_install.sh (a fresh virtual
   environment and pip install from a copy of the checkout; tools/test.sh runs it).
4. The command line: docs/examples/cli.sh in the clone with PREFIX/bin on PATH.

Usage: python3 tests/docs/readme_order.py SOURCE_DIR BUILD_DIR WORK_DIR"""

import json
import os
import pathlib
import re
import shutil
import subprocess
import sys
import time

EXPECTED_CPP = "hit 1, toi [0.5, 0.5], within 0.25 from [0.375, 0.375]\n"
CONSUMER = """cmake_minimum_required(VERSION 3.20)
project(readme_first_query LANGUAGES CXX)
find_package(exactccd CONFIG REQUIRED)
add_executable(first_query {source})
target_compile_features(first_query PRIVATE cxx_std_17)
target_link_libraries(first_query PRIVATE exactccd::exactccd)
"""


def run(cmd, **kw):
    """Runs cmd; on failure prints its output and raises."""
    r = subprocess.run(cmd, capture_output=True, text=True, **kw)
    if r.returncode != 0:
        raise SystemExit(f"readme_order: `{' '.join(map(str, cmd))}` failed ({r.returncode}):\n{r.stdout}\n{r.stderr}")
    return r.stdout


def demo_targets(source):
    """The targets tools/demo.sh builds (its `cmake --build build ... --target A B` line)."""
    text = (source / "tools" / "demo.sh").read_text(encoding="utf-8")
    found = re.search(r"^cmake --build build\b.*--target ((?:[\w.-]+ ?)+)$", text, re.M)
    if not found:
        raise SystemExit("readme_order: no `cmake --build build ... --target ...` line in tools/demo.sh")
    return found[1].split()


def installs_beyond(build, targets):
    """The non-optional install rules of targets that the build of `targets` does not build
    (CMake's file API, codemodel v2: each directory's installers, each target's dependencies)."""
    reply = build / ".cmake" / "api" / "v1" / "reply"
    index = json.loads(max(reply.glob("index-*.json")).read_text())
    response = index["reply"]["client-exactccd"]["query.json"]["responses"][0]
    codemodel = json.loads((reply / response["jsonFile"]).read_text())
    config = codemodel["configurations"][0]
    by_name = {t["name"]: t["id"] for t in config["targets"]}
    deps = {t["id"]: [d["id"] for d in json.loads((reply / t["jsonFile"]).read_text()).get("dependencies", [])]
            for t in config["targets"]}
    built, todo = set(), [by_name[t] for t in targets]
    while todo:
        t = todo.pop()
        if t not in built:
            built.add(t)
            todo += deps[t]
    missing = []
    for directory in config["directories"]:
        for installer in json.loads((reply / directory["jsonFile"]).read_text()).get("installers", []):
            if installer["type"] == "target" and not installer.get("isOptional") and installer["targetId"] not in built:
                missing.append(installer["targetId"].split("::")[0])
    return missing


def main(source, build, work):
    t0 = time.monotonic()
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    clone = work / "clone"
    run(["git", "clone", "-q", str(source), str(clone)])
    print(f"[{time.monotonic() - t0:.1f} s] a clean clone: {clone}")

    targets = demo_targets(clone)
    query = build / ".cmake" / "api" / "v1" / "query" / "client-exactccd" / "query.json"
    query.parent.mkdir(parents=True, exist_ok=True)
    query.write_text('{"requests": [{"kind": "codemodel", "version": 2}]}\n')
    run(["cmake", "-S", str(source), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release"])  # the demo's steps
    run(["cmake", "--build", str(build), "--target", *targets])
    missing = installs_beyond(build, targets)
    if missing:
        raise SystemExit(f"readme_order: `cmake --install` after `bash tools/demo.sh` needs targets the demo does not "
                         f"build ({', '.join(missing)}): build them in the demo or install them OPTIONAL")
    print(f"[{time.monotonic() - t0:.1f} s] the demo's build ({' '.join(targets)}) is all `cmake --install` needs")

    prefix = work / "prefix"
    run(["cmake", "--install", str(build), "--prefix", str(prefix)])
    consumer = work / "cpp"
    consumer.mkdir()
    example = (clone / "docs" / "examples" / "first_query.cpp").as_posix()
    (consumer / "CMakeLists.txt").write_text(CONSUMER.format(source=example))
    run(["cmake", "-S", str(consumer), "-B", str(consumer / "build"), "-DCMAKE_BUILD_TYPE=Release",
         f"-DCMAKE_PREFIX_PATH={prefix}"])
    run(["cmake", "--build", str(consumer / "build")])
    out = run([str(consumer / "build" / "first_query")])
    if out != EXPECTED_CPP:
        raise SystemExit(f"readme_order: the C++ example printed {out!r}, not {EXPECTED_CPP!r}")
    print(f"[{time.monotonic() - t0:.1f} s] cmake --install, then the C++ example against the prefix: {out.strip()}")

    env = dict(os.environ, PATH=f"{prefix / 'bin'}:{os.environ['PATH']}")
    out = run(["bash", "-euo", "pipefail", "docs/examples/cli.sh"], cwd=clone, env=env)
    # The output docs.example_cli expects (tests/CMakeLists.txt).
    expected = r"total .*\ntotal [^\n]*\n1 [0-9.e-]+ [0-9.e-]+\n1 [^\n]*\n1 [^\n]*\nvertices .*candidates "
    if not re.search(expected, out, re.S):
        raise SystemExit(f"readme_order: unexpected output of docs/examples/cli.sh:\n{out}")
    print(f"[{time.monotonic() - t0:.1f} s] the command lines with the installed exactccd on PATH")
    shutil.rmtree(work)
    return 0


if __name__ == "__main__":
    sys.exit(main(pathlib.Path(sys.argv[1]).resolve(), pathlib.Path(sys.argv[2]).resolve(),
                  pathlib.Path(sys.argv[3]).resolve()))
