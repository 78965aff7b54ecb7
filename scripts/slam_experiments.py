#!/usr/bin/python3
"""AntSLAM experiments: rho of the hybrid, every method on the paper's three sizes, convergence
(paper Fig. 5 c/f/i), and the standard g2o pose graphs. Runs the `antslam` program, writes CSV
and PNG to docs/figures/ and the tables to docs/slamgraph-results.md.

    /usr/bin/python3 scripts/slam_experiments.py [--antslam build/experiments/antslam]
        [--bench build/bench/bench_slam] [--threads 1] [--trials 100]
        [--only rho,methods,maps,g2o]       (docs/slamgraph-results.md)
    /usr/bin/python3 scripts/slam_experiments.py --only scaling   (docs/slamgraph-scaling.md)
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import tempfile
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FIGURES = os.path.join(ROOT, "docs", "figures")
PRESETS = ["paper9", "paper15", "paper24"]
RHOS = [0.01, 0.02, 0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 0.8, 0.9, 0.95, 1.0]
METHODS = ["as", "eas", "ras", "acs", "mmas", "hybrid", "hybrid+nlopt", "random", "nlopt",
           "ceres", "ceres-robust"]
DISCRETE = ["as", "eas", "ras", "acs", "mmas", "hybrid", "random"]
GRAPHS = [("ring", "ring.gt.g2o"), ("mit", None), ("intel", None),
          ("manhattan3500", "manhattan3500.gt.dat")]
GRAPH_METHODS = ["ceres", "ceres-robust", "nlopt", "hybrid", "hybrid+nlopt"]


def run(args, *cmd):
    subprocess.run([args.antslam, *cmd], check=True, stdout=subprocess.DEVNULL)


def optimize(args, work, fragment_set, method, tag, trials, extra=()):
    prefix = os.path.join(work, tag)
    run(args, "optimize", fragment_set, "--method", method, "--trials", str(trials),
        "--threads", str(args.threads), "--seed", "1", "-o", prefix, *extra)
    with open(prefix + ".json") as f:
        result = json.load(f)
    with open(prefix + ".times.json") as f:
        result["elapsed_s"] = json.load(f)["elapsed_s"]
    return result, prefix


def synth(args, work, preset, seed):
    path = os.path.join(work, f"{preset}-s{seed}.json")
    run(args, "synth", "--preset", preset, "--seed", str(seed), "-o", path)
    return path


def rho_study(args, work, out):
    rows = []
    for preset in PRESETS:
        for rho in RHOS:
            for seed in (1, 2, 3):
                fs = synth(args, work, preset, seed)
                r, _ = optimize(args, work, fs, "hybrid", f"rho-{preset}-{seed}-{rho}",
                                args.trials, ("--rho", str(rho)))
                rows.append([preset, seed, rho, r["weight"]["mean"], r["weight"]["std"],
                             r["elapsed_s"]["mean"]])
    with open(os.path.join(FIGURES, "slamgraph-rho.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["preset", "set_seed", "rho", "mean_weight", "std_weight", "mean_time_s"])
        w.writerows(rows)
    fig, axes = plt.subplots(1, 3, figsize=(13, 3.8))
    out.append("## Evaporation rate of the hybrid\n")
    out.append("Mean final weight over %d trials (3000 iterations, 20 ants), averaged over three "
               "synthetic sets per size (synth seeds 1-3).\n" % args.trials)
    out.append("| rho | " + " | ".join(PRESETS) + " |\n|---|" + "---|" * len(PRESETS) + "\n")
    table = {}
    for ax, preset in zip(axes, PRESETS):
        for seed in (1, 2, 3):
            pts = [(r[2], r[3], r[4]) for r in rows if r[0] == preset and r[1] == seed]
            ax.errorbar([p[0] for p in pts], [p[1] for p in pts], yerr=[p[2] for p in pts],
                        marker="o", capsize=3, label=f"set seed {seed}")
        for rho in RHOS:
            vals = [r[3] for r in rows if r[0] == preset and r[2] == rho]
            table.setdefault(rho, []).append(sum(vals) / len(vals))
        ax.set_xscale("log")
        ax.set_title(f"{preset}: hybrid, mean +- std over {args.trials} trials")
        ax.set_xlabel("rho")
        ax.set_ylabel("final weight (eq. 10)")
        ax.legend(fontsize=8)
    for rho in RHOS:
        out.append(f"| {rho} | " + " | ".join(f"{v:.4f}" for v in table[rho]) + " |\n")
    fig.tight_layout()
    fig.savefig(os.path.join(FIGURES, "slamgraph-rho.png"), dpi=110)
    out.append("\n![rho](figures/slamgraph-rho.png)\n\n")


def step_mean(traces, grid):
    """Mean and std over trials of the best weight (a step function of time) on a grid; a grid
    point is drawn once 95% of the trials have a first result."""
    means, stds = [], []
    for t in grid:
        vals = []
        for trace in traces:
            v = None
            for (et, w) in trace:
                if et <= t:
                    v = w
            if v is not None:
                vals.append(v)
        if len(vals) < 0.95 * len(traces):
            means.append(float("nan"))
            stds.append(float("nan"))
            continue
        m = sum(vals) / len(vals)
        means.append(m)
        stds.append((sum((v - m) ** 2 for v in vals) / max(1, len(vals) - 1)) ** 0.5)
    return means, stds


def read_traces(prefix):
    with open(prefix + ".times.json") as f:
        times = json.load(f)["trials"]
    traces = {}
    with open(prefix + ".convergence.csv") as f:
        for row in csv.DictReader(f):
            traces.setdefault(int(row["trial"]), []).append(float(row["best_weight"]))
    return [[(elapsed, w) for (_, elapsed), w in zip(times[t]["convergence"], weights)]
            for t, weights in sorted(traces.items())]


def methods_study(args, work, out):
    rows = []
    fig, axes = plt.subplots(1, 3, figsize=(14, 4.2))
    conv_fig, conv_axes = plt.subplots(1, 3, figsize=(14, 3.8))
    out.append("## Every method on the paper's three sizes\n")
    out.append("Synthetic sets `synth --preset paperN --seed 1`; %d trials per method; ACO "
               "methods 3000 iterations with their default ants (hybrid 20, ACS 10, others 20); "
               "random: the same 60000 evaluations; nlopt / ceres start from the means mu_i. "
               "Weight = eq. (10), chi2 = sum of squared Mahalanobis distances, ATE = "
               "translation RMSE of the fragment frames against the ground truth after rigid "
               "alignment (best trial).\n\n" % args.trials)
    for ax, conv_ax, preset in zip(axes, conv_axes, PRESETS):
        fs = synth(args, work, preset, 1)
        out.append(f"### {preset}\n\n| method | weight mean +- std | best | chi2 mean | "
                   "time per trial (ms) | ATE best (m) |\n|---|---|---|---|---|---|\n")
        for method in METHODS:
            r, prefix = optimize(args, work, fs, method, f"m-{preset}-{method}", args.trials)
            ate = r.get("trajectory_error", {}).get("rmse_m", float("nan"))
            rows.append([preset, method, r["weight"]["mean"], r["weight"]["std"],
                         r["weight"]["min"], r["chi2"]["mean"], r["elapsed_s"]["mean"], ate])
            out.append(f"| {method} | {r['weight']['mean']:.4f} +- {r['weight']['std']:.4f} | "
                       f"{r['weight']['min']:.4f} | {r['chi2']['mean']:.4g} | "
                       f"{1e3 * r['elapsed_s']['mean']:.2f} | {ate:.3f} |\n")
            ax.errorbar([1e3 * r["elapsed_s"]["mean"]], [r["weight"]["mean"]],
                        yerr=[r["weight"]["std"]], capsize=3, label=method,
                        color=plt.cm.tab20(METHODS.index(method) / len(METHODS)),
                        marker="o" if method in DISCRETE else "s")
            if method in ("hybrid", "mmas", "acs", "random", "hybrid+nlopt"):
                traces = read_traces(prefix)
                end = max(t[-1][0] for t in traces)
                grid = [end * k / 200 for k in range(1, 201)]
                m, s = step_mean(traces, grid)
                ms = [1e3 * g for g in grid]
                conv_ax.plot(ms, m, label=method)
                conv_ax.fill_between(ms, [a - b for a, b in zip(m, s)],
                                     [a + b for a, b in zip(m, s)], alpha=0.2)
        out.append("\n")
        ax.set_xscale("log")
        ax.set_xlabel("time per trial (ms, log)")
        ax.set_ylabel("final weight (eq. 10)")
        ax.set_title(f"{preset}: mean +- std over {args.trials} trials")
        conv_ax.set_xlabel("time (ms)")
        conv_ax.set_ylabel("best weight so far")
        conv_ax.set_title(f"{preset}: mean +- std over {args.trials} trials")
    axes[0].legend(fontsize=7)
    conv_axes[0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(FIGURES, "slamgraph-methods.png"), dpi=110)
    conv_fig.tight_layout()
    conv_fig.savefig(os.path.join(FIGURES, "slamgraph-convergence.png"), dpi=110)
    with open(os.path.join(FIGURES, "slamgraph-methods.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["preset", "method", "mean_weight", "std_weight", "best_weight",
                    "mean_chi2", "mean_time_s", "ate_best_m"])
        w.writerows(rows)
    out.append("![methods](figures/slamgraph-methods.png)\n\n")
    out.append("Convergence (as the paper's Fig. 5 c, f, i): best weight so far against time, "
               "mean +- std over the trials.\n\n![convergence](figures/slamgraph-convergence.png)"
               "\n\n")


def g2o_study(args, work, out):
    rows = []
    out.append("## Standard pose graphs (data/posegraphs)\n\n")
    out.append("Imported with M = 20 samples per alignment (`antslam g2o`); one trial per "
               "method (seed 1); ACO 3000 iterations x 20 ants. ATE against the ground truth "
               "where the data set has one.\n\n")
    out.append("| graph | N | closures | method | weight | chi2 | time (s) | ATE (m) |\n"
               "|---|---|---|---|---|---|---|---|\n")
    for name, gt in GRAPHS:
        graph = os.path.join(ROOT, "data", "posegraphs", name + ".g2o")
        extra = ("--reference", os.path.join(ROOT, "data", "posegraphs", gt)) if gt else ()
        for method in GRAPH_METHODS:
            r, _ = optimize(args, work, graph, method, f"g-{name}-{method}", 1, extra)
            ate = r.get("trajectory_error", {}).get("rmse_m", float("nan"))
            n = len(r["best"]["frames"])
            with open(graph) as f:
                edges = sum(1 for line in f if line.startswith("EDGE_SE2"))
            rows.append([name, method, r["weight"]["mean"], r["chi2"]["mean"],
                         r["elapsed_s"]["mean"], ate])
            out.append(f"| {name} | {n} | {edges - (n - 1)} | {method} | "
                       f"{r['weight']['mean']:.2f} | {r['chi2']['mean']:.5g} | "
                       f"{r['elapsed_s']['mean']:.3f} | {ate:.3f} |\n")
    with open(os.path.join(FIGURES, "slamgraph-g2o.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["graph", "method", "weight", "chi2", "time_s", "ate_m"])
        w.writerows(rows)
    out.append("\n")


def compose(a, b):
    c, s_ = math.cos(a[2]), math.sin(a[2])
    return (a[0] + c * b[0] - s_ * b[1], a[1] + s_ * b[0] + c * b[1], a[2] + b[2])


def world_path(fragment_set, frames):
    """The robot path in W: each fragment's trajectory moved by its frame (frames if none)."""
    xs, ys = [], []
    for frame, fragment in zip(frames, fragment_set["fragments"]):
        for p in fragment.get("trajectory", [[0, 0, 0, 0]]):
            w = compose(frame, p[1:])
            xs.append(w[0])
            ys.append(w[1])
    return xs, ys


def chain(alignments):
    frames = [(0.0, 0.0, 0.0)]
    for a in alignments:
        frames.append(compose(frames[-1], a))
    return frames


def maps_study(args, work, out):
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.6))
    out.append("## Maps\n\nRobot paths of the shipped synthetic sets and of ring.g2o: the scan "
               "matcher's map (chain of the means mu_i), the best of %d hybrid trials, Ceres "
               "least squares, and the ground truth.\n\n" % args.trials)
    for ax, name in zip(axes, ["paper15", "paper24", "ring"]):
        if name == "ring":
            fs_path = os.path.join(work, "ring.json")
            run(args, "g2o", os.path.join(ROOT, "data", "posegraphs", "ring.g2o"), "-o", fs_path,
                "--reference", os.path.join(ROOT, "data", "posegraphs", "ring.gt.g2o"))
        else:
            fs_path = os.path.join(ROOT, "data", "fragment-sets", name + ".json")
        with open(fs_path) as f:
            fs = json.load(f)
        means = chain([fr["alignment"]["mean"] for fr in fs["fragments"][1:]])
        ax.plot(*world_path(fs, means), color="0.6", lw=1, label="scan matcher (means)")
        for method, color, trials in (("hybrid", "tab:red", args.trials), ("ceres", "tab:blue", 1)):
            r, _ = optimize(args, work, fs_path, method, f"map-{name}-{method}", trials)
            ax.plot(*world_path(fs, r["best"]["frames"]), color=color, lw=1.2,
                    label=f"{method} (weight {r['best']['weight']:.2f})")
        ax.plot(*world_path(fs, fs["reference"]), "k--", lw=1, label="ground truth")
        ax.set_aspect("equal")
        ax.set_title(name)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(FIGURES, "slamgraph-maps.png"), dpi=110)
    out.append("![maps](figures/slamgraph-maps.png)\n\n")


def bench_rates(args):
    """One run of BM_Trials and BM_ParallelControl: rate per benchmark name."""
    text = subprocess.run([args.bench, "--benchmark_filter=Trials|Control",
                           "--benchmark_format=json"],
                          check=True, capture_output=True, text=True).stdout
    return {b["run_name"].split("/real_time")[0]: b.get("trials_per_s", b.get("tasks_per_s"))
            for b in json.loads(text)["benchmarks"]}


def scaling_study(args, work, out):
    """100 trials of paper9 on 1 and 2 threads beside a pure-arithmetic control, repeated in
    several time windows because the two cores are shared with other users."""
    out.append("## Thread scaling\n\n`build/bench/bench_slam --benchmark_filter='Trials|Control'`"
               " run %d times, %d s apart. BM_Trials: 100 independent hybrid trials of paper9 "
               "(paper configuration) spread over TBB threads; BM_ParallelControl: 100 tasks of "
               "pure arithmetic spread the same way. The control's speedup is what the shared "
               "machine gave in that window (1.0: the second core was busy elsewhere).\n\n"
               % (args.scaling_runs, args.scaling_pause))
    out.append("| window | load | trials/s, 1 thread | trials/s, 2 threads | trials speedup | "
               "control speedup |\n|---|---|---|---|---|---|\n")
    usable = []
    for k in range(args.scaling_runs):
        with open("/proc/loadavg") as f:
            load = f.read().split()[0]
        r = bench_rates(args)
        trials = r["BM_Trials/2"] / r["BM_Trials/1"]
        control = r["BM_ParallelControl/2"] / r["BM_ParallelControl/1"]
        if control >= 1.8:
            usable.append(trials)
        out.append(f"| {time.strftime('%H:%M:%S')} | {load} | {r['BM_Trials/1']:.1f} | "
                   f"{r['BM_Trials/2']:.1f} | {trials:.2f} | {control:.2f} |\n")
        if k + 1 < args.scaling_runs:
            time.sleep(args.scaling_pause)
    usable.sort()
    mid = len(usable) // 2
    median = usable[mid] if len(usable) % 2 else 0.5 * (usable[mid - 1] + usable[mid]) if usable else 0
    summary = (f"median trials speedup {median:.2f} (range {usable[0]:.2f} to "
               f"{usable[-1]:.2f}) over the {len(usable)} windows whose control reached 1.8"
               if usable else "no window had a free second core (control below 1.8)")
    out.append(f"\n{summary}.\n\n")


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("--antslam", default=os.path.join(ROOT, "build", "experiments", "antslam"))
    p.add_argument("--bench", default=os.path.join(ROOT, "build", "bench", "bench_slam"))
    p.add_argument("--threads", type=int, default=1,
                   help="threads of antslam optimize (1: per-trial times are not shared)")
    p.add_argument("--trials", type=int, default=100)
    p.add_argument("--only", default="rho,methods,maps,g2o",
                   help="studies; 'scaling' alone writes docs/slamgraph-scaling.md")
    p.add_argument("--scaling-runs", type=int, default=12)
    p.add_argument("--scaling-pause", type=int, default=30, help="seconds between runs")
    args = p.parse_args()
    os.makedirs(FIGURES, exist_ok=True)
    studies = {"scaling": scaling_study, "rho": rho_study, "methods": methods_study,
               "maps": maps_study, "g2o": g2o_study}
    with open("/proc/loadavg") as f:
        load = f.read().split()[0]
    out = ["# AntSLAM %s\n\n" % ("thread scaling" if args.only == "scaling" else "results"),
           "Generated by `/usr/bin/python3 scripts/slam_experiments.py --threads %d --trials %d "
           "--only %s` on %s (%d cores; load average %s at the start: the machine is shared, "
           "so times are indicative).\n\n"
           % (args.threads, args.trials, args.only, time.strftime("%Y-%m-%d"), os.cpu_count(),
              load)]
    with tempfile.TemporaryDirectory() as work:
        for name in args.only.split(","):
            studies[name](args, work, out)
            print(f"slam_experiments: {name} done", file=sys.stderr)
    name = {"rho,methods,maps,g2o": "slamgraph-results", "scaling": "slamgraph-scaling"}.get(
        args.only, "slamgraph-results-" + args.only.replace(",", "-"))
    with open(os.path.join(ROOT, "docs", name + ".md"), "w") as f:
        f.writelines(out)


if __name__ == "__main__":
    main()
