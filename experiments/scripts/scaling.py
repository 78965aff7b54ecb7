#!/usr/bin/python3
"""Thread scaling: speedup and efficiency against threads (1..cores) for ant construction (TSP
pr1002, MMAS without local search; and one AntSLAM hybrid trial on a large real fragment set:
intel, 93 fragments) and for independent AntSLAM trials, each repeated; and a check that the
results are identical at every thread count (tour file, best weights of every trial). Writes
scaling.csv, table.md and scaling.png into the results folder.

    /usr/bin/python3 experiments/scripts/scaling.py [--quick] [--repeats 3] [--out results/scaling]
        [--publish]

Times: the program's own elapsed time for the TSP, the wall clock of the `antslam optimize`
process for the fragment-set workloads (reading the set included). Median over the repeats;
speedup = median(1 thread) / median(T threads), efficiency = speedup / T. Measure on a quiet
machine: the load average before every workload goes into the table.
"""
import filecmp
import os
import time

from experiment_common import (DATA, antslam, check_program, header, load_average,
                               markdown_table, median, parser, plt, progress, read_csv, read_json,
                               save_figure, write_csv)


def tsp(args, threads, repeat):
    out = os.path.join(args.out, "runs", f"tsp-{threads}-{repeat}")
    antslam(args, "tsp", "--instance", os.path.join(DATA, "tsplib", "pr1002.tsp"), "--variant",
            "mmas", "--local-search", "none", "--iterations", 5 if args.quick else 30, "--seed",
            1, "--threads", threads, "--json", out + ".json", "--tour-out", out + ".tour")
    return read_json(out + ".json")["elapsed_s"], out + ".tour"


def optimize(args, fragment_set, tag, trials, threads, repeat):
    prefix = os.path.join(args.out, "runs", f"{tag}-{threads}-{repeat}")
    start = time.perf_counter()
    antslam(args, "optimize", fragment_set, "--method", "hybrid", "--trials", trials, "--threads",
            threads, "--seed", 1, "--iterations", 300 if args.quick else 3000, "-o", prefix)
    elapsed = time.perf_counter() - start
    weights = os.path.join(args.out, "runs", f"{tag}-{threads}-{repeat}.weights")
    with open(weights, "w") as f:  # what must not depend on the thread count
        f.writelines(f"{r['trial']},{r['seed']},{r['weight']},{r['evaluations']}\n"
                     for r in read_csv(prefix + ".trials.csv"))
    return elapsed, weights


def main():
    p = parser(__doc__, "scaling")
    p.add_argument("--repeats", type=int, default=None, help="repeats per point (3; quick 1)")
    args = p.parse_args()
    args.repeats = args.repeats or (1 if args.quick else 3)
    check_program(args)
    head = header(args, "experiments/scripts/scaling.py")  # the load before the runs
    os.makedirs(os.path.join(args.out, "runs"), exist_ok=True)
    progress("intel fragment set (simulate-odometry --seed 1, fragment-set)")
    bench = os.path.join(args.out, "intel")
    antslam(args, "simulate-odometry",
            os.path.join(DATA, "laser", "corrected", "intel-corrected.log.gz"), "--out", bench)
    fragment_set = os.path.join(bench, "fragment-set.json")
    antslam(args, "fragment-set", os.path.join(bench, "log.clf"), "-o", fragment_set)
    trials = 4 if args.quick else 16
    workloads = [
        ("TSP pr1002 ants (MMAS, no local search)", lambda t, r: tsp(args, t, r)),
        ("AntSLAM ants, intel set, 1 trial",
         lambda t, r: optimize(args, fragment_set, "ants", 1, t, r)),
        (f"AntSLAM independent trials, intel set, {trials} trials",
         lambda t, r: optimize(args, fragment_set, "trials", trials, t, r)),
    ]
    threads = list(range(1, (os.cpu_count() or 1) + 1))
    rows, table, curves = [], [], {}
    for name, work in workloads:
        load = load_average()
        times, outputs = {}, {}
        for t in threads:
            for r in range(args.repeats):
                progress(f"{name}: {t} thread(s), repeat {r + 1}/{args.repeats}")
                elapsed, output = work(t, r)
                times.setdefault(t, []).append(elapsed)
                outputs.setdefault(t, []).append(output)
        identical = all(filecmp.cmp(outputs[1][0], o, shallow=False)
                        for t in threads for o in outputs[t])
        base = median(times[1])
        curves[name] = [base / median(times[t]) for t in threads]
        for t in threads:
            speedup = base / median(times[t])
            rows.append([name, t, args.repeats, median(times[t]), min(times[t]), max(times[t]),
                         speedup, speedup / t, identical, load])
            table.append([name, t, f"{median(times[t]):.3f}",
                          f"{min(times[t]):.3f}..{max(times[t]):.3f}", f"{speedup:.2f}",
                          f"{speedup / t:.2f}", "yes" if identical else "NO", f"{load:.2f}"])
    write_csv(os.path.join(args.out, "scaling.csv"),
              ["workload", "threads", "repeats", "median_s", "min_s", "max_s", "speedup",
               "efficiency", "identical_results", "load_average"], rows)
    fig, ax = plt.subplots(figsize=(5.5, 4))
    for k, (name, speedups) in enumerate(curves.items()):
        ax.plot(threads, speedups, "o-", label=name, color=plt.cm.tab10(k))
    ax.plot(threads, threads, "k:", label="ideal")
    ax.set_xticks(threads)
    ax.set_xlabel("threads")
    ax.set_ylabel("speedup (median of repeats)")
    ax.legend(fontsize=7)
    save_figure(args, fig, "scaling")
    with open(os.path.join(args.out, "table.md"), "w") as f:
        f.write(head)
        f.write(f"{args.repeats} repeat(s) per point.\n\n")
        f.write(markdown_table(["workload", "threads", "median s", "range s", "speedup",
                                "efficiency", "identical results", "load before"], table))
    progress(f"wrote {args.out}/scaling.csv, table.md, scaling.png")


if __name__ == "__main__":
    main()
