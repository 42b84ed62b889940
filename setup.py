"""Builds the Python package exactccd with the project's CMake build (pyproject.toml; docs/python.md).

`pip install --no-build-isolation .` (or `pip wheel --no-build-isolation .`) runs setuptools,
which calls CMakeBuild below: it configures the project in the build directory with the
interpreter running pip (its NumPy and development files; the module is built for it), builds the
extension target only (the library and the module: no tests, benchmarks or command-line program)
and copies it into the package. The version is CMakeLists.txt's project(VERSION), the one version
of the C++ package, `exactccd --version`, exactccd_version() and exactccd.__version__.

Environment: CMAKE_BUILD_PARALLEL_LEVEL (default: every CPU) sets the build's parallel jobs;
EXACTCCD_CMAKE_ARGS (space-separated) adds configure arguments.
"""

import os
import pathlib
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


def project_version():
    """The version in CMakeLists.txt's project() call."""
    text = (ROOT / "CMakeLists.txt").read_text(encoding="utf-8")
    found = re.search(r"project\(\s*exactccd\s+VERSION\s+([0-9]+\.[0-9]+\.[0-9]+)", text)
    if not found:
        raise RuntimeError("CMakeLists.txt: no project(exactccd VERSION x.y.z)")
    return found.group(1)


def require_wheel_support():
    """Stops with a message naming the interpreter and the fix when pip asks this interpreter's
    setuptools for a wheel (or its metadata: dist_info runs bdist_wheel) and it cannot make one:
    setuptools before 70.1 takes bdist_wheel from the separate `wheel` package, without which
    pip reports only `error: invalid command 'bdist_wheel'` (a virtual environment made without
    --system-site-packages has setuptools but no wheel)."""
    if not {"bdist_wheel", "dist_info", "editable_wheel"} & set(sys.argv[1:]):
        return
    try:
        import setuptools.command.bdist_wheel  # noqa: F401  (setuptools >= 70.1)
        return
    except ImportError:
        pass
    try:
        import wheel.bdist_wheel  # noqa: F401
    except ImportError:
        import setuptools
        sys.exit(
            f"exactccd: {sys.executable} (Python {sys.version.split()[0]}, setuptools {setuptools.__version__}) "
            "cannot build a wheel: the `wheel` package is missing for this interpreter, and pip installs "
            "through a wheel. Fix: on Debian, `sudo apt-get install python3-wheel` (tools/install-deps.sh "
            "installs it) and make the virtual environment with `python3 -m venv --system-site-packages` "
            "as docs/python.md does; in a virtual environment of its own, `python -m pip install wheel`; "
            "or drop --no-build-isolation so that pip fetches setuptools and wheel (needs a package index).")


class CMakeExtension(Extension):
    """The compiled module exactccd._exactccd, built by CMake (no sources for setuptools)."""

    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    """Configures and builds the CMake target exactccd_python, then copies the module."""

    def build_extension(self, ext):
        target = pathlib.Path(self.get_ext_fullpath(ext.name)).resolve()
        build = pathlib.Path(self.build_temp).resolve() / "cmake"
        configure = [
            "cmake", "-S", str(ROOT), "-B", str(build),
            "-DCMAKE_BUILD_TYPE=Release",
            f"-DPython3_EXECUTABLE={sys.executable}",
            "-DEXACTCCD_BUILD_PYTHON=ON",
            "-DEXACTCCD_BUILD_TESTS=OFF",
            "-DEXACTCCD_BUILD_BENCHMARKS=OFF",
        ] + os.environ.get("EXACTCCD_CMAKE_ARGS", "").split()
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 2)
        subprocess.run(configure, check=True)
        subprocess.run(["cmake", "--build", str(build), "--target", "exactccd_python", "-j", jobs], check=True)
        built = sorted((build / "python" / "exactccd").glob("_exactccd*.so"))
        if len(built) != 1:
            raise RuntimeError(f"expected one built module in {build / 'python' / 'exactccd'}, found {built}")
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[0], target)


require_wheel_support()
setup(
    version=project_version(),
    packages=["exactccd"],
    package_dir={"": "python"},
    package_data={"exactccd": ["__init__.pyi", "py.typed"]},
    ext_modules=[CMakeExtension("exactccd._exactccd")],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
)
