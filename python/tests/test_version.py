"""One version everywhere: exactccd.__version__ (the library's exactccd_version()), the
package metadata when installed with pip (importlib.metadata), `exactccd --version`, and
CMakeLists.txt's project(VERSION). With EXACTCCD_EXPECT_INSTALLED=DIR (tools/test_pip_install.sh),
also that the module imported is the one installed under DIR, not the build tree."""

import importlib.metadata
import os
import pathlib
import re
import subprocess

import pytest

import exactccd
from conftest import ROOT, cli


def cmake_version():
    text = (ROOT / "CMakeLists.txt").read_text(encoding="utf-8")
    return re.search(r"project\(exactccd VERSION ([0-9.]+)", text)[1]


def test_module_version_is_the_project_version():
    assert re.fullmatch(r"[0-9]+\.[0-9]+\.[0-9]+", exactccd.__version__)
    assert exactccd.__version__ == cmake_version()


def test_cli_version():
    exe = cli()
    if exe is None:
        pytest.skip("the exactccd CLI is not built (set EXACTCCD_CLI)")
    out = subprocess.run([exe, "--version"], check=True, capture_output=True, text=True).stdout
    lines = out.splitlines()
    assert lines[0] == f"exactccd {exactccd.__version__}", out
    # The SIMD level of the batched stages, and why (docs/performance.md, "Batched stages").
    assert len(lines) == 2 and lines[1].split()[:2] in (["simd:", "sse2"], ["simd:", "avx2"], ["simd:", "avx512"]), out


def test_installed_package_metadata():
    where = os.environ.get("EXACTCCD_EXPECT_INSTALLED")
    if not where:
        pytest.skip("not an installed package (tools/test_pip_install.sh sets EXACTCCD_EXPECT_INSTALLED)")
    assert pathlib.Path(exactccd.__file__).resolve().is_relative_to(pathlib.Path(where).resolve()), exactccd.__file__
    assert importlib.metadata.version("exactccd") == exactccd.__version__
    files = [str(f) for f in importlib.metadata.files("exactccd")]
    assert any(f.startswith("exactccd/_exactccd") and f.endswith(".so") for f in files), files
    assert "exactccd/__init__.pyi" in files and "exactccd/py.typed" in files
