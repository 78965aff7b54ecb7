#!/usr/bin/python3
"""TSP solution quality: the defaults (MMAS + 3-opt, focused construction) on seven TSPLIB
instances (d198 ... pr2392), 10 seeds, 10 s wall clock per run, 1 and 2 threads, one run after
the other (`antslam tsp-experiment`; runs end early at the known optimum, as in ACOTSP); then the
mean excess over the optimum per instance and thread count against the reference targets
(ACOTSP level) and against ACOTSP 1.03 itself (MMAS + 3-opt, 10 s CPU, seeds 1-10, measured on
this machine kind: acotsp-10s.csv of the shared data, when it is there). Writes quality.csv
(every run), quality.md (the per-instance table of tsp-experiment) and table.md into the results
folder. About 12 minutes; run it on an otherwise idle machine.

    /usr/bin/python3 experiments/scripts/tsp_quality.py [--quick] [--seeds 10] [--publish]

--quick: d198 and lin318, 1 seed, 1 s per run.
"""
import os

from experiment_common import (DATA, ROOT, antslam, check_program, count_option, header,
                               markdown_table, parser, progress, publish, read_csv, save_table,
                               stats)

# Mean excess over the optimum (%) that Stuetzle's ACOTSP (MMAS or ACS with 3-opt) reaches in
# 10 s: within about 0.1 % on instances of 500 to 1200 cities.
TARGETS = {"d198": 0.01, "lin318": 0.05, "pcb442": 0.10, "att532": 0.05, "rat783": 0.10,
           "pr1002": 0.25, "pr2392": 0.50}
QUICK = ["d198", "lin318"]
THREADS = [1, 2]
ACOTSP = os.path.join(os.path.dirname(ROOT), "shared", "data", "tsplib", "acotsp-10s.csv")


def acotsp_excess():
    """instance -> ACOTSP's mean excess % over its seeds (empty without the shared file)."""
    if not os.path.exists(ACOTSP):
        return {}
    runs = {}
    for r in read_csv(ACOTSP):
        runs.setdefault(r["instance"], []).append(
            100.0 * (float(r["length"]) / float(r["optimum"]) - 1.0))
    return {name: sum(v) / len(v) for name, v in runs.items()}


def targets_table(runs, instances):
    """Instances x threads: the mean excess % against its target and ACOTSP's; whether every
    target is met."""
    rows, met, acotsp = [], True, acotsp_excess()
    for instance in instances:
        cells = []
        for threads in THREADS:
            excess = stats([float(r["excess_percent"]) for r in runs
                            if r["instance"] == instance and int(r["threads"]) == threads])
            met = met and excess["mean"] <= TARGETS[instance]
            cells.append(f"{excess['mean']:.3f}")
        reference = f"{acotsp[instance]:.3f}" if instance in acotsp else "-"
        rows.append([instance, f"{TARGETS[instance]:.2f}", reference, *cells])
    return markdown_table(["instance", "target", "ACOTSP 1.03",
                           *(f"{t} thread(s)" for t in THREADS)], rows), met


def main():
    p = parser(__doc__, "tsp")
    count_option(p, "--seeds", "seeds per instance and thread count", 10, 1)
    args = p.parse_args()
    check_program(args)
    head = header(args, "experiments/scripts/tsp_quality.py")  # the load before the runs
    instances = QUICK if args.quick else list(TARGETS)
    csv, markdown = os.path.join(args.out, "quality.csv"), os.path.join(args.out, "quality.md")
    progress(f"tsp-experiment: {', '.join(instances)}")
    antslam(args, "tsp-experiment", "--data-dir", os.path.join(DATA, "tsplib"),
            "--instances", ",".join(instances), "--variants", "mmas", "--local-search", "3opt",
            "--threads", ",".join(map(str, THREADS)), "--seeds", args.seeds,
            "--time", 1 if args.quick else 10, "--csv", csv, "--markdown", markdown)
    publish(args, csv, "tsp-quality.csv")
    table, met = targets_table(read_csv(csv), instances)
    with open(markdown) as f:
        text = (f.read() + "\nMean excess % over the optimum against the target:\n\n" + table
                + f"\n{'Every target is met.' if met else 'Some targets are missed.'}\n")
    save_table(args, head + text)
    print(text, end="")
    progress(f"wrote {csv}, {markdown}, {args.out}/table.md")


if __name__ == "__main__":
    main()
