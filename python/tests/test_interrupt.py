"""Ctrl-C in long calls: a Python process running a long batch call, a long scene call or a
long SceneBroadPhase query gets SIGINT (what Ctrl-C sends) half a second into the call; it must
raise KeyboardInterrupt within about a second, well before the call would have finished
(estimated in the same process from the same call on a twentieth of the work), with no thread
of the call left running: the only threads left besides the interpreter's are its helper (kept
for its next long call) and oneTBB's idle workers (kept for the next call: at most one per core
but one), which use no CPU once settled (conftest.IDLE_*)."""

import os
import pathlib
import signal
import subprocess
import sys
import time

import pytest
from conftest import IDLE_CPU_S, IDLE_SETTLE_S, IDLE_WINDOW_S

CHILD = r'''
import os, sys, time
import numpy as np
import exactccd

what = sys.argv[1]
rng = np.random.default_rng(3)

def soup(n):
    """n small random triangles moving in a cube of volume n / 20000: a fixed density, so that
    the work grows linearly with n (the estimate from n / 20 holds)."""
    c = rng.random((n, 1, 3)) * (n / 20000) ** (1 / 3)
    V0 = (c + rng.uniform(-0.02, 0.02, (n, 3, 3))).reshape(-1, 3)
    V1 = V0 + np.repeat(rng.uniform(-0.05, 0.05, (n, 3)), 3, axis=0)
    return V0, V1, np.arange(3 * n).reshape(-1, 3)

if what == "batch":
    base = np.load(sys.argv[2])
    small = np.tile(base, (max(1, 100000 // len(base)), 1, 1))
    big = np.tile(small, (20, 1, 1))
    call = lambda q: exactccd.vertex_face_toi(q, min_distance=1e-3, threads=2)
    args_small, args_big = (small,), (big,)
elif what == "rigid_batch":
    base = np.load(sys.argv[2])
    # The slowest bundled rigid set (about 20 us per query on 2 threads): a twentieth of the call
    # takes about 0.2 s, so the whole call several seconds.
    small = np.tile(base, (max(1, 10000 // len(base)), 1))
    big = np.tile(small, (20, 1))
    call = lambda q: exactccd.rigid_edge_edge_toi(q, threads=2)
    args_small, args_big = (small,), (big,)
elif what == "scene":
    n = int(sys.argv[2])
    small, big = soup(n // 20), soup(n)
    call = lambda s: exactccd.find_collisions(*s, threads=2)
    args_small, args_big = (small,), (big,)
else:  # the broad phase kept across a line search, then its narrow phase
    n = int(sys.argv[2])
    small, big = soup(n // 20), soup(n)
    bps = exactccd.SceneBroadPhase(*small, threads=2), exactccd.SceneBroadPhase(*big, threads=2)
    call = lambda bp: bp.find_collisions()
    args_small, args_big = (bps[0],), (bps[1],)

t = time.monotonic()
call(*args_small)
estimate = 20 * (time.monotonic() - t)
print("estimate", estimate, flush=True)
t = time.monotonic()
try:
    call(*args_big)
    print("finished", time.monotonic() - t, flush=True)
except KeyboardInterrupt:
    stopped = time.monotonic() - t
    time.sleep(@SETTLE@)  # oneTBB's workers spin a little before they sleep
    cpu = time.process_time()  # every thread of the process
    time.sleep(@WINDOW@)
    busy = time.process_time() - cpu
    print("interrupted", stopped, len(os.listdir("/proc/self/task")), busy, len(os.sched_getaffinity(0)), flush=True)
'''


def run_and_interrupt(tmp_path, *args):
    script = tmp_path / "child.py"
    script.write_text(CHILD.replace("@SETTLE@", str(IDLE_SETTLE_S)).replace("@WINDOW@", str(IDLE_WINDOW_S)))
    child = subprocess.Popen([sys.executable, str(script), *args], stdout=subprocess.PIPE, text=True,
                             env=dict(os.environ, PYTHONUNBUFFERED="1"))
    first = child.stdout.readline().split()
    assert first and first[0] == "estimate", first
    estimate = float(first[1])
    time.sleep(0.5)
    sent = time.monotonic()
    child.send_signal(signal.SIGINT)
    out, _ = child.communicate(timeout=120)
    exited = time.monotonic() - sent
    words = out.split()
    return estimate, exited, words


def check(estimate, exited, words):
    assert words and words[0] == "interrupted", (words, estimate)
    call_time, threads_left, busy, cores = float(words[1]), int(words[2]), float(words[3]), int(words[4])
    assert threads_left <= cores + 1, threads_left  # the interpreter's, its helper, oneTBB's idle workers
    assert busy < IDLE_CPU_S, busy  # CPU seconds of the whole process once settled
    # Within about a second of the signal (the interpreter polls every 0.1 s; the workers stop
    # between chunks), allowing for a loaded machine; the call would have taken much longer.
    # (exited also counts the child's idle measurement after the interrupt.)
    assert exited < 1.5 + IDLE_SETTLE_S + IDLE_WINDOW_S, exited
    assert call_time < 0.5 + 2.0, call_time
    assert estimate > 3 * call_time, (estimate, call_time)


def test_ctrl_c_stops_a_long_batch_call(tmp_path):
    import numpy as np
    from conftest import DATA, read_queries

    q, _ = read_queries(DATA / "families" / "families-vertex-face.csv", "vertex_face")
    np.save(tmp_path / "base.npy", q)
    check(*run_and_interrupt(tmp_path, "batch", str(tmp_path / "base.npy")))


def test_ctrl_c_stops_a_long_scene_call(tmp_path):
    check(*run_and_interrupt(tmp_path, "scene", "200000"))


def test_ctrl_c_stops_a_long_broad_phase_query(tmp_path):
    check(*run_and_interrupt(tmp_path, "broad_phase", "200000"))


def test_ctrl_c_stops_a_long_rigid_batch_call(tmp_path):
    import numpy as np
    from conftest import DATA

    path = DATA / "rigid" / "rigid-families-edge-edge.csv"
    rows = [line.split(",") for line in open(path, encoding="utf-8") if line.strip() and not line.startswith("#")]
    np.save(tmp_path / "base.npy", np.array([[float.fromhex(x) for x in r[:40]] for r in rows], dtype=np.float64))
    check(*run_and_interrupt(tmp_path, "rigid_batch", str(tmp_path / "base.npy")))
