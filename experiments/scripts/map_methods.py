#!/usr/bin/python3
"""Every optimizer through the whole pipeline (`antslam map`) on the bundled logs malaga-oneloop
(--laser-offset 0.78, no reference), intel-subset and mit-csail (--reference
data/laser/LOG.ref.tum): eq. (10) weight (best and mean of the 20 trials), loop closures within
their 2-sigma ellipse, the largest closure Mahalanobis distance, ATE RMSE against the reference
and the run times; and the scan matcher alone. Every optimizer runs with `--no-closing` (its own
map, docs/mapping.md); `default` is `antslam map`'s default, hybrid+nlopt and then the loops
closed with the trusted closures. `hybrid+nlopt-plain` is `--method hybrid+nlopt
--no-graduated` (the refinement of eq. (10) alone). Every run `antslam map LOG --method M
--threads 1 --no-maps` (seed 1, one thread, so that the times are comparable). Writes
map_methods.csv, table.md and each run's report (LOG-METHOD/report.json, LOG-METHOD.txt) into
the results folder.

    /usr/bin/python3 experiments/scripts/map_methods.py [--quick] [--out results/map-methods]
        [--publish]

--quick: malaga-oneloop only, the default, hybrid+nlopt without graduation and ceres, 2 trials
of 300 iterations.
"""
import os

from experiment_common import (DATA, antslam, check_program, header, parser, progress,
                               read_json, save_csv, save_table, write_text)

METHODS = ["default", "hybrid+nlopt", "hybrid+nlopt-plain", "hybrid", "mmas", "nlopt", "ceres",
           "ceres-robust"]
LOGS = {"malaga-oneloop": ["--laser-offset", "0.78"],
        "intel-subset": ["--reference", os.path.join(DATA, "laser", "intel-subset.ref.tum")],
        "mit-csail": ["--reference", os.path.join(DATA, "laser", "mit-csail.ref.tum")]}
QUICK = ["default", "hybrid+nlopt-plain", "ceres"]
COLUMNS = ["log", "method", "best_weight", "mean_weight", "closures_within_2_sigma", "closures",
           "largest_closure_mahalanobis", "ate_rmse_m", "optimization_s", "total_s"]


def run(args, log, method):
    """`antslam map` of one log and method; its report."""
    options = {"default": [],
               "hybrid+nlopt-plain": ["--method", "hybrid+nlopt", "--no-graduated",
                                      "--no-closing"]}.get(method,
                                                           ["--method", method, "--no-closing"])
    out = os.path.join(args.out, f"{log}-{method}")
    stdout = antslam(args, "map", os.path.join(DATA, "laser", log + ".clf"), *options,
                     "--threads", 1, "--no-maps", "--out", out, *LOGS[log],
                     *(["--trials", 2, "--iterations", 300] if args.quick else []))
    write_text(out + ".txt", stdout)
    return read_json(os.path.join(out, "report.json"))


def method_row(log, method, report):
    o, closures, times = report["optimization"], report["closures"], report["times"]
    ate = (report["evaluation"]["optimized"]["ate"]["translation_m"]["rmse"]
           if "evaluation" in report else None)
    return [log, method, o["best"]["weight"], o["weight"]["mean"],
            sum(c["within_2_sigma"] for c in closures), len(closures),
            max(c["optimized"]["mahalanobis"] for c in closures), ate,
            times["optimization_s"], times["total_s"]]


def scan_matcher_row(log, report):
    """The scan matcher alone (the frontend's map, before any optimisation)."""
    closures = report["closures"]
    ate = (report["evaluation"]["scan_matcher"]["ate"]["translation_m"]["rmse"]
           if "evaluation" in report else None)
    mahalanobis = [c["scan_matcher"]["mahalanobis"] for c in closures]
    return [log, "scan matcher alone", report["optimization"]["scan_matcher"]["weight"], None,
            sum(m <= 2 for m in mahalanobis), len(closures), max(mahalanobis), ate, None,
            report["times"]["frontend_s"]]


def markdown_row(row):
    log, method, best, mean, within, closures, largest, ate, optimization, total = row
    if method == "scan matcher alone":
        weight, optimization, total = f"{best:.2f}", "-", f"{total:.1f} (frontend)"
    else:
        weight, optimization, total = f"{best:.2f} / {mean:.2f}", f"{optimization:.2f}", \
            f"{total:.1f}"
    return (f"| {log} | {method} | {weight} | {within} of {closures} | {largest:.2f} | "
            f"{'-' if ate is None else f'{ate:.3f}'} | {optimization} | {total} |\n")


def main():
    p = parser(__doc__, "map-methods")
    args = p.parse_args()
    check_program(args)
    head = header(args, "experiments/scripts/map_methods.py")  # the load before the runs
    logs = ["malaga-oneloop"] if args.quick else list(LOGS)
    methods = QUICK if args.quick else METHODS
    reports = {}
    for method in methods:
        for log in logs:
            progress(f"{log}: antslam map --method {method}")
            reports[(log, method)] = run(args, log, method)
    rows = []
    for log in logs:
        rows += [method_row(log, method, reports[(log, method)]) for method in methods]
        rows.append(scan_matcher_row(log, reports[(log, methods[0])]))
    save_csv(args, "map_methods", COLUMNS, [["" if v is None else v for v in r] for r in rows])
    text = ("| log | method | weight (eq. 10) best / mean of trials | closures within 2 sigma | "
            "largest closure Mahalanobis | ATE RMSE m | optimisation s "
            f"({2 if args.quick else 20} trials) | total s |\n"
            "|---|---|---|---|---|---|---|---|\n" + "".join(markdown_row(r) for r in rows))
    save_table(args, head + text)
    print(text, end="")
    progress(f"wrote {args.out}/map_methods.csv, table.md")


if __name__ == "__main__":
    main()
