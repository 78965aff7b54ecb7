#!/usr/bin/python3
"""pcm-aco under several settings on simulated Manhattan pose graphs (simulated_graphs.py), none
of them a public graph: for every size, stated noise scale (1: as it is; 6: six times wider, as
manhattan3500 and intel state theirs; the odometry's another with --odometry-stated), kind of
false closures and graph seed, 1,000 false
closures, then per setting the false closures kept, the recall and the position RMSE against the
outlier-free least-squares map. A setting is `default` or comma-separated options of
antslam.slam.robust (`check_phi=3`, `recalibrate_below=0,check_phi=3`). Writes
robust-simulated.csv (one row per graph and setting), table.md (means per cell, then a
summary per setting) and, for several --stated scales, robust-simulated.png (false closures
kept, recall and RMSE against the stated scale, one line per setting and size).

    PYTHONPATH=build/python /usr/bin/python3 experiments/scripts/robust_simulated.py
        [--poses 1000 3500] [--stated 1 6] [--stated-theta 0.167 6] [--sigma-theta 0.05]
        [--odometry-stated S]
        [--kinds random random-group local-group]
        [--graphs 2] [--settings recalibrate_below=0 recalibrate_below=1e9] [--threads 2]
        [--method pcm-aco]
        [--out results/robust-simulated] [--publish] [--quick]

--quick: 1,000 poses, the noise stated 6 times wider, random false closures, one graph.
--count: false closures per graph (1,000; 0: the clean graphs). --stated-theta: the heading's
stated scale, every pair with every --stated (default: as x-y). --sigma-theta: the real heading
noise per step and closure (0.01 rad; 0.05-0.3: heavy rotation noise, as m3500b).
--method: the robust method every setting runs (pcm-aco; gnc and dcs as peers: `--settings
default`). --antslam is not used (the back ends run in this process).
"""
import math
import os
import sys
import time

import numpy as np

from experiment_common import (count_option, header, integer_at_least, markdown_table, parser,
                               plt, progress, save_csv, save_figure, save_table)
from simulated_graphs import WORLD_SIDE, manhattan_graph

try:
    import antslam
except ImportError:
    sys.exit("robust_simulated.py: error: the antslam Python module is not importable (build "
             "target antslam_python, then PYTHONPATH=build/python)")

def parse_setting(text):
    """`default` -> {}; `a=1,b=2.5` -> {"a": 1, "b": 2.5} (numbers as int or float)."""
    if text == "default":
        return {}
    options = {}
    for item in text.split(","):
        name, sep, value = item.partition("=")
        if not sep or not name:
            raise ValueError(f"'{item}' is not option=value")
        try:
            options[name] = int(value)
        except ValueError:
            options[name] = float(value)
    return options


def run_cell(p, args, graph, kind, seed, settings):
    """pcm-aco under every setting on `graph` spoiled with args.count false closures of `kind`:
    [setting, false closures kept, recall, position RMSE to the outlier-free map, seconds, the
    checked graph's variance factor (None without the joint check)]."""
    clean = antslam.slam.robust(graph, "ls").poses
    spoiled, false = antslam.slam.add_outliers(graph, args.count, kind=kind, seed=seed)
    false_pairs = {tuple(f) for f in false.tolist()}
    cell = []
    for text, options in settings:
        start = time.perf_counter()
        try:
            r = antslam.slam.robust(spoiled, args.method, threads=args.threads, **options)
        except (TypeError, ValueError) as e:  # an unknown or invalid option
            p.error(f"--settings {text}: {e}")
        seconds = time.perf_counter() - start
        kept = [tuple(c) for c in r.closures[r.accepted].tolist()]
        kept_false = sum(c in false_pairs for c in kept)
        recall = (len(kept) - kept_false) / (len(r.closures) - len(false))
        rmse = float(np.sqrt(((r.poses[:, :2] - clean[:, :2]) ** 2).sum(1).mean()))
        cell.append([text, kept_false, recall, rmse, seconds, r.variance_factor])
    return cell


def cell_table(args, rows, names):
    """Means per size, stated noise (x-y, heading) and kind, the settings' values side by side."""
    lines = []
    for poses in args.poses:
        for stated, theta in sorted({(r[1], r[2]) for r in rows}):
            for kind in args.kinds:
                cell = [r for r in rows if r[:4] == [poses, stated, theta, kind]]
                lines.append([poses, f"x{stated:g}, x{theta:g}", kind] + [
                    " / ".join(f"{np.mean([r[i] for r in cell if r[5] == n]):.{d}f}"
                               for n in names) for i, d in ((6, 1), (7, 3), (8, 3), (9, 1))])
    return markdown_table(["poses", "stated noise (x-y, heading)", "false closures",
                           "false kept (" + " / ".join(names) + ")", "recall", "RMSE m",
                           "time s"], lines)


def summary_table(rows, names):
    """One line per setting over all graphs; a run is "within" when its RMSE is at most 1.05x
    (+5 mm) the best setting's on the same graph."""
    best = {}
    for r in rows:
        best[tuple(r[:5])] = min(best.get(tuple(r[:5]), math.inf), r[8])
    lines = []
    for n in names:
        mine = [r for r in rows if r[5] == n]
        lines.append([n, sum(r[6] for r in mine), f"{np.mean([r[7] for r in mine]):.3f}",
                      f"{min(r[7] for r in mine):.3f}", f"{np.mean([r[8] for r in mine]):.3f}",
                      f"{max(r[8] for r in mine):.3f}",
                      sum(r[8] <= 1.05 * best[tuple(r[:5])] + 0.005 for r in mine), len(mine),
                      f"{sum(r[9] for r in mine):.1f}"])
    return markdown_table(["setting", "false kept, all runs", "recall mean", "recall min",
                           "RMSE mean m", "RMSE max m", "runs within 1.05x (+5 mm) of the best",
                           "runs", "time s, all runs"], lines)


def stated_figure(args, rows, names):
    """Means over kinds and graphs against the stated noise scale: one panel per measure, one
    line per setting and size (the sizes solid and dashed)."""
    fig, axes = plt.subplots(1, 3, figsize=(13, 4))
    measures = ((6, "false closures kept (of 1,000)"), (7, "recall"),
                (8, "position RMSE to the outlier-free map, m"))
    for ax, (i, label) in zip(axes, measures):
        for colour, n in enumerate(names):
            for style, poses in zip(("-", "--"), args.poses):
                ax.plot(args.stated, [np.mean([r[i] for r in rows if r[0] == poses and
                                               r[1] == stated and r[5] == n])
                                      for stated in args.stated], style, marker="o",
                        color=f"C{colour}", label=f"{n}, {poses} poses")
        ax.set_xscale("log")
        ax.set_xticks(args.stated, [f"x{s:g}" for s in args.stated])
        ax.minorticks_off()
        ax.set_xlabel("stated noise / real noise (standard deviation)")
        ax.set_ylabel(label)
    axes[0].legend(fontsize=7)
    fig.suptitle(f"{args.method} on simulated Manhattan graphs, {args.count} false closures "
                 "(means over kinds and graphs)")
    save_figure(args, fig, "robust-simulated")


def main():
    p = parser(__doc__, "robust-simulated")
    p.add_argument("--poses", type=int, nargs="+", choices=[1000, 3500], default=[1000, 3500])
    p.add_argument("--stated", type=float, nargs="+", default=[1.0, 6.0],
                   help="stated noise / real noise (standard deviations)")
    p.add_argument("--stated-theta", type=float, nargs="+",
                   help="stated heading noise / real heading noise (default: as --stated)")
    p.add_argument("--sigma-theta", type=float, default=0.01,
                   help="real heading noise of a step and a closure, rad (0.05-0.3: heavy)")
    p.add_argument("--odometry-stated", type=float,
                   help="the odometry's stated noise / real noise (default: as --stated)")
    p.add_argument("--kinds", nargs="+", default=["random", "random-group", "local-group"],
                   help="kinds of false closures")
    p.add_argument("--count", type=integer_at_least(0), default=1000, help="false closures")
    count_option(p, "--graphs", "graph seeds per setting", 2, 1)
    p.add_argument("--settings", nargs="+",
                   default=["recalibrate_below=0", "recalibrate_below=1e9"],
                   help="settings compared: default or option=value[,option=value]")
    p.add_argument("--method", default="pcm-aco", choices=["pcm-aco", "pcm-exact", "gnc", "dcs"],
                   help="the robust method every setting runs")
    p.add_argument("--threads", type=integer_at_least(1), default=2, help="threads of each run")
    args = p.parse_args()
    if args.quick:
        args.poses, args.stated, args.kinds = [1000], [6.0], ["random"]
    if not all(s > 0 for s in args.stated + (args.stated_theta or [])):
        p.error("--stated, --stated-theta: scales must be > 0")
    if not args.sigma_theta > 0:
        p.error("--sigma-theta: must be > 0")
    if args.odometry_stated is not None and not args.odometry_stated > 0:
        p.error("--odometry-stated: the scale must be > 0")
    try:
        settings = [(text, parse_setting(text)) for text in args.settings]
    except ValueError as e:
        p.error(f"--settings: {e}")
    os.makedirs(args.out, exist_ok=True)
    rows = []
    for poses in args.poses:
        for stated, stated_theta in [(s, t) for s in args.stated
                                     for t in (args.stated_theta or [s])]:
            for kind in args.kinds:
                for seed in range(1, args.graphs + 1):
                    g = manhattan_graph(antslam, poses, 100 + seed, world=WORLD_SIDE[poses],
                                        stated_scale=stated, stated_theta_scale=stated_theta,
                                        sigma_theta=args.sigma_theta,
                                        odometry_stated_scale=args.odometry_stated)
                    cell = run_cell(p, args, g, kind, seed, settings)
                    rows += [[poses, stated, stated_theta, kind, seed] + r for r in cell]
                    progress(f"{poses} poses, stated x{stated:g} (heading x{stated_theta:g}), "
                             f"{kind} #{seed}: " + "; ".join(
                                 f"{r[0]} {r[1]} false, recall {r[2]:.3f}, {r[3]:.3f} m"
                                 for r in cell))
    save_csv(args, "robust-simulated", ["poses", "stated", "stated_theta", "kind", "graph",
                                        "setting",
                                        "false_kept", "recall", "rmse_m", "time_s",
                                        "variance_factor"], rows)
    names = [text for text, _ in settings]
    table = cell_table(args, rows, names)
    summary = summary_table(rows, names)
    save_table(args, header(args, "experiments/scripts/robust_simulated.py") + table + "\n" +
               summary)
    if len(args.stated) > 1:
        stated_figure(args, rows, names)
    print(table + "\n" + summary, end="")


if __name__ == "__main__":
    main()
