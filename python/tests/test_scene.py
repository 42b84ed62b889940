"""Scene functions on arrays: the bundled scenes against the CLI's `exactccd scene` (pairs, TOIs
bit for bit, earliest TOI, largest safe step, intersection-free end states), hand-made 3D and 2D
scenes, and read_mesh."""

import re
import subprocess

import numpy as np
import pytest

import exactccd
from conftest import DATA, TEST_DATA, cli

SCENES = sorted(p for p in (DATA / "scenes").iterdir() if (p / "T0.obj").exists())


def cli_scene(t0, t1, min_distance=None):
    exe = cli()
    if exe is None:
        pytest.skip("the exactccd CLI is not built (set EXACTCCD_CLI)")
    cmd = [exe, "scene", str(t0), str(t1)]
    if min_distance is not None:
        cmd += ["--min-distance", repr(min_distance)]
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    result = {"vf": [], "ee": []}
    for line in out.splitlines():
        m = re.match(r"^(vf|ee) ([\d ]+) toi \[(\S+), (\S+)\]$", line)
        if m:
            result[m[1]].append(([int(x) for x in m[2].split()], float(m[3]), float(m[4])))
        elif line.startswith("earliest toi"):
            m = re.search(r"\[(\S+), (\S+)\]", line)
            result["earliest"] = (float(m[1]), float(m[2])) if m else None
        elif line.startswith("max safe step"):
            result["step"] = float(line.split()[-1])
        elif line.startswith("intersection-free at t0"):
            result["free0"] = line.endswith("yes")
        elif line.startswith("intersection-free at t1"):
            result["free1"] = line.endswith("yes")
    return result


@pytest.mark.parametrize("scene", SCENES, ids=lambda p: p.name)
@pytest.mark.parametrize("d", [None, 1e-3])
def test_bundled_scene_equals_cli(scene, d):
    V0, F = exactccd.read_mesh(scene / "T0.obj")
    V1, F1 = exactccd.read_mesh(scene / "T1.obj")
    assert V0.dtype == np.float64 and V0.shape[1] == 3 and F.dtype == np.int64 and F.shape[1] == 3
    assert np.array_equal(F, F1)
    want = cli_scene(scene / "T0.obj", scene / "T1.obj", d)
    kw = {} if d is None else {"min_distance": d}
    hits = exactccd.find_collisions(V0, V1, F, **kw)
    assert set(hits) == {"kind", "vertex", "triangle", "edge_a", "edge_b", "vertex_b", "toi"}
    vf = hits["kind"] == exactccd.VERTEX_FACE
    ee = hits["kind"] == exactccd.EDGE_EDGE
    assert (vf | ee).all()  # no point kinds in a triangle mesh without points
    got_vf = [([int(hits["vertex"][i]), int(hits["triangle"][i])], *hits["toi"][i]) for i in np.flatnonzero(vf)]
    got_ee = [([*map(int, hits["edge_a"][i]), *map(int, hits["edge_b"][i])], *hits["toi"][i])
              for i in np.flatnonzero(ee)]
    assert got_vf == want["vf"] and got_ee == want["ee"]
    assert len(got_vf) + len(got_ee) > 0
    assert (hits["triangle"][ee] == -1).all() and (hits["edge_a"][vf] == -1).all()
    assert exactccd.earliest_toi(V0, V1, F, **kw) == want["earliest"]
    assert exactccd.max_collision_free_step(V0, V1, F, **kw) == want["step"]
    assert exactccd.is_collision_free(V0, V1, F, **kw) is False
    assert exactccd.intersection_free(V0, F) == want["free0"]
    assert exactccd.intersection_free(V1, F) == want["free1"]
    for threads in (1, 3):
        again = exactccd.find_collisions(V0, V1, F, threads=threads, **kw)
        assert all(np.array_equal(again[k], hits[k]) for k in hits)


def test_hand_made_scene():
    # a triangle at z = 0, a point falling onto it and a second triangle sliding through
    V0 = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0.25, 0.25, 1], [5, 5, 5]], dtype=np.float64)
    V1 = V0.copy()
    V1[3] = [0.25, 0.25, -1]
    F = np.array([[0, 1, 2]])
    hits = exactccd.find_collisions(V0, V1, F, P=[3])
    assert hits["kind"].tolist() == [exactccd.VERTEX_FACE]
    assert hits["vertex"].tolist() == [3] and hits["triangle"].tolist() == [0]
    assert hits["toi"].tolist() == [[0.5, 0.5]]
    assert exactccd.earliest_toi(V0, V1, F, P=[3]) == (0.5, 0.5)
    assert exactccd.max_collision_free_step(V0, V1, F, P=[3]) == np.nextafter(0.5, 0)
    assert exactccd.earliest_toi(V0, V1, F, P=[3], tmax=0.25) is None
    assert exactccd.max_collision_free_step(V0, V1, F, P=[3], tmax=0.25) == 0.25
    assert exactccd.is_collision_free(V0, V1, F, P=[3], tmax=0.25)
    # a far isolated point and the falling one: point-point pairs only with d > 0
    hits = exactccd.find_collisions(V0, V0, F, P=[3, 4], min_distance=10.0)
    assert exactccd.POINT_POINT in hits["kind"].tolist()
    pp = hits["kind"] == exactccd.POINT_POINT
    assert hits["vertex"][pp].tolist() == [3] and hits["vertex_b"][pp].tolist() == [4]
    # an extra (codimensional) edge crossing the triangle
    E = np.array([[3, 4]])
    V1e = V0.copy()
    V1e[3] = [0.25, 0.25, -1]
    V1e[4] = [0.25, 0.25, -5]
    assert not exactccd.is_collision_free(V0, V1e, F, E=E)


def test_2d_scene():
    V0 = np.array([[0, 0], [1, 0], [0.5, 1], [0.5, 2], [3, 3]], dtype=np.float64)
    V1 = V0.copy()
    V1[2:4, 1] -= 2  # the edge (2, 3) falls through the edge (0, 1): touches it at t = 1/2
    E = np.array([[0, 1], [2, 3]])
    hits = exactccd.find_collisions(V0, V1, E=E)
    assert hits["kind"].tolist() == [exactccd.EDGE_EDGE]
    assert hits["edge_a"].tolist() == [[0, 1]] and hits["edge_b"].tolist() == [[2, 3]]
    assert hits["toi"].tolist() == [[0.5, 0.5]]
    assert exactccd.earliest_toi(V0, V1, None, E) == (0.5, 0.5)
    # an isolated point in the plane: point-edge pairs at d = 0 too
    V1p = V0.copy()
    V1p[4] = [0.5, -1]
    V0p = V0.copy()
    V0p[4] = [0.5, 1]
    hits = exactccd.find_collisions(V0p, V1p, E=np.array([[0, 1]]), P=[4])
    assert hits["kind"].tolist() == [exactccd.POINT_EDGE]
    assert hits["vertex"].tolist() == [4] and hits["edge_a"].tolist() == [[0, 1]]
    assert exactccd.max_collision_free_step(V0p, V1p, E=[[0, 1]], P=[4]) == np.nextafter(0.5, 0)


def test_intersection_free():
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0.2, 0.2, -1], [0.2, 0.2, 1], [2, 2, 0]], dtype=np.float64)
    assert exactccd.intersection_free(V, [[0, 1, 2]])
    assert not exactccd.intersection_free(V, [[0, 1, 2], [3, 4, 5]])  # pierces the first
    V[3:5, 0] = 5
    assert exactccd.intersection_free(V, np.array([[0, 1, 2], [3, 4, 5]], dtype=np.int32))


def test_read_mesh_of_every_test_mesh():
    # whatever formats the library reads: a mesh, or ValueError naming the file (never an empty mesh)
    meshes = sorted(p for p in (TEST_DATA / "meshes").iterdir() if p.suffix != ".md")
    meshes += [DATA / "scenes" / "fold" / "T0.obj"]
    for path in meshes:
        try:
            V, F = exactccd.read_mesh(str(path))
        except ValueError as e:
            assert path.name in str(e)  # the library's message names the file
            continue
        assert V.ndim == 2 and V.shape[1] == 3 and F.ndim == 2 and F.shape[1] == 3
        assert len(F) > 0 and F.min() >= 0 and F.max() < len(V)
