#!/usr/bin/python3
"""Every method on the paper's three sizes: the ACO variants (AS, EAS, RAS, ACS, MMAS, the
hybrid), hybrid+NLopt, random search, NLopt and Ceres (plain and under the eq. (10) loss) on the
synthetic sets `antslam synth --preset paperN --seed 1` (N = 9, 15, 24), each
`antslam optimize --method M --trials T --seed 1`. Final eq. (10) weight, chi2, time per trial
and the best trial's ATE against the set's ground truth; and the convergence (the paper's Fig. 5
c, f, i): best weight so far against time, mean +- std over the trials. Writes methods.csv,
table.md, methods.png and methods-convergence.png into the results folder.

    /usr/bin/python3 experiments/scripts/methods.py [--quick] [--trials 100] [--threads 1]
        [--out results/methods] [--publish]

--quick: 2 trials of 300 iterations.
"""
import os

from experiment_common import (antslam, check_program, header, count_option, parser, plt,
                               progress, read_result, read_study, save_csv, save_figure,
                               save_table, step_mean, threads_option)

PRESETS = ["paper9", "paper15", "paper24"]
METHODS = ["as", "eas", "ras", "acs", "mmas", "hybrid", "hybrid+nlopt", "random", "nlopt",
           "ceres", "ceres-robust"]
DISCRETE = ["as", "eas", "ras", "acs", "mmas", "hybrid", "random"]
CONVERGENCE = ["hybrid", "mmas", "acs", "random", "hybrid+nlopt"]


def run(args, fragment_set, preset, method):
    prefix = os.path.join(args.out, "runs", f"m-{preset}-{method}")
    antslam(args, "optimize", fragment_set, "--method", method, "--trials", args.trials,
            "--threads", args.threads, "--seed", 1, "-o", prefix, *args.iteration_options)
    return read_result(prefix), prefix


def plot_convergence(ax, prefix, method):
    """Best weight so far against time, mean +- std over the trials, on 200 grid points."""
    _, points = read_study(prefix)
    traces = [[(float(p["elapsed_s"]), float(p["best_weight"])) for p in trace]
              for trace in points]
    end = max(t[-1][0] for t in traces)
    grid = [end * k / 200 for k in range(1, 201)]
    mean, std = step_mean(traces, grid)
    ms = [1e3 * g for g in grid]
    ax.plot(ms, mean, label=method)
    ax.fill_between(ms, [a - b for a, b in zip(mean, std)], [a + b for a, b in zip(mean, std)],
                    alpha=0.2)


def main():
    p = parser(__doc__, "methods")
    count_option(p, "--trials", "trials per method", 100, 2)
    threads_option(p)
    args = p.parse_args()
    args.iteration_options = ["--iterations", 300] if args.quick else []
    check_program(args)
    head = header(args, "experiments/scripts/methods.py")  # the load before the runs
    rows = []
    fig, axes = plt.subplots(1, 3, figsize=(14, 4.2))
    conv_fig, conv_axes = plt.subplots(1, 3, figsize=(14, 3.8))
    iterations = 300 if args.quick else 3000
    text = [f"Synthetic sets `synth --preset paperN --seed 1`; {args.trials} trials per method; "
            f"ACO methods {iterations} iterations with their default ants (hybrid 20, ACS 10, "
            f"others 20); random: the same {20 * iterations} evaluations; nlopt / "
            "ceres start from the means mu_i. Weight = eq. (10), chi2 = sum of squared "
            "Mahalanobis distances, ATE = translation RMSE of the fragment frames against the "
            "ground truth after rigid alignment (best trial).\n\n"]
    for ax, conv_ax, preset in zip(axes, conv_axes, PRESETS):
        fragment_set = os.path.join(args.out, "sets", f"{preset}-s1.json")
        antslam(args, "synth", "--preset", preset, "--seed", 1, "-o", fragment_set)
        text.append(f"### {preset}\n\n| method | weight mean +- std | best | chi2 mean | "
                    "time per trial (ms) | ATE best (m) |\n|---|---|---|---|---|---|\n")
        for method in METHODS:
            progress(f"{preset}: {method}, {args.trials} trials")
            r, prefix = run(args, fragment_set, preset, method)
            ate = r.get("trajectory_error", {}).get("rmse_m", float("nan"))
            rows.append([preset, method, r["weight"]["mean"], r["weight"]["std"],
                         r["weight"]["min"], r["chi2"]["mean"], r["elapsed_s"]["mean"], ate])
            text.append(f"| {method} | {r['weight']['mean']:.4f} +- {r['weight']['std']:.4f} | "
                        f"{r['weight']['min']:.4f} | {r['chi2']['mean']:.4g} | "
                        f"{1e3 * r['elapsed_s']['mean']:.2f} | {ate:.3f} |\n")
            ax.errorbar([1e3 * r["elapsed_s"]["mean"]], [r["weight"]["mean"]],
                        yerr=[r["weight"]["std"]], capsize=3, label=method,
                        color=plt.cm.tab20(METHODS.index(method) / len(METHODS)),
                        marker="o" if method in DISCRETE else "s")
            if method in CONVERGENCE:
                plot_convergence(conv_ax, prefix, method)
        text.append("\n")
        ax.set_xscale("log")
        ax.set_xlabel("time per trial (ms, log)")
        ax.set_ylabel("final weight (eq. 10)")
        ax.set_title(f"{preset}: mean +- std over {args.trials} trials")
        conv_ax.set_xlabel("time (ms)")
        conv_ax.set_ylabel("best weight so far")
        conv_ax.set_title(f"{preset}: mean +- std over {args.trials} trials")
    axes[0].legend(fontsize=7)
    conv_axes[0].legend(fontsize=8)
    save_figure(args, fig, "methods")
    save_figure(args, conv_fig, "methods-convergence")
    save_csv(args, "methods", ["preset", "method", "mean_weight", "std_weight", "best_weight",
                               "mean_chi2", "mean_time_s", "ate_best_m"], rows)
    text.append("![methods](figures/results-methods.png)\n\nConvergence (as the paper's Fig. 5 "
                "c, f, i): best weight so far against time, mean +- std over the trials.\n\n"
                "![convergence](figures/results-methods-convergence.png)\n")
    save_table(args, head + "".join(text))
    print("".join(text), end="")
    progress(f"wrote {args.out}/methods.csv, table.md, methods.png, methods-convergence.png")


if __name__ == "__main__":
    main()
