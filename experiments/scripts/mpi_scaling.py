#!/usr/bin/python3
"""Trials per second over MPI ranks: the same independent runs on 1 rank (a plain process) and
on 2 ranks (`mpirun -np 2`, run i on rank i % 2), and a check that the outputs are the same.

Workloads: the paper's 100-trial study (`antslam optimize --method hybrid --trials 100
--iterations 3000 --threads 1 --seed 1`, the configuration Table I runs, on each shipped paper
fragment set: paper9, paper15, paper24), ten times that study on paper24 in one command (1000
trials: the launcher's cost spread over a longer run), and `antslam tsp-experiment` (MMAS with 3-opt on four
shipped TSPLIB instances x 4 seeds, 300 iterations each, not stopped at the optimum). Each rank
runs one thread, so 2 ranks use the machine's 2 cores. Time: the wall clock of the whole command
(launcher, MPI start-up, reading and writing included), median over the repeats; trials per
second = runs / time. The launcher's own cost (`mpirun -np 2 antslam --help`: start-up, MPI_Init,
MPI_Finalize) is measured apart, and the speedup is also given without it (once per command:
three for the paper sets).

Identical outputs: PREFIX.json, .trials.csv and .convergence.csv byte for byte; the
tsp-experiment CSV and Markdown without their wall-clock columns (time_to_best_s, elapsed_s,
mean time to best), which differ between any two runs.

Measure on a quiet machine: with --max-load L every measurement waits (up to --max-wait s in
all) until the load average is below L; the load before each goes into the CSV and the table.

Writes mpi_scaling.csv, table.md and mpi_scaling.png into the results folder.

    /usr/bin/python3 experiments/scripts/mpi_scaling.py [--quick] [--repeats 3]
        [--max-load 1.5] [--max-wait 1800] [--out results/mpi_scaling] [--publish]

--quick: paper9 only with 10 trials of 300 iterations, 20 trials of paper24, eil51 x 2 seeds of
20 iterations, 1 repeat.
"""
import csv
import filecmp
import io
import os
import time

from experiment_common import (DATA, check_program, count_option, header, load_average,
                               markdown_table, median, mpirun, parser, plt, progress,
                               run_program, save_csv, save_figure, save_table)

RANKS = [1, 2]
TIME_COLUMNS = {"time_to_best_s", "elapsed_s", "mean time to best (s)"}


def launch(args, ranks, *cmd):
    """The antslam command on `ranks` ranks (a plain process for 1); its wall-clock seconds."""
    prefix = mpirun(ranks) if ranks > 1 else []
    start = time.perf_counter()
    run_program(*prefix, args.antslam, *cmd)
    return time.perf_counter() - start


def optimize_workload(args):
    sets = ["paper9"] if args.quick else ["paper9", "paper15", "paper24"]
    trials, iterations = (10, 300) if args.quick else (100, 3000)

    def run(ranks, tag):
        seconds, outputs = 0.0, []
        for name in sets:
            prefix = os.path.join(args.out, "runs", f"{name}-{tag}")
            seconds += launch(args, ranks, "optimize",
                              os.path.join(DATA, "fragment-sets", name + ".json"), "--method",
                              "hybrid", "--trials", trials, "--iterations", iterations,
                              "--threads", 1, "--seed", 1, "-o", prefix)
            outputs += [prefix + ext for ext in (".json", ".trials.csv", ".convergence.csv")]
        return seconds, outputs

    return (f"AntSLAM: {trials} trials x {len(sets)} paper set{'s' if len(sets) > 1 else ''}",
            trials * len(sets), len(sets), run)


def long_study_workload(args):
    """Ten times the paper's study on its largest set in one command: the launcher's cost spread
    over a longer run."""
    trials, iterations = (20, 300) if args.quick else (1000, 3000)

    def run(ranks, tag):
        prefix = os.path.join(args.out, "runs", f"paper24-long-{tag}")
        seconds = launch(args, ranks, "optimize",
                         os.path.join(DATA, "fragment-sets", "paper24.json"), "--method", "hybrid",
                         "--trials", trials, "--iterations", iterations, "--threads", 1, "--seed",
                         1, "-o", prefix)
        return seconds, [prefix + ext for ext in (".json", ".trials.csv", ".convergence.csv")]

    return f"AntSLAM: {trials} trials of paper24", trials, 1, run


def tsp_workload(args):
    instances = ["eil51"] if args.quick else ["eil51", "kroA100", "ch130", "d198"]
    seeds, iterations = (2, 20) if args.quick else (4, 300)

    def run(ranks, tag):
        out = os.path.join(args.out, "runs", f"tsp-{tag}")
        seconds = launch(args, ranks, "tsp-experiment", "--data-dir",
                         os.path.join(DATA, "tsplib"), "--instances", ",".join(instances),
                         "--variants", "mmas", "--seeds", seeds, "--iterations", iterations,
                         "--stop-at-optimum", "false", "--csv", out + ".csv", "--markdown",
                         out + ".md")
        return seconds, [out + ".csv", out + ".md"]

    return (f"TSP: tsp-experiment, {len(instances)} instance{'s' if len(instances) > 1 else ''} "
            f"x {seeds} seeds", len(instances) * seeds, 1, run)


def without_times(path):
    """A CSV or Markdown table without its wall-clock columns, as rows of cells."""
    with open(path) as f:
        text = f.read()
    if path.endswith(".md"):
        rows = [[c.strip() for c in line.strip().strip("|").split("|")]
                for line in text.splitlines()]
    else:
        rows = list(csv.reader(io.StringIO(text)))
    keep = [i for i, name in enumerate(rows[0]) if name not in TIME_COLUMNS]
    return [[row[i] for i in keep] for row in rows]


def same(a, b):
    if a.endswith((".csv", ".md")) and "tsp-" in os.path.basename(a):
        return without_times(a) == without_times(b)
    return filecmp.cmp(a, b, shallow=False)


def wait_for_quiet(args, deadline):
    """Waits until the load average is below --max-load (or the deadline); returns the load."""
    while args.max_load and load_average() >= args.max_load and time.time() < deadline:
        time.sleep(15)
    return load_average()


def main():
    p = parser(__doc__, "mpi_scaling")
    count_option(p, "--repeats", "repeats of every measurement", 3, 1)
    p.add_argument("--max-load", type=float, default=None,
                   help="wait before each measurement until the load average is below this")
    p.add_argument("--max-wait", type=float, default=1800,
                   help="seconds to wait for a quiet machine in all, then measure anyway")
    args = p.parse_args()
    check_program(args)
    os.makedirs(os.path.join(args.out, "runs"), exist_ok=True)
    head = header(args, "experiments/scripts/mpi_scaling.py")
    deadline = time.time() + args.max_wait
    rows, table, rates = [], [], {}
    launch_cost = []
    for r in range(args.repeats):
        wait_for_quiet(args, deadline)
        launch_cost.append(launch(args, 2, "--help"))
    cost = median(launch_cost)
    for name, runs, launches, run in (optimize_workload(args), long_study_workload(args),
                                      tsp_workload(args)):
        seconds, loads, first, measured = {}, {}, None, []
        identical = True
        for ranks in RANKS:
            for r in range(args.repeats):
                load = wait_for_quiet(args, deadline)
                progress(f"{name}: {ranks} rank(s), repeat {r + 1}/{args.repeats} "
                         f"(load {load:.2f})")
                s, outputs = run(ranks, f"{ranks}-{r}")
                first = first or outputs
                identical = identical and all(same(a, b) for a, b in zip(first, outputs))
                seconds.setdefault(ranks, []).append(s)
                loads.setdefault(ranks, []).append(load)
                measured.append([name, ranks, r + 1, s, runs, runs / s, load])
        base = median(seconds[1])
        rates[name] = [runs / median(seconds[k]) for k in RANKS]
        for k in RANKS:
            t = median(seconds[k])
            startup = cost * launches if k > 1 else 0.0
            table.append([name, k, f"{t:.2f}", f"{runs / t:.1f}", f"{base / t:.2f}",
                          f"{base / (t - startup):.2f}", "yes" if identical else "NO",
                          f"{min(loads[k]):.2f}..{max(loads[k]):.2f}"])
        rows += [row + [identical] for row in measured]
    save_csv(args, "mpi_scaling", ["workload", "ranks", "repeat", "seconds", "runs",
                                   "runs_per_s", "load_average", "identical_outputs"], rows)
    fig, ax = plt.subplots(figsize=(7, 3.8))
    width = 0.38
    for k, ranks in enumerate(RANKS):
        values = [rates[name][k] for name in rates]
        bars = ax.bar([i + (k - 0.5) * width for i in range(len(rates))], values, width,
                      label=f"{ranks} rank{'s' if ranks > 1 else ''}", color=plt.cm.tab10(k))
        if ranks > 1:
            for bar, name in zip(bars, rates):
                ax.annotate(f"{rates[name][k] / rates[name][0]:.2f}x",
                            (bar.get_x() + bar.get_width() / 2, bar.get_height()),
                            ha="center", va="bottom", fontsize=8)
    ax.set_xticks(range(len(rates)))
    ax.set_xticklabels([n.replace(": ", "\n") for n in rates], fontsize=7)
    ax.set_ylabel("runs (trials) per second")
    ax.legend(fontsize=8)
    save_figure(args, fig, "mpi_scaling")
    text = (f"{args.repeats} repeat(s) per point; launcher cost (`mpirun -np 2 antslam --help`, "
            f"median) {cost:.2f} s.\n\n"
            + markdown_table(["workload", "ranks", "median s", "runs/s", "speedup",
                              "speedup without launcher", "identical outputs",
                              "load before"], table))
    save_table(args, head + text)
    print(text, end="")
    progress(f"wrote {args.out}/mpi_scaling.csv, table.md, mpi_scaling.png")


if __name__ == "__main__":
    main()
