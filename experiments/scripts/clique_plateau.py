#!/usr/bin/python3
"""Length of the plateau walk after each ant's (1,2)-swaps (clique/local_search.hpp), chosen on
generated graphs only: random graphs G(n, p) of four kinds, from sparse like the consistency
graph of mit with 1,000 false closures to dense like manhattan3500's (whose maximum clique branch
and bound cannot prove). For every graph (seeds 1..GRAPHS), the exact maximum (branch and bound,
--exact-limit s) and the ants' clique (antslam.clique.aco, the defaults of `antslam robust
--method pcm-aco`, 1 thread) for every walk length and ant seeds 1..SEEDS. Writes
clique-plateau.csv (one row per graph, length and seed), table.md and clique-plateau.png.

    PYTHONPATH=build/python /usr/bin/python3 experiments/scripts/clique_plateau.py
        [--graphs 5] [--seeds 3] [--steps 0 5 10 20 50] [--out results/clique-plateau]
        [--exact-limit 20] [--publish] [--quick]

--quick: 2 graphs per kind, 1 ant seed, branch and bound 2 s. --antslam is not used (the
searches run in this process).
"""
import os
import sys

import numpy as np

from experiment_common import (count_option, header, markdown_table, parser, plt, progress,
                               save_csv, save_figure, save_table)

try:
    import antslam
except ImportError:
    sys.exit("clique_plateau.py: error: the antslam Python module is not importable (build "
             "target antslam_python, then PYTHONPATH=build/python)")

# name, vertices, edge probability
KINDS = [("sparse", 1000, 0.05), ("medium", 400, 0.5), ("dense", 200, 0.9),
         ("large-dense", 1000, 0.9)]


def random_graph(n, p, seed):
    rng = np.random.default_rng(seed)
    i, j = np.triu_indices(n, 1)
    keep = rng.random(i.size) < p
    return antslam.clique.Graph(n, np.column_stack((i[keep], j[keep])))


def plot(args, rows, steps):
    fig, axes = plt.subplots(1, 2, figsize=(11, 3.8))
    for kind, _, _ in KINDS:
        gap = [np.mean([r[5] - r[4] for r in rows if r[0] == kind and r[2] == s]) for s in steps]
        time = [np.mean([r[6] for r in rows if r[0] == kind and r[2] == s]) for s in steps]
        axes[0].plot(steps, gap, marker="o", label=kind)
        axes[1].plot(steps, time, marker="o", label=kind)
    axes[0].set_ylabel("best known - ants' clique (vertices)")
    axes[1].set_ylabel("ants' time, s (1 thread)")
    axes[1].set_yscale("log")
    for ax in axes:
        ax.set_xlabel("plateau steps")
        ax.legend(fontsize=8)
    save_figure(args, fig, "clique-plateau")


def main():
    p = parser(__doc__, "clique-plateau")
    count_option(p, "--graphs", "random graphs per kind", 5, 2)
    count_option(p, "--seeds", "ant seeds per graph and length", 3, 1)
    p.add_argument("--steps", type=int, nargs="+", default=[0, 5, 10, 20, 50],
                   help="plateau walk lengths to compare")
    p.add_argument("--exact-limit", type=float, default=None,
                   help="branch-and-bound budget per graph, s (20; quick 2)")
    args = p.parse_args()
    if args.exact_limit is None:
        args.exact_limit = 2.0 if args.quick else 20.0
    if not args.exact_limit > 0:
        p.error("--exact-limit: must be > 0 s")
    if any(s < 0 for s in args.steps):
        p.error("--steps: lengths must be >= 0")
    os.makedirs(args.out, exist_ok=True)
    rows = []
    for kind, n, prob in KINDS:
        for g_seed in range(1, args.graphs + 1):
            g = random_graph(n, prob, g_seed)
            exact = antslam.clique.exact(g, args.exact_limit)
            runs = {(steps, seed): antslam.clique.aco(g, seed=seed, plateau_steps=steps)
                    for steps in args.steps for seed in range(1, args.seeds + 1)}
            best = max([exact.weight] + [r.weight for r in runs.values()])
            for (steps, seed), r in runs.items():
                rows.append([kind, g_seed, steps, seed, r.weight, best, r.clique.elapsed_s,
                             exact.weight, exact.optimal, exact.elapsed_s])
            means = {s: np.mean([runs[s, k].weight for k in range(1, args.seeds + 1)])
                     for s in args.steps}
            progress(f"{kind} graph {g_seed}: exact {exact.weight:.0f}"
                     f"{'' if exact.optimal else ' (budget)'}, ants "
                     + ", ".join(f"{s}: {m:.2f}" for s, m in means.items()))
    save_csv(args, "clique-plateau", ["kind", "graph", "plateau_steps", "seed", "ants_clique",
                                      "best_known", "ants_s", "exact_clique", "exact_optimal",
                                      "exact_s"], rows)
    table_rows = []
    for kind, n, prob in KINDS:
        for s in args.steps:
            cell = [r for r in rows if r[0] == kind and r[2] == s]
            hits = sum(r[4] >= r[5] for r in cell)
            table_rows.append([f"{kind} G({n}, {prob})", s, f"{np.mean([r[4] for r in cell]):.2f}",
                               f"{np.mean([r[5] for r in cell]):.2f}", f"{hits}/{len(cell)}",
                               f"{np.mean([r[6] for r in cell]):.3f}",
                               f"{len({r[1] for r in cell if r[8]})}/{args.graphs}"])
    table = markdown_table(["graphs", "plateau steps", "ants' clique", "best known",
                            "runs at best known", "ants s", "exact proven"], table_rows)
    save_table(args, header(args, "experiments/scripts/clique_plateau.py") + table)
    print(table, end="")
    plot(args, rows, args.steps)


if __name__ == "__main__":
    main()
