#!/usr/bin/python3
"""TSP at scale: `antslam tsp` (the defaults: MMAS + 3-opt with focused construction) on d15112
(TSPLIB, optimum 1,573,084) and mona-lisa100K (best known tour 5,757,191) from the shared data,
and on random uniform instances of 10,000 and 100,000 cities (`tsp-generate --seed 1`; excess
against 0.7124 sqrt(n A), the asymptotic optimum of Percus & Martin 1996, so an estimate that
finite instances exceed a little). One run per instance on --threads threads; memory (maximum
resident set of the run), time per iteration, and quality over time. Writes large.csv (one row
per run), the traces (trace-NAME.csv), table.md and large-quality.png. About 24 minutes (120 s
for the 10,000-city instances, 600 s for the 100,000-city ones); run it on an idle machine.

    /usr/bin/python3 experiments/scripts/tsp_large.py [--quick] [--threads 2] [--publish]

--quick: one random instance of 2,000 cities for 3 s.
"""
import math
import os
import subprocess
import sys

from experiment_common import (ROOT, antslam, check_program, header, markdown_table, parser,
                               plt, progress, publish, read_csv, read_json, save_figure,
                               save_table, write_csv)

SHARED = os.path.join(os.path.dirname(ROOT), "shared", "data", "tsplib")
# name: (file or generated size, reference length or None for the random estimate, seconds)
FULL = {"d15112": ("d15112.tsp", 1573084, 120), "E10k": (10000, None, 120),
        "mona-lisa100K": ("mona-lisa100K.tsp", 5757191, 600), "E100k": (100000, None, 600)}
QUICK = {"E2k": (2000, None, 3)}


def instance_path(args, name, source):
    """The shared file, or a random uniform instance written into the results folder."""
    if isinstance(source, str):
        path = os.path.join(args.shared, source)
        if not os.path.exists(path):
            sys.exit(f"{path}: not found (--shared names the folder of d15112.tsp)")
        return path
    path = os.path.join(args.out, f"{name}.tsp")
    antslam(args, "tsp-generate", "--cities", source, "--seed", 1, "--out", path)
    return path


def run_measured(cmd):
    """Runs cmd; returns the maximum resident set of that process in MB."""
    process = subprocess.Popen([*map(str, cmd)], stdout=subprocess.DEVNULL,
                               stderr=subprocess.PIPE, text=True)
    _, status, usage = os.wait4(process.pid, 0)
    error = process.stderr.read().strip().splitlines()
    process.returncode = os.waitstatus_to_exitcode(status)
    if process.returncode != 0:
        sys.exit(f"failed: {' '.join(map(str, cmd))}: {error[-1] if error else status}")
    return usage.ru_maxrss / 1024.0


def main():
    p = parser(__doc__, "tsp-large")
    p.add_argument("--threads", type=int, default=2, help="threads of each run (2)")
    p.add_argument("--shared", default=SHARED, help="folder of d15112.tsp and mona-lisa100K.tsp")
    args = p.parse_args()
    check_program(args)
    head = header(args, "experiments/scripts/tsp_large.py")
    cases = QUICK if args.quick else FULL
    rows, traces = [], {}
    for name, (source, reference, seconds) in cases.items():
        path = instance_path(args, name, source)
        trace, summary = (os.path.join(args.out, f"{kind}-{name}.{ext}")
                          for kind, ext in (("trace", "csv"), ("run", "json")))
        progress(f"{name}: {seconds} s on {args.threads} thread(s)")
        rss = run_measured([args.antslam, "tsp", "--instance", path, "--threads", args.threads,
                            "--time", seconds, "--seed", 1, "--trace-csv", trace,
                            "--json", summary])
        run = read_json(summary)
        n = run["cities"]
        if reference is None:  # Percus & Martin's constant; the square's side is 1e6
            reference = 0.7124 * math.sqrt(n * 1e12)
        excess = 100.0 * (run["best_length"] / reference - 1.0)
        rows.append([name, n, args.threads, seconds, f"{run['best_length']:.0f}",
                     f"{reference:.0f}", f"{excess:.3f}", run["iterations"],
                     f"{1000.0 * run['elapsed_s'] / run['iterations']:.1f}", f"{rss:.0f}"])
        traces[name] = [(float(r["elapsed_s"]), 100.0 * (float(r["global_best"]) / reference - 1))
                        for r in read_csv(trace)]
    columns = ["instance", "cities", "threads", "budget_s", "best", "reference", "excess_percent",
               "iterations", "ms_per_iteration", "max_rss_mb"]
    csv_path = os.path.join(args.out, "large.csv")
    write_csv(csv_path, columns, rows)
    publish(args, csv_path, "tsp-large.csv")
    fig, ax = plt.subplots(figsize=(7, 4))
    for name, points in traces.items():
        ax.plot([t for t, _ in points], [e for _, e in points], label=name)
    ax.set_xscale("log")
    ax.set_xlabel("wall-clock seconds")
    ax.set_ylabel("% over the optimum / best known / estimate")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    save_figure(args, fig, "tsp-large-quality")
    table = markdown_table(["instance", "n", "threads", "budget (s)", "best", "reference",
                            "excess %", "iterations", "ms / iteration", "max RSS (MB)"], rows)
    save_table(args, head + table)
    print(table, end="")
    progress(f"wrote {csv_path}, {args.out}/table.md, {args.out}/tsp-large-quality.png")


if __name__ == "__main__":
    main()
