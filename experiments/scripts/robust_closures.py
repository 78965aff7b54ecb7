#!/usr/bin/python3
"""Robust back ends against false loop closures (docs/robust-closures.md).

For every pose graph x outlier count x kind x seed: `antslam outliers` adds the false closures
(Suenderhauf & Protzel 2012), then `antslam robust` runs every method on the spoiled graph and
reports precision, recall, ATE against the outlier-free least-squares solution (and against the
ground truth where the graph has one) and time. Seeds are the outer loop, so a run stopped early
(or resumed with --resume) holds the whole grid for the seeds it finished. Per seed, the
spoiled graphs are made first, then every method runs on them: with --ranks K each stage is one
`mpirun -np K antslam batch` (the same files; each run still uses --threads threads).

Writes OUT/robust.csv (one row per run), OUT/table.md (means over the seeds) and one figure per
graph, OUT/robust-GRAPH.png: precision, recall and ATE against the outlier count, one column per
kind, one line per method.
"""
import csv
import os

from experiment_common import (DATA, antslam, check_program, count_option, header,
                               integer_at_least, load_average, markdown_table, parser, plt,
                               progress, ranks_option, read_csv, read_json, run_batch, save_csv,
                               save_figure, save_table, stats)

METHODS = ["ls", "cauchy", "dcs", "gnc", "pcm-exact", "pcm-aco"]
KINDS = ["random", "local", "random-group", "local-group"]
GROUND_TRUTH = {"manhattan3500": "manhattan3500.gt.dat", "ring": "ring.gt.g2o"}
FULL = {"graphs": ["intel", "mit", "manhattan3500", "ring"], "counts": [0, 10, 100, 500, 1000],
        "kinds": KINDS}
# --quick: every method and both sorts of kind on the small ring graph
QUICK = {"graphs": ["ring"], "counts": [0, 10], "kinds": ["random", "local-group"]}
COLUMNS = ["graph", "kind", "count", "seed", "method", "closures", "accepted", "false_accepted",
           "precision", "recall", "ate_ls_m", "ate_gt_m", "time_s", "consistency_s", "clique_s",
           "optimize_s", "clique_size", "clique_optimal", "clique_bound", "load"]


def options():
    p = parser(__doc__, "robust")
    p.add_argument("--graphs", nargs="+", help=f"pose graphs in data/posegraphs ({FULL['graphs']})")
    p.add_argument("--counts", nargs="+", type=integer_at_least(0),
                   help=f"false closures per graph ({FULL['counts']})")
    p.add_argument("--kinds", nargs="+", choices=KINDS, help=f"kinds of false closure ({KINDS})")
    p.add_argument("--methods", nargs="+", choices=METHODS, default=METHODS,
                   help=f"back ends ({METHODS})")
    p.add_argument("--plateau-steps", type=integer_at_least(0),
                   help="pcm-aco: its --plateau-steps (default: the program's)")
    p.add_argument("--restart-stagnant", type=integer_at_least(0),
                   help="pcm-aco: its --restart-stagnant (default: the program's)")
    p.add_argument("--proof-nodes", type=integer_at_least(0),
                   help="pcm-aco: its --proof-nodes (default: the program's)")
    p.add_argument("--recalibrate-below", type=float,
                   help="pcm-*: the recalibrated check's threshold (antslam robust "
                        "--recalibrate-below; default: the program's)")
    p.add_argument("--check-phi", type=float,
                   help="pcm-*: the check's Phi from the noise the clique shows (antslam robust "
                        "--check-phi; default: the program's)")
    count_option(p, "--seeds", "seeds 1..N per count and kind", 10, 1)
    count_option(p, "--threads", "threads of the consistency and the ants", 2, 2)
    ranks_option(p)
    p.add_argument("--resume", action="store_true", help="keep the runs already in OUT/runs")
    p.add_argument("--collect", action="store_true",
                   help="run nothing: tabulate and plot the runs in OUT/runs (a grid gathered "
                        "from several calls; cases without a run are left out)")
    p.add_argument("--earlier", metavar="CSV",
                   help="rows of an earlier robust.csv (such as docs/figures/results-robust.csv) "
                        "to tabulate with this call's runs; a case run here replaces its row")
    args = p.parse_args()
    if args.check_phi is not None and not 0 <= args.check_phi < float("inf"):
        p.error(f"--check-phi: {args.check_phi} is not a finite number >= 0")
    if args.earlier:
        args.earlier_rows = earlier_rows(p, args.earlier)
    defaults = QUICK if args.quick else FULL
    for name, value in defaults.items():
        if getattr(args, name) is None:
            setattr(args, name, value)
    for graph in args.graphs:
        if not os.path.exists(os.path.join(DATA, "posegraphs", graph + ".g2o")):
            p.error(f"--graphs: unknown {graph} (none of data/posegraphs/*.g2o)")
    return args


def earlier_rows(p, path):
    """The rows of an earlier robust.csv, as lists in COLUMNS order (a parser error if it is
    missing or has other columns)."""
    if not os.path.isfile(path):
        p.error(f"--earlier: {path}: no such file")
    with open(path) as f:
        reader = csv.reader(f)
        if next(reader, None) != COLUMNS:
            p.error(f"--earlier: {path}: line 1: expected the columns {','.join(COLUMNS)}")
        return list(reader)


def case_of(row):
    """The case a row (in COLUMNS order) belongs to: graph, kind, count, seed and method."""
    return tuple(str(v) for v in row[:5])


def with_earlier(args, rows):
    """This call's rows after the earlier rows (--earlier) of the cases it did not run."""
    if not args.earlier:
        return rows
    run_here = {case_of(r) for r in rows}
    return [r for r in args.earlier_rows if case_of(r) not in run_here] + rows


def spoil(args, graph, kind, count, seed):
    """The spoiled graph of one case (path) and the `antslam outliers` job that makes it."""
    spoiled = os.path.join(args.out, "graphs", f"{graph}-{kind}-{count}-{seed}.g2o")
    return spoiled, ["outliers", os.path.join(DATA, "posegraphs", graph + ".g2o"), "--count",
                     count, "--kind", kind, "--seed", seed, "-o", spoiled]


def run_cases(args, cases):
    """The rows of the cases (graph, kind, count, seed, reference, ground truth), every method
    (skipping the runs --resume finds): first every spoiled graph, then every method on them,
    each stage one batch of independent runs (run_batch: over --ranks MPI ranks)."""
    todo = []  # (spoiled graph, its outliers job, method, output prefix, refs)
    for graph, kind, count, seed, reference, ground_truth in cases:
        spoiled, outliers = spoil(args, graph, kind, count, seed)
        refs = ["--reference", reference] + (["--reference", ground_truth] if ground_truth
                                             else [])
        for method in args.methods:
            prefix = os.path.join(args.out, "runs", f"{graph}-{kind}-{count}-{seed}-{method}")
            if not (args.collect or (args.resume and os.path.exists(prefix + ".json"))):
                todo.append((spoiled, outliers, method, prefix, refs))
    needed = {t[0]: t[1] for t in todo if not os.path.exists(t[0])}
    run_batch(args, list(needed.values()), "outliers")
    load = load_average()
    ant_options = [] if args.plateau_steps is None else ["--plateau-steps", args.plateau_steps]
    if args.restart_stagnant is not None:
        ant_options += ["--restart-stagnant", args.restart_stagnant]
    if args.proof_nodes is not None:
        ant_options += ["--proof-nodes", args.proof_nodes]
    pcm_options = ([] if args.recalibrate_below is None else
                   ["--recalibrate-below", args.recalibrate_below])
    if args.check_phi is not None:
        pcm_options += ["--check-phi", args.check_phi]
    run_batch(args, [["robust", spoiled, "--method", method, "--threads", args.threads, *refs,
                      *(ant_options if method == "pcm-aco" else []),
                      *(pcm_options if method.startswith("pcm") else []), "-o", prefix]
                     for spoiled, _, method, prefix, refs in todo], "robust")
    for _, _, _, prefix, _ in todo:
        for ext in (".g2o", ".accepted.txt"):
            os.remove(prefix + ext)
        with open(prefix + ".load", "w") as f:
            f.write(f"{load}\n")
    rows = []
    for graph, kind, count, seed, _, _ in cases:
        spoiled, _ = spoil(args, graph, kind, count, seed)
        for method in args.methods:
            prefix = os.path.join(args.out, "runs", f"{graph}-{kind}-{count}-{seed}-{method}")
            if os.path.exists(prefix + ".json") or not args.collect:
                rows.append(row_of(graph, kind, count, seed, method, prefix))
        for path in (spoiled, spoiled.replace(".g2o", ".outliers.txt")):
            if os.path.exists(path):
                os.remove(path)
    return rows


def row_of(graph, kind, count, seed, method, prefix):
    r = read_json(prefix + ".json")
    with open(prefix + ".load") as f:
        load = float(f.read())
    outliers = r.get("outliers", {})
    ate = [a["rmse_m"] for a in r["ate"]]
    clique = r.get("clique", {})
    t = r["time_s"]
    return [graph, kind, count, seed, method, r["closures"], r["accepted"],
            outliers.get("accepted", 0), outliers.get("precision"), outliers.get("recall"),
            ate[0], ate[1] if len(ate) > 1 else None, t["total"], t["consistency"], t["clique"],
            t["optimize"], clique.get("size"), clique.get("optimal"), clique.get("upper_bound"),
            load]


def number(value):
    return None if value in ("", None) else float(value)


def summarize(args, rows):
    """table.md: per graph, kind, count and method the means over the seeds."""
    groups = {}
    for r in rows:
        groups.setdefault((r["graph"], r["kind"], int(r["count"]), r["method"]), []).append(r)
    table = []
    for (graph, kind, count, method), rs in sorted(groups.items()):
        cell = {c: stats([number(r[c]) for r in rs]) for c in
                ("precision", "recall", "ate_ls_m", "ate_gt_m", "time_s", "clique_size")}
        fmt = lambda s, d=3: "-" if s["n"] == 0 else f"{s['mean']:.{d}f}"  # noqa: E731
        table.append([graph, kind, count, method, len(rs), fmt(cell["precision"]),
                      fmt(cell["recall"]), fmt(cell["ate_ls_m"]), fmt(cell["ate_gt_m"]),
                      fmt(cell["time_s"], 2), fmt(cell["clique_size"], 1)])
    text = (header(args, "experiments/scripts/robust_closures.py") +
            "Means over the seeds; precision and recall of the accepted loop closures, ATE "
            "(m, rigid alignment) against the outlier-free least-squares solution (ls) and the "
            "ground truth (gt), wall-clock seconds of the whole call.\n\n" +
            markdown_table(["graph", "kind", "false", "method", "seeds", "precision", "recall",
                            "ATE ls", "ATE gt", "time s", "clique"], table) +
            "\n" + clique_table(rows))
    save_table(args, text)
    print(text)


def clique_table(rows):
    """The ants' clique against branch and bound, run by run: sizes, whether the exact search
    finished (proved its clique maximum) within its budget, and the clique stage's seconds."""
    runs = {}
    for r in rows:
        if r["method"] in ("pcm-exact", "pcm-aco"):
            runs.setdefault((r["graph"], r["kind"], int(r["count"]), r["seed"]), {})[r["method"]] = r
    table = {}
    for (graph, kind, count, _), pair in sorted(runs.items()):
        if len(pair) < 2:
            continue
        exact, ants = pair["pcm-exact"], pair["pcm-aco"]
        cell = table.setdefault((graph, kind, count), {"n": 0, "proved": 0, "ratio": [],
                                                       "bigger": 0, "exact_s": [], "ants_s": []})
        cell["n"] += 1
        cell["proved"] += exact["clique_optimal"] == "True"
        if exact["clique_optimal"] == "True":
            cell["ratio"].append(float(ants["clique_size"]) / float(exact["clique_size"]))
        cell["bigger"] += float(ants["clique_size"]) > float(exact["clique_size"])
        cell["exact_s"].append(float(exact["clique_s"]))
        cell["ants_s"].append(float(ants["clique_s"]))
    lines = []
    for (graph, kind, count), c in table.items():
        ratio = f"{min(c['ratio']):.4f}" if c["ratio"] else "-"
        lines.append([graph, kind, count, c["n"], c["proved"], ratio, c["bigger"],
                      f"{stats(c['exact_s'])['mean']:.2f}", f"{stats(c['ants_s'])['mean']:.2f}"])
    return ("Maximum clique: the ants (pcm-aco) against branch and bound (pcm-exact, 60 s), per "
            "graph, kind and count over the seeds: runs, runs the exact search finished, the "
            "least ratio ants / exact where it finished, runs where the ants' clique is larger, "
            "mean seconds of the clique stage.\n\n" +
            markdown_table(["graph", "kind", "false", "runs", "exact finished", "min ants/exact",
                            "ants larger", "exact s", "ants s"], lines))


def plot(args, rows):
    colours = dict(zip(METHODS, ["tab:gray", "tab:orange", "tab:green", "tab:purple",
                                 "tab:blue", "tab:red"]))
    for graph in args.graphs:
        fig, axes = plt.subplots(3, len(args.kinds), figsize=(4 * len(args.kinds), 9),
                                 squeeze=False)
        for col, kind in enumerate(args.kinds):
            for method in args.methods:
                points = {}
                for r in rows:
                    if r["graph"] == graph and r["method"] == method and \
                            (r["kind"] == kind or int(r["count"]) == 0):
                        points.setdefault(int(r["count"]), []).append(r)
                counts = sorted(points)
                for row, column in enumerate(("precision", "recall", "ate_ls_m")):
                    means = [stats([number(r[column]) for r in points[c]])["mean"] for c in counts]
                    axes[row][col].plot(counts, means, "o-", color=colours.get(method),
                                        label=method, markersize=3)
            axes[0][col].set_title(f"{graph}: {kind}")
            for row, label in enumerate(("precision", "recall", "ATE vs ls (m)")):
                axes[row][col].set_xlabel("false loop closures")
                axes[row][col].set_ylabel(label)
                axes[row][col].set_xscale("symlog", linthresh=10)
            axes[2][col].set_yscale("symlog", linthresh=0.01)
        axes[0][0].legend(fontsize=8)
        save_figure(args, fig, f"robust-{graph}")
        plt.close(fig)


def main():
    args = options()
    check_program(args)
    for sub in ("graphs", "runs", "refs"):
        os.makedirs(os.path.join(args.out, sub), exist_ok=True)
    references = {}
    for graph in args.graphs:
        prefix = os.path.join(args.out, "refs", graph + "-ls")
        if not os.path.exists(prefix + ".g2o"):
            antslam(args, "robust", os.path.join(DATA, "posegraphs", graph + ".g2o"), "--method",
                    "ls", "--outliers", os.devnull, "-o", prefix)
        references[graph] = prefix + ".g2o"
    rows = []
    for seed in range(1, args.seeds + 1):
        cases = []
        for graph in args.graphs:
            truth = GROUND_TRUTH.get(graph)
            truth = os.path.join(DATA, "posegraphs", truth) if truth else None
            for count in args.counts:
                for kind in (args.kinds if count > 0 else ["none"]):
                    if count == 0 and seed > 1:
                        continue  # no false closures: nothing random
                    cases.append((graph, kind if count else "random", count, seed,
                                  references[graph], truth))
        progress(f"seed {seed}: {len(cases)} spoiled graphs x {len(args.methods)} methods")
        rows += run_cases(args, cases)
        save_csv(args, "robust", COLUMNS, with_earlier(args, rows))
    rows = read_csv(os.path.join(args.out, "robust.csv"))
    summarize(args, rows)
    plot(args, rows)
    progress(f"wrote {args.out}/robust.csv, table.md and robust-*.png")


if __name__ == "__main__":
    main()
