#!/usr/bin/python3
"""One option of the ants' clique search (antslam.clique.aco, the search of `antslam robust
--method pcm-aco`), chosen on generated graphs only. For every graph, the exact maximum (branch
and bound, --exact-limit s) and the ants' clique (the program's defaults but OPTION) for every
value of OPTION and ant seeds 1..SEEDS; "best known" is the largest clique any search found.

Two families of generated graphs (--family):
- random: G(n, p) of four kinds, from sparse like the consistency graph of mit with 1,000 false
  closures to dense like manhattan3500's (whose maximum clique branch and bound cannot prove);
- manhattan: the consistency graphs (antslam.slam.consistency) of simulated Manhattan pose
  graphs (simulated_graphs.py: 800 poses in a 60 x 60 world, with few loop closures as mit,
  1,000 in 12 x 12 and 3,500 in 25 x 25, with many; the noise stated half as wide as it is, as it
  is, or 6 times wider) spoiled with 100 or 1,000 false closures of each of the four kinds of
  `antslam outliers`: the graphs pcm-aco meets, none of them one of the public pose graphs.

OPTION: plateau_steps (the plateau walk after each ant's (1,2)-swaps, clique/local_search.hpp),
restart_stagnant (MAX-MIN's trails re-initialised when its restart-best is that many iterations
old), beta (the heuristic's exponent), rho (evaporation) or proof_nodes (branch and bound from
the colony's clique for at most that many nodes: a proof or a larger clique; "ants proven"
counts the runs whose clique is proven maximum). Writes clique-FAMILY-OPTION.csv
(one row per graph, value and seed; underscores as hyphens), table.md and
clique-FAMILY-OPTION.png.

    PYTHONPATH=build/python /usr/bin/python3 experiments/scripts/clique_options.py
        [--family random] [--option plateau_steps] [--values 0 5 10 20 50] [--graphs N]
        [--seeds 3] [--threads 1] [--out results/clique-options] [--exact-limit 20]
        [--publish] [--quick]

--quick: 2 graphs per kind (random) or 4 (manhattan: 1,000 poses, 100 false closures of each
kind, the noise stated 6 times wider), 1 ant seed, branch and bound 2 s.
--antslam is not used (the searches run in this process).
"""
import os
import sys

import numpy as np

from experiment_common import (count_option, header, integer_at_least, markdown_table, parser,
                               plt, progress, save_csv, save_figure, save_table)
from simulated_graphs import WORLD_SIDE, manhattan_graph

try:
    import antslam
except ImportError:
    sys.exit("clique_options.py: error: the antslam Python module is not importable (build "
             "target antslam_python, then PYTHONPATH=build/python)")

# option: (label, type)
OPTIONS = {"plateau_steps": ("plateau steps", int),
           "restart_stagnant": ("restart after stagnant iterations", int),
           "beta": ("heuristic exponent beta", float), "rho": ("evaporation rho", float),
           "proof_nodes": ("branch-and-bound nodes after the colony", int)}
# random: (group, vertices, edge probability)
RANDOM = [("sparse", 1000, 0.05), ("medium", 400, 0.5), ("dense", 200, 0.9),
          ("large-dense", 1000, 0.9)]
# manhattan: (poses, world side), stated noise scales, false closure counts
MANHATTAN = [(poses, WORLD_SIDE[poses]) for poses in (800, 1000, 3500)]
STATED = [0.5, 1.0, 6.0]
COUNTS = [100, 1000]
OUTLIER_KINDS = ["random", "local", "random-group", "local-group"]


def random_graph(n, p, seed):
    rng = np.random.default_rng(seed)
    i, j = np.triu_indices(n, 1)
    keep = rng.random(i.size) < p
    return antslam.clique.Graph(n, np.column_stack((i[keep], j[keep])))


def generated(family, graphs, quick):
    """(group, graph id, graph) for every generated graph, built when asked for (quick: the
    manhattan family's 1,000 poses with 100 false closures and the noise stated 6 times wider)."""
    if family == "random":
        for group, n, p in RANDOM:
            for seed in range(1, graphs + 1):
                yield group, f"G({n}, {p}) #{seed}", lambda n=n, p=p, s=seed: random_graph(n, p, s)
        return
    for poses, world in MANHATTAN[1:2] if quick else MANHATTAN:
        for kind in OUTLIER_KINDS:
            for stated in STATED[2:] if quick else STATED:
                for count in COUNTS[:1] if quick else COUNTS:
                    for seed in range(1, graphs + 1):
                        def build(poses=poses, world=world, stated=stated, count=count,
                                  kind=kind, seed=seed):
                            g = manhattan_graph(antslam, poses, seed, world=world,
                                                stated_scale=stated)
                            spoiled, _ = antslam.slam.add_outliers(g, count, kind=kind,
                                                                   seed=seed)
                            return antslam.slam.consistency(spoiled).graph
                        yield (f"{poses} poses, {kind}",
                               f"stated x{stated:g}, {count} false #{seed}", build)


def plot(args, rows, values, groups, name):
    fig, axes = plt.subplots(1, 2, figsize=(11, 3.8))
    for k, group in enumerate(groups):  # colour: the kind; line style: the size (manhattan)
        style = dict(marker="o", label=group, color=f"C{k % 4}", linestyle=["-", "--", ":"][k // 4])
        gap = [np.mean([r[5] - r[4] for r in rows if r[0] == group and r[2] == v])
               for v in values]
        time = [np.mean([r[6] for r in rows if r[0] == group and r[2] == v]) for v in values]
        axes[0].plot(values, gap, **style)
        axes[1].plot(values, time, **style)
    axes[0].set_ylabel("best known - ants' clique (vertices)")
    axes[1].set_ylabel(f"ants' time, s ({args.threads} thread{'s' * (args.threads > 1)})")
    axes[1].set_yscale("log")
    for ax in axes:
        ax.set_xlabel(OPTIONS[args.option][0])
        ax.legend(fontsize=7)
    save_figure(args, fig, name)


def main():
    p = parser(__doc__, "clique-options")
    p.add_argument("--family", choices=["random", "manhattan"], default="random",
                   help="the generated graphs")
    p.add_argument("--graphs", type=integer_at_least(1), default=None,
                   help="graphs per kind (random 5, manhattan 2; quick 2 and 1)")
    count_option(p, "--seeds", "ant seeds per graph and value", 3, 1)
    p.add_argument("--option", choices=sorted(OPTIONS), default="plateau_steps",
                   help="the option compared")
    p.add_argument("--values", type=float, nargs="+", default=[0, 5, 10, 20, 50],
                   help="its values (>= 0)")
    p.add_argument("--threads", type=integer_at_least(1), default=1, help="threads of the ants")
    p.add_argument("--exact-limit", type=float, default=None,
                   help="branch-and-bound budget per graph, s (20; quick 2)")
    args = p.parse_args()
    if args.graphs is None:
        args.graphs = (2 if args.quick else 5) if args.family == "random" else (
            1 if args.quick else 2)
    if args.exact_limit is None:
        args.exact_limit = 2.0 if args.quick else 20.0
    if not args.exact_limit > 0:
        p.error("--exact-limit: must be > 0 s")
    kind = OPTIONS[args.option][1]
    if any(not v >= 0 or kind(v) != v for v in args.values):
        p.error(f"--values: {args.option} takes {'whole numbers' if kind is int else 'numbers'}"
                " >= 0")
    values = [kind(v) for v in args.values]
    name = f"clique-{args.family}-{args.option.replace('_', '-')}"
    os.makedirs(args.out, exist_ok=True)
    rows, groups = [], []
    for group, graph_id, build in generated(args.family, args.graphs, args.quick):
        if group not in groups:
            groups.append(group)
        g = build()
        exact = antslam.clique.exact(g, args.exact_limit)
        runs = {(v, seed): antslam.clique.aco(g, seed=seed, threads=args.threads,
                                              **{args.option: v})
                for v in values for seed in range(1, args.seeds + 1)}
        best = max([exact.weight] + [r.weight for r in runs.values()])
        for (v, seed), r in runs.items():
            rows.append([group, graph_id, v, seed, r.weight, best, r.clique.elapsed_s,
                         exact.weight, exact.optimal, exact.elapsed_s, r.clique.optimal])
        means = {v: np.mean([runs[v, k].weight for k in range(1, args.seeds + 1)])
                 for v in values}
        progress(f"{group}, {graph_id}: exact {exact.weight:.0f}"
                 f"{'' if exact.optimal else ' (budget)'}, ants "
                 + ", ".join(f"{v:g}: {m:.2f}" for v, m in means.items()))
    save_csv(args, name, ["group", "graph", args.option, "seed", "ants_clique",
                                      "best_known", "ants_s", "exact_clique", "exact_optimal",
                                      "exact_s", "ants_optimal"], rows)
    table_rows = []
    for group in groups:
        for v in values:
            cell = [r for r in rows if r[0] == group and r[2] == v]
            hits = sum(r[4] >= r[5] for r in cell)
            table_rows.append([group, f"{v:g}", f"{np.mean([r[4] for r in cell]):.2f}",
                               f"{np.mean([r[5] for r in cell]):.2f}", f"{hits}/{len(cell)}",
                               f"{np.mean([r[6] for r in cell]):.3f}",
                               f"{len({r[1] for r in cell if r[8]})}/{len({r[1] for r in cell})}",
                               f"{sum(r[10] for r in cell)}/{len(cell)}"])
    table = markdown_table(["graphs", OPTIONS[args.option][0], "ants' clique", "best known",
                            "runs at best known", "ants s", "exact proven", "ants proven"],
                           table_rows)
    save_table(args, header(args, "experiments/scripts/clique_options.py") + table)
    print(table, end="")
    plot(args, rows, values, groups, name)


if __name__ == "__main__":
    main()
