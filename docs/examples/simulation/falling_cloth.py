"""A cloth falls under gravity onto a fixed obstacle (a hill on flat ground), folds onto itself
and comes to rest, never closer than d to the obstacle or to itself: a simulation loop driven
by exactccd's line search (docs/simulation.md).

Each step of h seconds:

1. The integrator proposes positions x1: position-based dynamics (Mueller et al. 2007), the
   shortest cloth integrator to read: velocity and gravity predict x0 + h v + h^2 g, then
   Gauss-Seidel sweeps pull every edge back towards its rest length.
2. The line search: a SceneBroadPhase over the step x0 -> x1 with min_distance d gives s =
   max_collision_free_step(), the largest fraction of the step over which every pair of
   primitives sharing no vertex stays farther apart than d (exactly).
3. The contact response, inelastic and sticking, while s < MIN_FRACTION: the pairs that come
   within d over the step (find_collisions) are contacts, and their cloth vertices keep their
   positions this step (so they lose their velocity); the broad phase is refitted to the new
   x1 (update) and asked again. Each round stops at least one more vertex (a pair whose
   vertices all stand still stays farther than d), so it ends; without it the loop stalls: a
   cloth resting on the hill under gravity proposes to sink into it every step, and s is then
   about 1e-16 (the record's first_fraction).
4. The new positions x0 + s (x1 - x0) are rounded to doubles, so the motion to them is checked
   again (update, is_collision_free), s halved until it is collision-free: every configuration
   the loop reaches is farther than d from itself and the obstacle, exactly, in every pair.

Usage: python3 docs/examples/falling_cloth.py [--steps N] [--record R.csv] [--frames F.png]
(through the installed module; PYTHONPATH=build/python uses the build tree's).
"""

import argparse
import csv
import os
import time

import numpy as np

import exactccd

GRAVITY = np.array([0.0, 0.0, -9.81])  # m / s^2
SWEEPS = 10                            # Gauss-Seidel sweeps over the edges per step
MIN_FRACTION = 0.5                     # the contact response runs until s >= MIN_FRACTION


def grid(n, size):
    """A square n x n grid of vertices of side `size` centred at the origin in the plane z = 0,
    each cell split into two triangles: (V (n^2, 3), F (2 (n - 1)^2, 3))."""
    u = np.linspace(-size / 2, size / 2, n)
    x, y = np.meshgrid(u, u, indexing="ij")
    V = np.stack([x.ravel(), y.ravel(), np.zeros(n * n)], axis=1)
    i, j = np.meshgrid(np.arange(n - 1), np.arange(n - 1), indexing="ij")
    a = (i * n + j).ravel()
    F = np.concatenate([np.stack([a, a + n, a + n + 1], axis=1), np.stack([a, a + n + 1, a + 1], axis=1)])
    return V, F


def edge_classes(F, V):
    """The triangles' edges as classes of edges sharing no vertex (a greedy colouring), each as
    (i, j, rest length): the constraints of one class are projected at once."""
    E = np.unique(np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1), axis=0)
    used = [set() for _ in range(len(V))]
    colour = np.zeros(len(E), dtype=int)
    for k, (a, b) in enumerate(E):
        colour[k] = min(set(range(len(used[a]) + len(used[b]) + 1)) - used[a] - used[b])
        used[a].add(colour[k])
        used[b].add(colour[k])
    return [(E[colour == c, 0], E[colour == c, 1], np.linalg.norm(V[E[colour == c, 0]] - V[E[colour == c, 1]], axis=1))
            for c in range(colour.max() + 1)]


class FallingCloth:
    """The cloth (vertices [0, n_cloth), upright, leaning 20 degrees, its lower edge 0.35 m up)
    and the fixed obstacle (the other vertices: a hill 0.2 m high on flat ground), one scene."""

    def __init__(self, resolution=40, obstacle_resolution=25, min_distance=1e-3, h=0.02, threads=0):
        cloth, cloth_f = grid(resolution, 1.0)
        tilt = np.radians(20)
        height = cloth[:, 1] + 0.5
        cloth = np.stack([cloth[:, 0], np.sin(tilt) * height, 0.35 + np.cos(tilt) * height], axis=1)
        ground, ground_f = grid(obstacle_resolution, 1.6)
        ground[:, 2] = 0.2 * np.exp(-(ground[:, 0] ** 2 + ground[:, 1] ** 2) / (2 * 0.25 ** 2))
        self.n_cloth = len(cloth)
        self.x = np.concatenate([cloth, ground])
        self.v = np.zeros_like(self.x)
        self.F = np.concatenate([cloth_f, ground_f + self.n_cloth])
        self.constraints = edge_classes(cloth_f, cloth)
        self.d, self.h, self.threads = min_distance, h, threads

    def propose(self):
        """Position-based dynamics: the predicted cloth positions, then the edge constraints."""
        c = self.n_cloth
        x1 = self.x.copy()
        x1[:c] += self.h * self.v[:c] + self.h ** 2 * GRAVITY
        for _ in range(SWEEPS):
            for i, j, rest in self.constraints:
                delta = x1[i] - x1[j]
                length = np.linalg.norm(delta, axis=1)
                correction = (0.5 * (length - rest) / length)[:, None] * delta
                x1[i] -= correction
                x1[j] += correction
        return x1

    def pair_vertices(self, hits):
        """The vertices of each colliding pair of find_collisions' dict, one row per pair (-1
        pads a vertex-face pair's row, which has four)."""
        vf = hits["kind"] == exactccd.VERTEX_FACE
        rows = np.full((len(vf), 4), -1)
        rows[vf] = np.column_stack([hits["vertex"][vf], self.F[hits["triangle"][vf]]])
        rows[~vf] = np.column_stack([hits["edge_a"][~vf], hits["edge_b"][~vf]])
        return rows

    def step(self):
        """One step (the module's docstring); returns its record."""
        wall, cpu = time.perf_counter(), time.process_time()
        x0, x1 = self.x, self.propose()
        wall_ccd, cpu_ccd = time.perf_counter(), time.process_time()
        line_search = exactccd.SceneBroadPhase(x0, x1, self.F, min_distance=self.d, threads=self.threads)
        s = first = line_search.max_collision_free_step()
        pairs = self.pair_vertices(line_search.find_collisions()) if s < 1 else np.zeros((0, 4), dtype=int)
        contacts, self_contacts = len(pairs), int((pairs < self.n_cloth).all(axis=1).sum())
        stopped, rounds = np.zeros(len(x0), dtype=bool), 0
        while s < MIN_FRACTION:                       # the contact response
            moving = pairs[(pairs >= 0) & (pairs < self.n_cloth)]
            if stopped[moving].all():
                raise RuntimeError("fixed vertices within d of each other: the obstacle itself is closer than d")
            stopped[moving] = True
            x1[stopped] = x0[stopped]
            line_search.update(x1)
            s, rounds = line_search.max_collision_free_step(), rounds + 1
            if s < MIN_FRACTION:
                pairs = self.pair_vertices(line_search.find_collisions())
        x, retries = x1, 0
        while s < 1:                                  # the rounded positions, checked
            x = x0 + s * (x1 - x0)
            line_search.update(x)
            if line_search.is_collision_free():
                break
            s, retries = s / 2, retries + 1
        wall_end, cpu_end = time.perf_counter(), time.process_time()
        self.v, self.x = (x - x0) / self.h, x
        return {"first_fraction": first, "safe_fraction": s, "contacts": contacts, "self_contacts": self_contacts,
                "max_speed": float(np.linalg.norm(self.v, axis=1).max()), "response_rounds": rounds,
                "stopped": int(stopped.sum()), "retries": retries,
                "ccd_seconds": wall_end - wall_ccd, "ccd_cpu_seconds": cpu_end - cpu_ccd,
                "step_seconds": wall_end - wall, "step_cpu_seconds": cpu_end - cpu}


def resident_kib():
    """The process's resident memory in KiB (Linux: /proc/self/statm)."""
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE") // 1024


def write_record(records, path):
    """The per-step records as CSV, one row per step (times and speeds to 6 digits; the
    fractions in full: 1 and the double below it differ)."""
    with open(path, "w", newline="") as f:
        out = csv.DictWriter(f, fieldnames=["step"] + list(records[0]))
        out.writeheader()
        for k, r in enumerate(records):
            out.writerow({"step": k + 1, **{key: f"{v:.6g}" if key.endswith(("seconds", "speed")) else v
                                            for key, v in r.items()}})


def draw_frames(sim, snapshots, path):
    """A strip of frames (matplotlib): the cloth and the obstacle at each (step, positions)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    light = np.array([0.3, -0.5, 0.8]) / np.linalg.norm([0.3, -0.5, 0.8])
    cloth = (sim.F < sim.n_cloth).all(axis=1)
    fig = plt.figure(figsize=(2.6 * len(snapshots), 2.8))
    for k, (step, x) in enumerate(snapshots):
        ax = fig.add_subplot(1, len(snapshots), k + 1, projection="3d", computed_zorder=False)
        for faces, colour in ((sim.F[~cloth], (0.85, 0.8, 0.7)), (sim.F[cloth], (0.2, 0.45, 0.8))):
            T = x[faces]
            n = np.cross(T[:, 1] - T[:, 0], T[:, 2] - T[:, 0])
            shade = 0.35 + 0.65 * np.abs(n @ light) / np.maximum(np.linalg.norm(n, axis=1), 1e-300)
            ax.add_collection3d(Poly3DCollection(T, facecolors=np.outer(shade, colour), edgecolor="none"))
        ax.set(xlim=(-0.6, 0.6), ylim=(-0.6, 0.6), zlim=(0, 0.9), title=f"step {step}")
        ax.set_box_aspect((1.2, 1.2, 0.9))
        ax.view_init(15, -60)
        ax.set_axis_off()
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--steps", type=int, default=200)
    parser.add_argument("--resolution", type=int, default=40, help="cloth vertices per side (40: 3042 triangles)")
    parser.add_argument("--threads", type=int, default=0)
    parser.add_argument("--record", help="write the per-step record here (CSV)")
    parser.add_argument("--frames", help="write a strip of frames here (PNG)")
    parser.add_argument("--frame-steps", default="0,12,20,30,50,100,200", help="the steps the strip shows")
    args = parser.parse_args(argv)
    sim = FallingCloth(resolution=args.resolution, threads=args.threads)
    frame_steps = {int(k) for k in args.frame_steps.split(",")}
    snapshots = [(0, sim.x)] if 0 in frame_steps else []
    records = []
    for k in range(1, args.steps + 1):
        records.append({**sim.step(), "resident_kib": resident_kib()})
        if k in frame_steps:
            snapshots.append((k, sim.x))
    r = records[-1]
    print(f"{args.steps} steps: last step s = {r['safe_fraction']:.3g} "
          f"(before the response {r['first_fraction']:.3g}), "
          f"{r['contacts']} pairs within d ({r['self_contacts']} of the cloth with itself), "
          f"intersection-free {exactccd.intersection_free(sim.x, sim.F)}")
    if args.record:
        write_record(records, args.record)
    if args.frames:
        draw_frames(sim, snapshots, args.frames)


if __name__ == "__main__":
    main()
