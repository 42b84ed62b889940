import numpy as np
import exactccd

# One vertex-face query per row block: p, a, b, c at t = 0, then at t = 1 -> shape (N, 8, 3).
q = np.array([[[0.25, 0.25, 1], [0, 0, 0], [1, 0, 0], [0, 1, 0],
               [0.25, 0.25, -1], [0, 0, 0], [1, 0, 0], [0, 1, 0]]])
print(exactccd.vertex_face_ccd(q))                                # [ True]
print(exactccd.vertex_face_toi(q, min_distance=0.25, tmax=0.75))  # [[0.375 0.375]]

# A whole mesh over one step, and a line search that refits the broad phase per trial.
V0, F = exactccd.read_mesh("data/scenes/cloth/T0.obj")
V1, _ = exactccd.read_mesh("data/scenes/cloth/T1.obj")
print(exactccd.earliest_toi(V0, V1, F))                  # (lo, hi) or None
bp = exactccd.SceneBroadPhase(V0, V1, F, min_distance=1e-3)
for alpha in (1.0, 0.5, 0.25):
    bp.update(V0 + alpha * (V1 - V0))
    print(alpha, bp.max_collision_free_step())            # the largest safe fraction of the trial
