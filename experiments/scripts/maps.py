#!/usr/bin/python3
"""Maps of fragment sets: the robot paths of the shipped synthetic sets paper15 and paper24
(data/fragment-sets) and of ring.g2o (`antslam g2o` with its ground truth) under the scan
matcher's map (the chain of the alignment means mu_i, eq. 8), the best of T hybrid trials
(`antslam optimize --method hybrid --trials T --seed 1`), Ceres least squares (one solve), and
the ground truth. Writes maps.csv (best and mean eq. (10) weight per set and method), table.md
and maps.png into the results folder.

    /usr/bin/python3 experiments/scripts/maps.py [--quick] [--trials 100] [--threads 1]
        [--out results/maps] [--publish]

--quick: 2 hybrid trials of 300 iterations.
"""
import math
import os

from experiment_common import (DATA, antslam, check_program, header, count_option,
                               markdown_table, parser, plt, progress, read_json, read_result,
                               save_csv, save_figure, save_table, threads_option)

SETS = ["paper15", "paper24", "ring"]
POSEGRAPHS = os.path.join(DATA, "posegraphs")


def compose(a, b):
    """SE(2) composition a * b of (x, y, theta) poses."""
    c, s = math.cos(a[2]), math.sin(a[2])
    return (a[0] + c * b[0] - s * b[1], a[1] + s * b[0] + c * b[1], a[2] + b[2])


def chain(alignments):
    """Eq. (8): the fragment frames F_1 = identity, F_i = F_{i-1} X_i."""
    frames = [(0.0, 0.0, 0.0)]
    for a in alignments:
        frames.append(compose(frames[-1], a))
    return frames


def world_path(fragment_set, frames):
    """The robot path in W: each fragment's trajectory moved by its frame (the frame itself if
    the fragment has no trajectory)."""
    xs, ys = [], []
    for frame, fragment in zip(frames, fragment_set["fragments"]):
        for pose in fragment.get("trajectory", [[0, 0, 0, 0]]):
            w = compose(frame, pose[1:])
            xs.append(w[0])
            ys.append(w[1])
    return xs, ys


def fragment_set_path(args, name):
    if name != "ring":
        return os.path.join(DATA, "fragment-sets", name + ".json")
    path = os.path.join(args.out, "sets", "ring.json")
    antslam(args, "g2o", os.path.join(POSEGRAPHS, "ring.g2o"), "-o", path, "--reference",
            os.path.join(POSEGRAPHS, "ring.gt.g2o"))
    return path


def main():
    p = parser(__doc__, "maps")
    count_option(p, "--trials", "hybrid trials", 100, 2)
    threads_option(p)
    args = p.parse_args()
    check_program(args)
    head = header(args, "experiments/scripts/maps.py")  # the load before the runs
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.6))
    rows = []
    for ax, name in zip(axes, SETS):
        progress(f"{name}: {args.trials} hybrid trials, one Ceres solve")
        path = fragment_set_path(args, name)
        fragment_set = read_json(path)
        means = chain([f["alignment"]["mean"] for f in fragment_set["fragments"][1:]])
        ax.plot(*world_path(fragment_set, means), color="0.6", lw=1,
                label="scan matcher (means)")
        for method, color, trials in (("hybrid", "tab:red", args.trials),
                                      ("ceres", "tab:blue", 1)):
            prefix = os.path.join(args.out, "runs", f"map-{name}-{method}")
            antslam(args, "optimize", path, "--method", method, "--trials", trials,
                    "--threads", args.threads, "--seed", 1, "-o", prefix,
                    *(["--iterations", 300] if args.quick and method == "hybrid" else []))
            r = read_result(prefix)
            rows.append([name, method, trials, r["best"]["weight"], r["weight"]["mean"]])
            ax.plot(*world_path(fragment_set, r["best"]["frames"]), color=color, lw=1.2,
                    label=f"{method} (weight {r['best']['weight']:.2f})")
        ax.plot(*world_path(fragment_set, fragment_set["reference"]), "k--", lw=1,
                label="ground truth")
        ax.set_aspect("equal")
        ax.set_title(name)
        ax.legend(fontsize=7)
    save_figure(args, fig, "maps")
    save_csv(args, "maps", ["set", "method", "trials", "best_weight", "mean_weight"], rows)
    text = (f"Robot paths of the shipped synthetic sets and of ring.g2o: the scan matcher's map "
            f"(chain of the means mu_i), the best of {args.trials} hybrid trials, Ceres least "
            "squares, and the ground truth.\n\n"
            + markdown_table(["set", "method", "trials", "best weight", "mean weight"],
                             [[r[0], r[1], r[2], f"{r[3]:.2f}", f"{r[4]:.2f}"] for r in rows])
            + "\n![maps](figures/results-maps.png)\n")
    save_table(args, head + text)
    print(text, end="")
    progress(f"wrote {args.out}/maps.csv, table.md, maps.png")


if __name__ == "__main__":
    main()
