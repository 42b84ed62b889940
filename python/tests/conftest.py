"""Shared helpers of the Python module's tests: the bundled data files read in Python (exact
rationals, which are doubles in every bundled file, so float(Fraction) is exact) and the CLI's
answers on them (`exactccd check --answers --toi`), an implementation independent of the module."""

import os
import pathlib
import shutil
import subprocess
from fractions import Fraction

import numpy as np
import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
DATA = pathlib.Path(os.environ.get("EXACTCCD_DATA", ROOT / "data"))
TEST_DATA = pathlib.Path(os.environ.get("EXACTCCD_TEST_DATA", ROOT / "tests" / "data"))

# After a long call is interrupted or its callers stopped: nothing of the call may still run.
# A call still running keeps at least one thread busy (about 1 CPU second per second); idle
# threads (oneTBB's workers, the callers' kept helpers) are blocked and use none, once oneTBB's
# workers have finished the short spin before they sleep. So: wait IDLE_SETTLE_S, then the
# whole process's CPU time over IDLE_WINDOW_S must stay under IDLE_CPU_S, a quarter of one
# busy thread (margin for a loaded machine's accounting; 0.107 s was once seen in the half
# second straight after a stop, with no settling).
IDLE_SETTLE_S = 0.5
IDLE_WINDOW_S = 1.0
IDLE_CPU_S = 0.25

# kind (batch function stem) -> (file-name suffix, CLI --kind, rows per query, coordinates)
KINDS = {
    "vertex_face": ("vertex-face", "vf", 8, 3),
    "edge_edge": ("edge-edge", "ee", 8, 3),
    "point_edge": ("point-edge", "pe", 6, 3),
    "point_point": ("point-point", "pp", 4, 3),
    "edge_edge_2d": ("edge-edge-2d", "ee2", 8, 2),
    "point_edge_2d": ("point-edge-2d", "pe2", 6, 2),
    "point_point_2d": ("point-point-2d", "pp2", 4, 2),
}


def kind_of_file(path):
    """The batch kind of a bundled data file, from its name (longest suffix first)."""
    name = pathlib.Path(path).stem
    for kind, (suffix, *_rest) in sorted(KINDS.items(), key=lambda kv: -len(kv[1][0])):
        if name.endswith(suffix):
            return kind
    raise ValueError(f"no kind for {path}")


def bundled_files():
    """Every bundled query file of data/sim and data/kinds."""
    return sorted((DATA / "sim").glob("*.csv")) + sorted((DATA / "kinds").glob("*.csv"))


def read_queries(path, kind):
    """(q, truth): q an (N, rows, dim) float64 array (exact: every value is a double), truth
    an (N,) bool array."""
    _, _, rows, dim = KINDS[kind]
    values, truth = [], []
    with open(path) as f:
        for line in f:
            line = line.strip()
            if not line:
                continue
            cols = [int(c) for c in line.split(",")]
            assert len(cols) == 2 * dim + 1, (path, line)
            row = []
            for k in range(dim):
                x = Fraction(cols[2 * k], cols[2 * k + 1])
                assert Fraction(float(x)) == x, f"{path}: {x} is not a double"
                row.append(float(x))
            values.append(row)
            truth.append(cols[-1])
    q = np.array(values, dtype=np.float64).reshape(-1, rows, dim)
    return q, np.array(truth[::rows], dtype=bool)


def cli():
    """The exactccd CLI of the build, or None."""
    exe = os.environ.get("EXACTCCD_CLI")
    if exe and os.path.exists(exe):
        return exe
    for candidate in (ROOT / "build" / "exactccd",):
        if candidate.exists():
            return str(candidate)
    return shutil.which("exactccd")


def cli_answers(path, kind, min_distance=None, tmax=None):
    """The CLI's `check --answers --toi` on `path`: (N,) bool answers and (N, 2) TOIs (NaN rows
    where no collision)."""
    exe = cli()
    if exe is None:
        pytest.skip("the exactccd CLI is not built (set EXACTCCD_CLI)")
    cmd = [exe, "check", "--kind", KINDS[kind][1], "--answers", "--toi"]
    if min_distance is not None:
        cmd += ["--min-distance", repr(float(min_distance))]
    if tmax is not None:
        cmd += ["--tmax", repr(float(tmax))]
    out = subprocess.run(cmd + [str(path)], check=True, capture_output=True, text=True).stdout
    answers, tois = [], []
    for line in out.splitlines():
        parts = line.split()
        answers.append(parts[0] == "1")
        tois.append([float(parts[1]), float(parts[2])] if parts[0] == "1" else [np.nan, np.nan])
    return np.array(answers, dtype=bool), np.array(tois, dtype=np.float64).reshape(-1, 2)


SAMPLE_QUERIES = pathlib.Path(os.environ.get("EXACTCCD_SAMPLE_QUERIES_DIR", ROOT.parent / "shared" / "data" / "sample-queries"))


def shared_files():
    """(path, kind) of the shared benchmark sample's query files (none when it is absent)."""
    out = []
    for kind in ("vertex_face", "edge_edge"):
        out += [(p, kind) for p in sorted(SAMPLE_QUERIES.glob(f"**/{KINDS[kind][0]}/*.csv"))]
    return out
