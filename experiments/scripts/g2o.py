#!/usr/bin/python3
"""Standard 2D pose graphs (data/posegraphs: ring, mit, intel, manhattan3500), imported with
M = 20 samples per alignment, under Ceres (plain and under the eq. (10) loss), NLopt from the
means, the hybrid and hybrid+NLopt: one trial each (`antslam optimize GRAPH.g2o --method M
--trials 1 --seed 1`, ACO 3000 iterations x 20 ants), eq. (10) weight, chi2, time and the ATE
against the ground truth where the data set has one. Writes g2o.csv and table.md into the
results folder.

    /usr/bin/python3 experiments/scripts/g2o.py [--quick] [--threads 1] [--out results/g2o]
        [--publish]

--quick: ring only, ACO 300 iterations.
"""
import os

from experiment_common import (DATA, antslam, check_program, header, parser, progress,
                               read_result, save_csv, save_table, threads_option)

GRAPHS = [("ring", "ring.gt.g2o"), ("mit", None), ("intel", None),
          ("manhattan3500", "manhattan3500.gt.dat")]
METHODS = ["ceres", "ceres-robust", "nlopt", "hybrid", "hybrid+nlopt"]
POSEGRAPHS = os.path.join(DATA, "posegraphs")


def edges(graph):
    with open(graph) as f:
        return sum(1 for line in f if line.startswith("EDGE_SE2"))


def main():
    p = parser(__doc__, "g2o")
    threads_option(p)
    args = p.parse_args()
    check_program(args)
    head = header(args, "experiments/scripts/g2o.py")  # the load before the runs
    graphs = GRAPHS[:1] if args.quick else GRAPHS
    rows, lines = [], []
    for name, truth in graphs:
        graph = os.path.join(POSEGRAPHS, name + ".g2o")
        reference = ["--reference", os.path.join(POSEGRAPHS, truth)] if truth else []
        for method in METHODS:
            progress(f"{name}: {method}")
            prefix = os.path.join(args.out, "runs", f"g-{name}-{method}")
            antslam(args, "optimize", graph, "--method", method, "--trials", 1, "--threads",
                    args.threads, "--seed", 1, "-o", prefix, *reference,
                    *(["--iterations", 300] if args.quick else []))
            r = read_result(prefix)
            ate = r.get("trajectory_error", {}).get("rmse_m", float("nan"))
            n = len(r["best"]["frames"])
            rows.append([name, method, r["weight"]["mean"], r["chi2"]["mean"],
                         r["elapsed_s"]["mean"], ate])
            lines.append(f"| {name} | {n} | {edges(graph) - (n - 1)} | {method} | "
                         f"{r['weight']['mean']:.2f} | {r['chi2']['mean']:.5g} | "
                         f"{r['elapsed_s']['mean']:.3f} | {ate:.3f} |\n")
    save_csv(args, "g2o", ["graph", "method", "weight", "chi2", "time_s", "ate_m"], rows)
    text = ("Imported with M = 20 samples per alignment (`antslam g2o`); one trial per method "
            f"(seed 1); ACO {300 if args.quick else 3000} iterations x 20 ants. ATE against the "
            "ground truth where the data set has one.\n\n"
            "| graph | N | closures | method | weight | chi2 | time (s) | ATE (m) |\n"
            "|---|---|---|---|---|---|---|---|\n" + "".join(lines))
    save_table(args, head + text)
    print(text, end="")
    progress(f"wrote {args.out}/g2o.csv, table.md")


if __name__ == "__main__":
    main()
