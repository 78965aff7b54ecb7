#!/usr/bin/python3
"""Paper Fig. 5 on real logs: for the bundled one-loop log (malaga) and for noise-corrupted
corrected logs (aces, intel; `antslam simulate-odometry --seed 1`): (a) the initial map (the
scan matcher's) beside the average map of random sample sequences (the spread the optimizer
chooses from, `antslam frontend --average-samples`), (b) the average of the optimized maps of
every AntSLAM (hybrid) trial (`antslam map --method hybrid`), (b') their corrected trajectories
overlaid, and (c) the best weight (eq. 10) against time, mean +- std over the trials. Writes
fig5.csv (per dataset and trial: final weight, time, ATE if a reference exists), table.md and
fig5-DATASET.png into the results folder.

    /usr/bin/python3 experiments/scripts/fig5.py [--quick] [--trials 100] [--out results/fig5]
        [--publish]

Panel (b) is the paper's: `antslam map` runs the same frontend and fragment set (seed 1) and the
same hybrid trials and averages their maps. (b') adds the trajectories: a tight bundle says the
trials agree, a fan shows where they do not.

--quick: malaga and aces, 3 trials of 300 iterations, maps at 0.2 m per cell.
"""
import os

import matplotlib.image as mpimg

from experiment_common import (DATA, antslam, check_program, header, count_option,
                               markdown_table, parser, plt, pm, progress, read_csv, read_json,
                               read_study, save_csv, save_figure, save_table, stats, step_mean)

LASER = os.path.join(DATA, "laser")


def read_tum(path):
    return [tuple(map(float, line.split()[1:3])) for line in open(path) if line[0] != "#"]


def prepare(args, name):
    """The log to map and its reference (None for malaga)."""
    if name == "malaga":
        return os.path.join(LASER, "malaga-oneloop.clf"), None
    work = os.path.join(args.out, name, "benchmark")
    antslam(args, "simulate-odometry", os.path.join(LASER, "corrected", f"{name}-corrected.log.gz"),
            "--out", work, "--seed", 1)
    return os.path.join(work, "log.clf"), os.path.join(work, "reference.tum")


def study(args, name):
    progress(f"{name}: frontend, fragment set")
    log, reference = prepare(args, name)
    work = os.path.join(args.out, name)
    antslam(args, "frontend", log, "--out", os.path.join(work, "frontend"), "--average-samples",
            args.trials, *args.map_options)
    fragment_set = os.path.join(work, "fragment-set.json")
    antslam(args, "fragment-set", log, "-o", fragment_set)
    progress(f"{name}: {args.trials} hybrid trials")
    prefix = os.path.join(work, "hybrid")
    antslam(args, "optimize", fragment_set, "--method", "hybrid", "--trials", args.trials,
            "--seed", 1, "--iterations", args.iterations, "-o", prefix)
    progress(f"{name}: average map of the {args.trials} hybrid trials")
    antslam(args, "map", log, "--method", "hybrid", "--trials", args.trials, "--seed", 1,
            "--iterations", args.iterations, "--out", os.path.join(work, "map"), *args.map_options)
    trials, points = read_study(prefix)
    traces = [[(float(p["elapsed_s"]), float(p["best_weight"])) for p in trace]
              for trace in points]
    # `optimize --tum-out` writes the best trial's trajectory only: for panel (b) run seeds 1..T
    # one trial each (same settings) and keep every trajectory.
    paths, rows = [], []
    for seed in range(1, args.trials + 1):
        tum = os.path.join(work, "trials", f"{seed}.tum")
        antslam(args, "optimize", fragment_set, "--method", "hybrid", "--seed", seed,
                "--iterations", args.iterations, "-o", os.path.join(work, "trials", str(seed)),
                "--tum-out", tum)
        ate = None
        if reference:
            antslam(args, "eval", tum, reference, "--json", tum + ".eval.json", "--aligned-out",
                    tum + ".aligned.tum")
            ate = read_json(tum + ".eval.json")["ate"]["translation_m"]["rmse"]
            tum += ".aligned.tum"  # drawn on the reference's frame
        weight = float(read_csv(os.path.join(work, "trials", f"{seed}.trials.csv"))[0]["weight"])
        paths.append(read_tum(tum))
        rows.append([name, seed, weight, "" if ate is None else ate])
    return {"traces": traces, "trials": trials, "paths": paths, "rows": rows,
            "reference": read_tum(reference) if reference else None,
            "frontend": os.path.join(work, "frontend"), "map": os.path.join(work, "map")}


def plot(args, name, r):
    fig, axes = plt.subplots(1, 5, figsize=(21, 4.4))
    for ax, png, title in ((axes[0], os.path.join(r["frontend"], "map.png"),
                            "(a) initial map (scan matcher)"),
                           (axes[1], os.path.join(r["frontend"], "map-samples.png"),
                            f"(a') average of {args.trials} random sample sequences"),
                           (axes[2], os.path.join(r["map"], "map-average.png"),
                            f"(b) average of the {args.trials} optimized maps (hybrid)")):
        ax.imshow(mpimg.imread(png), cmap="gray")
        ax.set_title(title, fontsize=9)
        ax.axis("off")
    ax = axes[3]
    for path in r["paths"]:
        ax.plot([p[0] for p in path], [p[1] for p in path], color="tab:blue", lw=0.5, alpha=0.15)
    if r["reference"]:
        ax.plot([p[0] for p in r["reference"]], [p[1] for p in r["reference"]], color="k", lw=0.6,
                ls="--", label="reference")
        ax.legend(fontsize=7)
    ax.set_aspect("equal")
    ax.set_title(f"(b') {len(r['paths'])} corrected trajectories (hybrid)"
                 + (", aligned" if r["reference"] else ""), fontsize=9)
    ax = axes[4]
    end = max(t[-1][0] for t in r["traces"])
    grid = [end * i / 200 for i in range(201)]
    mean, std = step_mean(r["traces"], grid)
    ax.plot(grid, mean, color="tab:red")
    ax.fill_between(grid, [m - s for m, s in zip(mean, std)], [m + s for m, s in zip(mean, std)],
                    color="tab:red", alpha=0.25)
    ax.set_xlabel("time (s)")
    ax.set_ylabel("best weight (eq. 10), mean +- std")
    ax.set_title(f"(c) {name}: best weight against time, {len(r['traces'])} trials", fontsize=9)
    fig.suptitle(name)
    save_figure(args, fig, f"fig5-{name}")


def main():
    p = parser(__doc__, "fig5")
    count_option(p, "--trials", "trials", 100, 3)
    args = p.parse_args()
    args.iterations = 300 if args.quick else 3000
    args.map_options = ["--resolution", 0.2] if args.quick else []
    check_program(args)
    head = header(args, "experiments/scripts/fig5.py")  # the load before the runs
    names = ["malaga", "aces"] if args.quick else ["malaga", "aces", "intel"]
    rows, table = [], []
    for name in names:
        r = study(args, name)
        plot(args, name, r)
        rows += r["rows"]
        weights = stats([float(t["weight"]) for t in r["trials"]])
        times = stats([float(t["elapsed_s"]) for t in r["trials"]])
        ate = stats([row[3] for row in r["rows"] if row[3] != ""])
        table.append([name, len(r["trials"]), pm(weights), f"{1e3 * times['mean']:.1f}", pm(ate)])
    save_csv(args, "fig5", ["dataset", "seed", "weight", "ate_rmse_m"], rows)
    text = (f"AntSLAM hybrid, {args.iterations} iterations, 20 ants.\n\n"
            + markdown_table(["dataset", "trials", "final weight", "ms per trial",
                              "ATE RMSE (m)"], table))
    save_table(args, head + text)
    print(text, end="")
    progress(f"wrote {args.out}/fig5.csv, table.md, " + ", ".join(f"fig5-{n}.png" for n in names))


if __name__ == "__main__":
    main()
