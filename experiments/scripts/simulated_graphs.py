"""Simulated pose graphs in a Manhattan world, as Olson, Leonard & Teller (2006) made
manhattan3500: a robot on a grid of 1 m streets, one step per pose, turning by 90 degrees at
some crossings, with a loop closure to an earlier pose at the same crossing. The odometry and
the closures carry Gaussian noise of `sigma_xy`, `sigma_theta`; every edge states the
information of `stated_scale` times that noise's standard deviation (manhattan3500 and intel
state their noise about 6 to 7 times wider than their least-squares residuals show), the odometry
optionally another scale. Used to
choose parameters on data that is not one of the public graphs (clique_options.py)."""
import math
import os
import tempfile

import numpy as np

# World side (crossings) for a number of poses: 800 in 60 x 60 gives few loop closures, as mit;
# 1,000 in 12 x 12 and 3,500 in 25 x 25 give many, as manhattan3500.
WORLD_SIDE = {800: 60, 1000: 12, 3500: 25}


def _compose(a, b):
    c, s = math.cos(a[2]), math.sin(a[2])
    return (a[0] + c * b[0] - s * b[1], a[1] + s * b[0] + c * b[1],
            math.remainder(a[2] + b[2], 2 * math.pi))


def _between(a, b):
    c, s = math.cos(a[2]), math.sin(a[2])
    dx, dy = b[0] - a[0], b[1] - a[1]
    return (c * dx + s * dy, -s * dx + c * dy, math.remainder(b[2] - a[2], 2 * math.pi))


def manhattan_g2o(poses, seed, world=30, turn=0.3, closure=0.5, min_gap=10, sigma_xy=0.05,
                  sigma_theta=0.01, stated_scale=6.0, odometry_stated_scale=None,
                  stated_theta_scale=None):
    """g2o text of a simulated Manhattan graph with `poses` poses in a world of world x world
    crossings: at each crossing the robot turns with probability `turn` (and always at the
    border), and a pose at a crossing it visited at least `min_gap` poses earlier closes a loop
    to one of those visits with probability `closure`. The odometry states its noise
    `odometry_stated_scale` times wider than it is (default: stated_scale, as the closures); the
    heading of every edge `stated_theta_scale` times (default: as x and y)."""
    rng = np.random.default_rng(seed)
    truth = [(0.0, 0.0, 0.0)]
    heading = 0
    cell = (0, 0)
    for _ in range(poses - 1):
        turns = [0, 1, -1] if rng.random() < turn else [0]
        rng.shuffle(turns)
        for t in turns + [2, 1, -1]:
            h = (heading + t) % 4
            nxt = (cell[0] + (1, 0, -1, 0)[h], cell[1] + (0, 1, 0, -1)[h])
            if 0 <= nxt[0] < world and 0 <= nxt[1] < world:
                break
        heading, cell = h, nxt
        truth.append((float(cell[0]), float(cell[1]), math.remainder(h * math.pi / 2, 2 * math.pi)))
    noise = np.array([sigma_xy, sigma_xy, sigma_theta])

    def measured(i, j):
        z = np.array(_between(truth[i], truth[j])) + rng.normal(0.0, noise)
        z[2] = math.remainder(z[2], 2 * math.pi)
        return z

    edges = [(i, i + 1, measured(i, i + 1)) for i in range(poses - 1)]
    visits = {}
    for j, p in enumerate(truth):
        key = (round(p[0]), round(p[1]))
        earlier = [i for i in visits.get(key, []) if i <= j - min_gap]
        if earlier and rng.random() < closure:
            i = int(rng.choice(earlier))
            edges.append((i, j, measured(i, j)))
        visits.setdefault(key, []).append(j)
    theta_factor = 1.0 if stated_theta_scale is None else stated_theta_scale / stated_scale

    def information(scale):
        return 1.0 / (scale * sigma_xy) ** 2, 1.0 / (scale * theta_factor * sigma_theta) ** 2

    closure_info = information(stated_scale)
    odometry_info = information(stated_scale if odometry_stated_scale is None
                                else odometry_stated_scale)
    estimate = [(0.0, 0.0, 0.0)]
    for _, _, z in edges[:poses - 1]:
        estimate.append(_compose(estimate[-1], z))
    lines = [f"VERTEX_SE2 {k} {x!r} {y!r} {t!r}" for k, (x, y, t) in enumerate(estimate)]
    for i, j, z in edges:
        xy, theta = odometry_info if j == i + 1 else closure_info
        lines.append(f"EDGE_SE2 {i} {j} {z[0]!r} {z[1]!r} {z[2]!r} {xy!r} 0 0 {xy!r} 0 {theta!r}")
    return "\n".join(lines) + "\n"


def manhattan_graph(antslam, poses, seed, **options):
    """The simulated graph (manhattan_g2o) as an antslam.slam.PoseGraph."""
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, f"manhattan{poses}-{seed}.g2o")
        with open(path, "w") as f:
            f.write(manhattan_g2o(poses, seed, **options))
        return antslam.slam.read_graph(path)
