#!/usr/bin/python3
"""Thread scaling, in two parts.

Workloads: speedup and efficiency against threads (1..cores) for ant construction (TSP pr1002,
MMAS without local search; and one AntSLAM hybrid trial on a large real fragment set: intel, 93
fragments) and for independent AntSLAM trials, each repeated; and a check that the results are
identical at every thread count (tour file, best weights of every trial). Times: the program's
own elapsed time for the TSP, the wall clock of the `antslam optimize` process for the
fragment-set workloads (reading the set included). Median over the repeats; speedup =
median(1 thread) / median(T threads), efficiency = speedup / T. Measure on a quiet machine: the
load average before every workload goes into the table.

Time windows: `bench_slam --benchmark_filter='Trials|Control'` run --windows times, --pause s
apart. BM_Trials: 100 independent hybrid trials of paper9 (the paper's configuration) spread
over 1 and 2 TBB threads; BM_ParallelControl: 100 tasks of pure arithmetic spread the same way.
The control's speedup is what the shared machine gave in that window (1.0: the second core was
busy elsewhere); the median trials speedup is taken over the windows whose control reached 1.8.

Writes scaling.csv, windows.csv, table.md and scaling.png into the results folder.

    /usr/bin/python3 experiments/scripts/scaling.py [--quick] [--repeats 3] [--windows 12]
        [--pause 30] [--bench build/bench/bench_slam] [--out results/scaling] [--publish]

--quick: TSP 5 iterations, AntSLAM 300 iterations and 4 trials, 1 repeat; one window with
Google Benchmark's shortest run time. --windows 0 skips the windows (no bench_slam needed).
"""
import filecmp
import json
import os
import time

from experiment_common import (DATA, ROOT, antslam, check_program, header, count_option,
                               load_average, markdown_table, median, parser, plt, progress,
                               read_csv, read_json, run_program, save_csv, save_figure,
                               save_table)


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


def workloads_study(args):
    """Every workload at 1..cores threads, --repeats times; its rows and Markdown."""
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
    save_csv(args, "scaling", ["workload", "threads", "repeats", "median_s", "min_s", "max_s",
                               "speedup", "efficiency", "identical_results", "load_average"],
             rows)
    fig, ax = plt.subplots(figsize=(5.5, 4))
    for k, (name, speedups) in enumerate(curves.items()):
        ax.plot(threads, speedups, "o-", label=name, color=plt.cm.tab10(k))
    ax.plot(threads, threads, "k:", label="ideal")
    ax.set_xticks(threads)
    ax.set_xlabel("threads")
    ax.set_ylabel("speedup (median of repeats)")
    ax.legend(fontsize=7)
    save_figure(args, fig, "scaling")
    return (f"{args.repeats} repeat(s) per point.\n\n"
            + markdown_table(["workload", "threads", "median s", "range s", "speedup",
                              "efficiency", "identical results", "load before"], table))


def bench_rates(args):
    """One run of BM_Trials and BM_ParallelControl: rate per benchmark name."""
    quick = ["--benchmark_min_time=0.01"] if args.quick else []
    text = run_program(args.bench, "--benchmark_filter=Trials|Control",
                       "--benchmark_format=json", *quick)
    return {b["run_name"].split("/real_time")[0]: b.get("trials_per_s", b.get("tasks_per_s"))
            for b in json.loads(text)["benchmarks"]}


def windows_study(args):
    """100 trials of paper9 on 1 and 2 threads beside a pure-arithmetic control, repeated in
    several time windows because the two cores are shared with other users."""
    rows, usable = [], []
    for k in range(args.windows):
        progress(f"window {k + 1}/{args.windows}: bench_slam Trials|Control")
        load = load_average()
        r = bench_rates(args)
        trials = r["BM_Trials/2"] / r["BM_Trials/1"]
        control = r["BM_ParallelControl/2"] / r["BM_ParallelControl/1"]
        if control >= 1.8:
            usable.append(trials)
        rows.append([time.strftime("%H:%M:%S"), load, r["BM_Trials/1"], r["BM_Trials/2"], trials,
                     control])
        if k + 1 < args.windows:
            time.sleep(args.pause)
    save_csv(args, "windows", ["window", "load_average", "trials_per_s_1", "trials_per_s_2",
                               "trials_speedup", "control_speedup"], rows)
    summary = (f"median trials speedup {median(usable):.2f} (range {min(usable):.2f} to "
               f"{max(usable):.2f}) over the {len(usable)} windows whose control reached 1.8"
               if usable else "no window had a free second core (control below 1.8)")
    return (f"`bench_slam --benchmark_filter='Trials|Control'` run {args.windows} times, "
            f"{args.pause} s apart.\n\n"
            + markdown_table(["window", "load", "trials/s, 1 thread", "trials/s, 2 threads",
                              "trials speedup", "control speedup"],
                             [[w, f"{load:.2f}", f"{t1:.1f}", f"{t2:.1f}", f"{ts:.2f}", f"{cs:.2f}"]
                              for w, load, t1, t2, ts, cs in rows])
            + f"\n{summary}.\n")


def main():
    p = parser(__doc__, "scaling")
    count_option(p, "--repeats", "repeats per point", 3, 1)
    count_option(p, "--windows", "time windows of bench_slam, 0: none", 12, 1, low=0)
    count_option(p, "--pause", "seconds between windows", 30, 0, low=0)
    p.add_argument("--bench", default=os.path.join(ROOT, "build", "bench", "bench_slam"),
                   help="the bench_slam program (cmake --build build --target bench_slam)")
    args = p.parse_args()
    check_program(args)
    if args.windows and not os.access(args.bench, os.X_OK):
        p.error(f"{args.bench}: not found; build it with cmake --build build --target "
                "bench_slam, or pass --windows 0")
    os.makedirs(os.path.join(args.out, "runs"), exist_ok=True)
    text = header(args, "experiments/scripts/scaling.py")  # the load before the runs
    text += "## Workloads\n\n" + workloads_study(args)
    if args.windows:
        text += "\n## Time windows\n\n" + windows_study(args)
    save_table(args, text)
    print(text, end="")
    progress(f"wrote {args.out}/scaling.csv, " + ("windows.csv, " if args.windows else "")
             + "table.md, scaling.png")


if __name__ == "__main__":
    main()
