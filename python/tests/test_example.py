"""The example script runs headless on a bundled scene and writes its PNG."""

import os
import subprocess
import sys

import pytest

from conftest import DATA, ROOT

pytest.importorskip("matplotlib")


def test_earliest_contact_example(tmp_path):
    out = tmp_path / "contact.png"
    env = dict(os.environ, MPLBACKEND="Agg")
    script = ROOT / "python" / "examples" / "earliest_contact.py"
    run = subprocess.run([sys.executable, str(script), str(DATA / "scenes" / "fold" / "T0.obj"),
                          str(DATA / "scenes" / "fold" / "T1.obj"), "--out", str(out)],
                         env=env, capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    assert "earliest contact" in run.stdout and "0.845057825494" in run.stdout
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
