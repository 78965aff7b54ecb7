#!/usr/bin/python3
"""Variant comparison on fragment sets: AS, ACS, MMAS, the hybrid, hybrid+NLopt, Ceres and random
search at an equal evaluation budget and at an equal wall time. Writes variants.csv, table.md and
the figures variants-weights.png and variants-convergence.png into the results folder.

    /usr/bin/python3 experiments/scripts/variants.py [--quick] [--out results/variants]
        [--set NAME=FRAGMENT_SET.json ...] [--publish]

Sets: the synthetic presets N = 9, 15, 24 (data/fragment-sets/paperN.json), two from real logs
made here with `antslam fragment-set` (malaga: the one-loop log; aces: the corrected aces log
with `antslam simulate-odometry --seed 1` noise), and every --set given.
Budgets: 'evaluations' = 20 ants x 3000 iterations (random: 60000 uniform paths; Ceres is one
shot; hybrid+nlopt adds its NLopt evaluations); 'time' = a wall-clock limit per trial (the ACO
stops there, hybrid+nlopt refines after it). Trials run one at a time on one thread, so each
trial's wall clock is its own.
Target: 1.05 x the lowest mean final weight of the discrete ACO methods at the evaluation budget;
for every method the share of trials that reach it, and the median evaluations and seconds they
needed.

--quick: 3 trials, 300 iterations, 0.01 s; the real set malaga only.
"""
import os

from experiment_common import (DATA, antslam, check_program, header, count_option,
                               markdown_table, median, parser, plt, pm, progress, read_json,
                               read_study, save_csv, save_figure, save_table, stats, step_mean)

METHODS = ["as", "acs", "mmas", "hybrid", "hybrid+nlopt", "ceres", "random"]
DISCRETE_ACO = ["as", "acs", "mmas", "hybrid"]
ANYTIME = ["as", "acs", "mmas", "hybrid", "random"]
ANTS = 20


def budgets(args):
    iterations = 300 if args.quick else 3000
    seconds = 0.01 if args.quick else 0.05
    return {"evaluations": ["--iterations", iterations],
            "time": ["--iterations", 10**9, "--time", seconds]}, iterations * ANTS, seconds


def run_method(args, name, path, method, budget, extra):
    prefix = os.path.join(args.out, "runs", f"{name}.{budget}.{method}")
    os.makedirs(os.path.dirname(prefix), exist_ok=True)
    antslam(args, "optimize", path, "--method", method, "--trials", args.trials, "--threads", 1,
            "--seed", 1, "--ants", ANTS, "-o", prefix, *extra)
    result = read_json(prefix + ".json")
    trials, points = read_study(prefix)
    traces = [[(int(p["evaluations"]), float(p["elapsed_s"]), float(p["best_weight"]))
               for p in trace] for trace in points]
    return {"weight": stats([float(t["weight"]) for t in trials]),
            "elapsed": stats([float(t["elapsed_s"]) for t in trials]),
            "chi2": result["chi2"]["mean"], "traces": traces}


def time_to_target(traces, target):
    """Per trial: the first (evaluations, seconds) at which the best weight is <= target."""
    hits = []
    for trace in traces:
        hit = next(((e, t) for e, t, w in trace if w <= target), None)
        if hit:
            hits.append(hit)
    return hits


def study_set(args, name, path, budget_args):
    runs = {}
    for budget, extra in budget_args.items():
        for method in METHODS:
            progress(f"{name}: {method}, {budget} budget, {args.trials} trials")
            runs[(budget, method)] = run_method(args, name, path, method, budget, extra)
    target = 1.05 * min(runs[("evaluations", m)]["weight"]["mean"] for m in DISCRETE_ACO)
    rows = []
    for method in METHODS:
        for budget in budget_args:
            r = runs[(budget, method)]
            hits = time_to_target(r["traces"], target)
            rows.append([name, budget, method, r["weight"]["n"], r["weight"]["mean"],
                         r["weight"]["std"], r["weight"]["min"], r["weight"]["max"], r["chi2"],
                         r["elapsed"]["mean"], target, len(hits) / max(1, len(r["traces"])),
                         median([h[0] for h in hits]), median([h[1] for h in hits])])
    return runs, target, rows


def plot_weights(args, results, budget_args):
    names = list(results)
    fig, axes = plt.subplots(len(budget_args), len(names), figsize=(3.6 * len(names), 6.4),
                             squeeze=False)
    for col, name in enumerate(names):
        runs, target, _ = results[name]
        for row, budget in enumerate(budget_args):
            ax = axes[row][col]
            for k, method in enumerate(METHODS):
                w = runs[(budget, method)]["weight"]
                ax.errorbar([k], [w["mean"]], yerr=[w["std"]], fmt="o", capsize=4,
                            color=plt.cm.tab10(k))
            ax.axhline(target, color="0.5", ls=":", lw=1)
            ax.set_xticks(range(len(METHODS)))
            ax.set_xticklabels(METHODS, rotation=45, ha="right", fontsize=8)
            ax.set_title(f"{name}: {budget} budget", fontsize=9)
            ax.set_ylabel("final weight (eq. 10), mean +- std")
    save_figure(args, fig, "variants-weights")


def plot_convergence(args, results, evaluations):
    names = list(results)
    fig, axes = plt.subplots(1, len(names), figsize=(3.8 * len(names), 3.6), squeeze=False)
    for ax, name in zip(axes[0], names):
        runs, target, _ = results[name]
        for k, method in enumerate(METHODS):
            r = runs[("evaluations", method)]
            if method in ANYTIME:
                # Traces hold the improvements; the last best holds until the budget is spent.
                traces = [[(e, w) for e, _, w in tr] + [(evaluations, tr[-1][2])]
                          for tr in r["traces"]]
                grid = [int(ANTS * (evaluations / ANTS) ** (i / 100)) for i in range(101)]
                mean, _ = step_mean(traces, grid)
                ax.plot(grid, mean, label=method, color=plt.cm.tab10(k))
            else:
                ax.axhline(r["weight"]["mean"], label=f"{method} (final)", color=plt.cm.tab10(k),
                           ls="--", lw=1)
        ax.axhline(target, color="0.5", ls=":", lw=1, label="target")
        ax.set_xscale("log")
        ax.set_xlabel("paths evaluated")
        ax.set_ylabel("best weight so far (mean over trials)")
        ax.set_title(name, fontsize=9)
    axes[0][0].legend(fontsize=7)
    save_figure(args, fig, "variants-convergence")


def real_sets(args):
    """Fragment sets of the one-loop log and (not with --quick) of a noise-corrupted corrected
    log."""
    laser = os.path.join(DATA, "laser")
    work = os.path.join(args.out, "sets")
    malaga, aces = os.path.join(work, "malaga.json"), os.path.join(work, "aces.json")
    progress("fragment set of malaga-oneloop")
    antslam(args, "fragment-set", os.path.join(laser, "malaga-oneloop.clf"), "-o", malaga)
    if args.quick:
        return [("malaga", malaga)]
    progress("fragment set of aces (simulated odometry, seed 1)")
    antslam(args, "simulate-odometry", os.path.join(laser, "corrected", "aces-corrected.log.gz"),
            "--out", os.path.join(work, "aces"), "--seed", 1)
    antslam(args, "fragment-set", os.path.join(work, "aces", "log.clf"), "-o", aces)
    return [("malaga", malaga), ("aces", aces)]


def summary(rows, names, budget):
    """Sets x methods at one budget (rows as in variants.csv)."""
    table = []
    for name in names:
        cells = {r[2]: r for r in rows if r[0] == name and r[1] == budget}
        best = min(cells[m][4] for m in METHODS)
        table.append([name] + [(f"**{cells[m][4]:.2f} +- {cells[m][5]:.2f}**"
                                if cells[m][4] <= best * (1 + 1e-9) else
                                f"{cells[m][4]:.2f} +- {cells[m][5]:.2f}") for m in METHODS])
    return markdown_table(["set"] + METHODS, table)


def main():
    p = parser(__doc__, "variants")
    p.add_argument("--set", action="append", default=[], metavar="NAME=PATH",
                   help="a further fragment set (JSON or .g2o)")
    count_option(p, "--trials", "trials per method", 100, 3)
    args = p.parse_args()
    check_program(args)
    budget_args, evaluations, seconds = budgets(args)
    sets = [(f"paper{n}", os.path.join(DATA, "fragment-sets", f"paper{n}.json"))
            for n in (9, 15, 24)]
    sets += real_sets(args) + [tuple(s.split("=", 1)) for s in args.set]
    text = [header(args, "experiments/scripts/variants.py"),
            f"{args.trials} trials per method and budget; evaluation budget {evaluations} paths "
            f"({ANTS} ants); time budget {seconds} s per trial.\n\n"]
    results, all_rows = {}, []
    for name, path in sets:
        results[name] = study_set(args, name, path, budget_args)
        runs, target, rows = results[name]
        all_rows += rows
        table = []
        for method in METHODS:
            e, t = runs[("evaluations", method)], runs[("time", method)]
            hits = time_to_target(e["traces"], target)
            table.append([method, pm(e["weight"]), f"{e['weight']['min']:.3f}",
                          f"{1e3 * e['elapsed']['mean']:.1f}", pm(t["weight"]),
                          f"{len(hits)}/{len(e['traces'])}",
                          f"{median([h[0] for h in hits]):.0f}" if hits else "-",
                          f"{1e3 * median([h[1] for h in hits]):.1f}" if hits else "-"])
        text.append(f"### {name} (target weight {target:.3f})\n\n")
        text.append(markdown_table(
            ["method", "weight, evaluation budget", "best", "ms per trial",
             "weight, time budget", "reached target", "median paths to target",
             "median ms to target"], table) + "\n")
    save_csv(args, "variants",
             ["set", "budget", "method", "trials", "mean_weight", "std_weight", "min_weight",
              "max_weight", "mean_chi2", "mean_time_s", "target_weight", "reached_fraction",
              "median_evaluations_to_target", "median_seconds_to_target"], all_rows)
    plot_weights(args, results, budget_args)
    plot_convergence(args, results, evaluations)
    summaries = "".join(
        f"Final weight (eq. 10) at the equal {budget} budget, mean +- std; lowest in bold:\n\n"
        + summary(all_rows, [name for name, _ in sets], budget) + "\n" for budget in budget_args)
    save_table(args, text[0] + text[1] + summaries + "".join(text[2:]))
    print(text[1] + summaries + "".join(text[2:]), end="")
    progress(f"wrote {args.out}/variants.csv, table.md, variants-weights.png, "
             "variants-convergence.png")


if __name__ == "__main__":
    main()
