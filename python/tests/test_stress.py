"""Many callers at once: 8 Python threads mixing batch queries, scene functions, the functions
over a caller's candidates and SceneBroadPhase line searches (each thread its own broad phase,
and one shared by all) on shared read-only inputs get exactly the single-threaded answers; and
Ctrl-C (SIGINT) sent to a process running such a mix ends it promptly with no caller thread left
and nothing of a call still running (oneTBB's idle workers, at most one per core but one, stay
for the next call and use no CPU).

The library's calls release the GIL, so the 8 callers run at once in the library, each call on
its own worker threads (`threads` 1, 2 or 0 = all cores, mixed)."""

import os
import signal
import subprocess
import sys
import threading
import time

import numpy as np

import exactccd
from conftest import DATA, IDLE_CPU_S, IDLE_SETTLE_S, IDLE_WINDOW_S, read_queries

CALLERS = 8


def inputs():
    """The shared read-only inputs: query batches of every 3D kind, the cloth scene's step."""
    batches = {}
    for kind, name in (("vertex_face", "sim/sim-cloth-vertex-face.csv"), ("edge_edge", "sim/sim-fold-edge-edge.csv"),
                       ("point_edge", "kinds/kinds-fold-point-edge.csv"),
                       ("point_point", "kinds/kinds-fold-point-point.csv")):
        q, _ = read_queries(DATA / name, kind)
        batches[kind] = np.tile(q, (12, 1, 1))                    # about 5 000 rows: above 4096, interruptible
    V0, F = exactccd.read_mesh(DATA / "scenes" / "cloth" / "T0.obj")
    V1, _ = exactccd.read_mesh(DATA / "scenes" / "cloth" / "T1.obj")
    for a in (*batches.values(), V0, V1, F):
        a.setflags(write=False)
    return batches, V0, V1, F


def tasks(batches, V0, V1, F, shared):
    """(name, call) pairs; call(threads) gives a value comparable with ==, through `canonical`."""
    out = []
    for kind, q in batches.items():
        for d, tmax in ((0.0, 1.0), (1e-3, 0.75)):
            out.append((f"{kind}_toi d={d}", lambda t, kind=kind, q=q, d=d, tmax=tmax:
                        getattr(exactccd, f"{kind}_toi")(q, min_distance=d, tmax=tmax, threads=t)))
    for d in (0.0, 1e-3):
        kw = dict(min_distance=d)
        out += [
            (f"find_collisions d={d}", lambda t, kw=kw: exactccd.find_collisions(V0, V1, F, threads=t, **kw)),
            (f"earliest_toi d={d}", lambda t, kw=kw: exactccd.earliest_toi(V0, V1, F, threads=t, **kw)),
            (f"is_collision_free d={d}", lambda t, kw=kw: exactccd.is_collision_free(V0, V1, F, threads=t, **kw)),
            (f"max_collision_free_step d={d}",
             lambda t, kw=kw: exactccd.max_collision_free_step(V0, V1, F, threads=t, **kw)),
        ]
    vf = np.array([[v, *F[f]] for v, f in shared.candidates["vertex_face"]], dtype=np.int64).reshape(-1, 4)
    out.append(("candidates_find_collisions",
                lambda t: exactccd.candidates_find_collisions(V0, V1, vertex_face=vf, threads=t)))
    out.append(("intersection_free", lambda t: exactccd.intersection_free(V1, F)))
    out.append(("shared broad phase", lambda t: (shared.find_collisions(), shared.max_collision_free_step())))

    def line_search(t):
        """A line search on this caller's own broad phase: refit to shrinking steps."""
        bp = exactccd.SceneBroadPhase(V0, V1, F, min_distance=1e-3, threads=t)
        steps = []
        for alpha in (1.0, 0.5, 0.25, 0.125):
            bp.update(V0 + alpha * (V1 - V0))
            steps.append(bp.max_collision_free_step())
        return steps, bp.earliest_toi()

    out.append(("line search", line_search))
    return out


def canonical(value):
    """A value comparable with == exactly (arrays as bytes, so NaN rows compare equal)."""
    if isinstance(value, np.ndarray):
        return (value.dtype.str, value.shape, value.tobytes())
    if isinstance(value, dict):
        return tuple((k, canonical(v)) for k, v in sorted(value.items()))
    if isinstance(value, (tuple, list)):
        return tuple(canonical(v) for v in value)
    return value


def test_eight_callers_get_the_single_threaded_answers():
    batches, V0, V1, F = inputs()
    shared = exactccd.SceneBroadPhase(V0, V1, F, min_distance=1e-3)
    work = tasks(batches, V0, V1, F, shared)
    expected = {name: canonical(call(1)) for name, call in work}
    failures, calls = [], [0] * CALLERS

    def caller(k):
        order = work[k % len(work):] + work[:k % len(work)]         # each caller its own order
        for round_ in range(2):
            for i, (name, call) in enumerate(order):
                threads = (1, 2, 0)[(k + i + round_) % 3]
                try:
                    got = canonical(call(threads))
                except Exception as e:  # noqa: BLE001 (reported below, with the task)
                    failures.append(f"caller {k}, {name}, threads={threads}: {e!r}")
                    continue
                calls[k] += 1
                if got != expected[name]:
                    failures.append(f"caller {k}, {name}, threads={threads}: differs from the single-threaded answer")

    pool = [threading.Thread(target=caller, args=(k,)) for k in range(CALLERS)]
    for t in pool:
        t.start()
    for t in pool:
        t.join()
    assert not failures, failures[:10]
    assert calls == [2 * len(work)] * CALLERS


CHILD = r'''
import os, sys, threading, time
sys.path.insert(0, sys.argv[1])
import numpy as np
import exactccd
from test_stress import inputs, tasks, CALLERS, IDLE_SETTLE_S, IDLE_WINDOW_S

batches, V0, V1, F = inputs()
shared = exactccd.SceneBroadPhase(V0, V1, F, min_distance=1e-3)
work = tasks(batches, V0, V1, F, shared)
stop = threading.Event()

def caller(k):
    i = k
    while not stop.is_set():
        work[i % len(work)][1]((1, 2, 0)[i % 3])
        i += 1

pool = [threading.Thread(target=caller, args=(k,)) for k in range(CALLERS)]
for t in pool:
    t.start()
print("running", flush=True)
long_batch = np.tile(batches["edge_edge"], (40, 1, 1))
try:
    while True:   # the main thread in long library calls too: Ctrl-C lands in one
        exactccd.edge_edge_toi(long_batch, min_distance=1e-3, threads=2)
except KeyboardInterrupt:
    t = time.monotonic()
    stop.set()
    for p in pool:
        p.join()
    # A joined thread may still be leaving the kernel for a moment (Python's join returns when
    # its thread state is gone): wait up to a second for the callers to be gone (with them their
    # helper threads, joined when a caller ends). What may stay: the main thread's helper (kept
    # for its next long call) and oneTBB's idle workers (kept for the next call: at most one per
    # core but one), blocked, using no CPU.
    cores = len(os.sched_getaffinity(0))
    deadline = time.monotonic() + 1.0
    while len(os.listdir("/proc/self/task")) > cores + 1 and time.monotonic() < deadline:
        time.sleep(0.01)
    stopped, left = time.monotonic() - t, len(os.listdir("/proc/self/task"))
    time.sleep(IDLE_SETTLE_S)  # oneTBB's workers spin a little before they sleep
    cpu = time.process_time()  # every thread of the process
    time.sleep(IDLE_WINDOW_S)
    print("stopped", stopped, left, time.process_time() - cpu, cores, flush=True)
'''


def test_ctrl_c_stops_eight_callers(tmp_path):
    script = tmp_path / "child.py"
    script.write_text(CHILD)
    child = subprocess.Popen([sys.executable, str(script), os.path.dirname(__file__)], stdout=subprocess.PIPE,
                             text=True, env=dict(os.environ, PYTHONUNBUFFERED="1"))
    try:
        assert child.stdout.readline().split() == ["running"]
        time.sleep(1.5)                                       # every caller busy in the library
        sent = time.monotonic()
        child.send_signal(signal.SIGINT)
        out, _ = child.communicate(timeout=20)
    finally:
        child.kill()
    exited = time.monotonic() - sent
    words = out.split()
    assert words[:1] == ["stopped"], out
    threads_left, busy, cores = int(words[2]), float(words[3]), int(words[4])
    assert threads_left <= cores + 1, out   # the callers gone; the main thread's helper, oneTBB's idle workers
    assert busy < IDLE_CPU_S, out             # nothing of a call still runs
    assert child.returncode == 0
    # Promptly: the calls in flight finish or stop within seconds (exited also counts the child's
    # wait for the callers' threads and its idle measurement).
    assert exited < 4.5 + IDLE_SETTLE_S + IDLE_WINDOW_S, exited
