#!/usr/bin/python3
"""Evaporation rate of the hybrid (Algorithm 2; the paper leaves rho open): the final eq. (10)
weight, mean +- std over the trials, for rho from 0.01 to 1 on three synthetic sets of each of
the paper's sizes (`antslam synth --preset paperN --seed 1..3`, N = 9, 15, 24), every set and rho
`antslam optimize --method hybrid --trials T --seed 1 --rho RHO` (3000 iterations, 20 ants).
Writes rho.csv (one row per size, set and rho), table.md (the mean over the three sets) and
rho.png into the results folder.

    /usr/bin/python3 experiments/scripts/rho.py [--quick] [--trials 100] [--threads 1]
        [--out results/rho] [--publish]

--quick: 2 trials of 300 iterations, rho 0.05, 0.5 and 1 only.
"""
import os

from experiment_common import (antslam, check_program, count_option, header, parser, plt,
                               progress, read_result, save_csv, save_figure, save_table,
                               threads_option)

PRESETS = ["paper9", "paper15", "paper24"]
RHOS = [0.01, 0.02, 0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 0.8, 0.9, 0.95, 1.0]
QUICK_RHOS = [0.05, 0.5, 1.0]
SET_SEEDS = (1, 2, 3)


def synth(args, preset, seed):
    path = os.path.join(args.out, "sets", f"{preset}-s{seed}.json")
    antslam(args, "synth", "--preset", preset, "--seed", seed, "-o", path)
    return path


def run(args, fragment_set, preset, seed, rho):
    prefix = os.path.join(args.out, "runs", f"rho-{preset}-{seed}-{rho}")
    antslam(args, "optimize", fragment_set, "--method", "hybrid", "--trials", args.trials,
            "--threads", args.threads, "--seed", 1, "-o", prefix, "--rho", rho,
            *args.iteration_options)
    return read_result(prefix)


def plot(args, rows):
    fig, axes = plt.subplots(1, 3, figsize=(13, 3.8))
    for ax, preset in zip(axes, PRESETS):
        for seed in SET_SEEDS:
            points = [(r[2], r[3], r[4]) for r in rows if r[0] == preset and r[1] == seed]
            ax.errorbar([p[0] for p in points], [p[1] for p in points],
                        yerr=[p[2] for p in points], marker="o", capsize=3,
                        label=f"set seed {seed}")
        ax.set_xscale("log")
        ax.set_title(f"{preset}: hybrid, mean +- std over {args.trials} trials")
        ax.set_xlabel("rho")
        ax.set_ylabel("final weight (eq. 10)")
        ax.legend(fontsize=8)
    save_figure(args, fig, "rho")


def table(args, rows, rhos):
    """Mean final weight per rho and size, averaged over the three sets."""
    lines = [f"Mean final weight over {args.trials} trials ({args.iterations} iterations, 20 "
             "ants), averaged over three synthetic sets per size (synth seeds 1-3).\n\n",
             "| rho | " + " | ".join(PRESETS) + " |\n|---|" + "---|" * len(PRESETS) + "\n"]
    for rho in rhos:
        means = []
        for preset in PRESETS:
            values = [r[3] for r in rows if r[0] == preset and r[2] == rho]
            means.append(sum(values) / len(values))
        lines.append(f"| {rho} | " + " | ".join(f"{v:.4f}" for v in means) + " |\n")
    return "".join(lines) + "\n![rho](figures/results-rho.png)\n"


def main():
    p = parser(__doc__, "rho")
    count_option(p, "--trials", "trials per set and rho", 100, 2)
    threads_option(p)
    args = p.parse_args()
    args.iterations = 300 if args.quick else 3000
    args.iteration_options = ["--iterations", 300] if args.quick else []
    rhos = QUICK_RHOS if args.quick else RHOS
    check_program(args)
    head = header(args, "experiments/scripts/rho.py")  # the load before the runs
    rows = []
    for preset in PRESETS:
        progress(f"{preset}: {len(rhos)} rho values x {len(SET_SEEDS)} sets, "
                 f"{args.trials} trials each")
        sets = {seed: synth(args, preset, seed) for seed in SET_SEEDS}
        for rho in rhos:
            for seed in SET_SEEDS:
                r = run(args, sets[seed], preset, seed, rho)
                rows.append([preset, seed, rho, r["weight"]["mean"], r["weight"]["std"],
                             r["elapsed_s"]["mean"]])
    save_csv(args, "rho", ["preset", "set_seed", "rho", "mean_weight", "std_weight",
                           "mean_time_s"], rows)
    plot(args, rows)
    text = table(args, rows, rhos)
    save_table(args, head + text)
    print(text, end="")
    progress(f"wrote {args.out}/rho.csv, table.md, rho.png")


if __name__ == "__main__":
    main()
