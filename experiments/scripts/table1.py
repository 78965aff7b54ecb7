#!/usr/bin/python3
"""Paper-2 Table I: datasets x methods, trajectory ATE RMSE (after rigid SE(2) alignment) mean +-
std over runs, with the reference path length; plus the relations metric (Kuemmerle et al. 2009)
for Intel. Writes table1.csv (one row per dataset, method and run), table.md and table1.png.

    /usr/bin/python3 experiments/scripts/table1.py [--quick] [--runs 10] [--out results/table1]
        [--ranks K] [--publish]

Datasets: the GMapping-corrected logs (aces, intel, freiburg-079, csail) turned into benchmarks
by `antslam simulate-odometry` (run r: noise seed r, reference = the corrected poses), and the raw
logs with a reference (mit-csail, intel-subset; the optimizer's and tinySLAM's seed vary).
Methods: odometry only; the scan matcher alone (the frontend's pre-solution); tinySLAM; AntSLAM
(hybrid) and AntSLAM + NLopt and Ceres least squares on the same fragment set
(`antslam fragment-set` then `antslam optimize --tum-out`: each scan's corrected pose is its
fragment's optimized frame times its pose in the fragment).

The runs go stage by stage (noisy logs, frontends, methods, scores), each stage's commands
independent of each other: with --ranks K each stage is one `mpirun -np K antslam batch`
(the same files as --ranks 1, which runs them one after the other).

--quick: aces and intel-subset, 1 run, 300 ACO iterations.
"""
import os

from experiment_common import (DATA, check_program, header, count_option, markdown_table,
                               parser, path_length, plt, pm, progress, ranks_option, read_json,
                               run_batch, save_csv, save_figure, save_table, stats)

LASER = os.path.join(DATA, "laser")
CORRECTED = ["aces", "intel", "freiburg-079", "csail"]
RAW = [("mit-csail", "mit-csail.clf", "mit-csail.ref.tum", None),
       ("intel-subset", "intel-subset.clf", "intel-subset.ref.tum", "intel.relations")]
OPTIMIZERS = ["hybrid", "hybrid+nlopt", "ceres"]
METHODS = ["odometry", "scan-matcher", "tinyslam"] + OPTIMIZERS
QUICK = ["aces", "intel-subset"]  # one corrected log, one raw log with relations


def eval_job(estimate, reference, relations):
    """The `antslam eval` job of one trajectory (its scores: score())."""
    return ["eval", estimate, reference, "--json", estimate + ".eval.json",
            *(["--relations", relations] if relations else [])]


def score(estimate):
    e = read_json(estimate + ".eval.json")
    rel = e.get("relations")
    return (e["ate"]["translation_m"]["rmse"], e["ate"]["rotation_deg"]["rmse"],
            rel["translation_m"]["mean"] if rel else None)


class Run:
    """One run of one dataset: where its files go, its log and reference, and every method's
    trajectory (tums: {method: TUM path})."""

    def __init__(self, args, name, raw, run):
        self.name, self.run = name, run
        if raw:  # one frontend per raw log; the optimizer's and tinySLAM's seeds vary
            self.work = os.path.join(args.out, "runs", name)
            self.log, self.reference = os.path.join(LASER, raw[1]), os.path.join(LASER, raw[2])
            self.relations = os.path.join(LASER, raw[3]) if raw[3] else None
            self.simulate = None
            self.frontend = run == 1
        else:  # a fresh noisy odometry (and fragment set) per run
            self.work = os.path.join(args.out, "runs", f"{name}-{run}")
            self.log = os.path.join(self.work, "log.clf")
            self.reference = os.path.join(self.work, "reference.tum")
            self.relations = None
            self.simulate = ["simulate-odometry",
                             os.path.join(LASER, "corrected", f"{name}-corrected.log.gz"),
                             "--out", self.work, "--seed", run]
            self.frontend = True
        self.fragment_set = os.path.join(self.work, "fragment-set.json")
        tiny = os.path.join(self.work, f"tinyslam-{run}")
        self.tiny = tiny
        self.tums = {"odometry": os.path.join(self.work, "odometry.tum"),
                     "scan-matcher": os.path.join(self.work, "scan-matcher.tum"),
                     "tinyslam": os.path.join(tiny, "trajectory.tum")}
        for method in OPTIMIZERS:
            self.tums[method] = os.path.join(self.work, f"{method}-{run}.tum")

    def frontend_jobs(self):
        if not self.frontend:
            return []
        return [["odometry", self.log, "-o", self.tums["odometry"]],
                ["fragment-set", self.log, "-o", self.fragment_set, "--seed", self.run,
                 "--trajectory", self.tums["scan-matcher"]]]

    def method_jobs(self, args):
        jobs = [["tinyslam", self.log, "--out", self.tiny, "--seed", self.run]]
        for method in OPTIMIZERS:
            prefix = self.tums[method][:-len(".tum")]
            jobs.append(["optimize", self.fragment_set, "--method", method, "--seed", self.run,
                         "--iterations", 300 if args.quick else 3000, "-o", prefix,
                         "--tum-out", self.tums[method]])
        return jobs


def run_all(args, runs):
    """Every run's commands, stage by stage (each stage's runs are independent of each other:
    one batch, over --ranks MPI ranks with run_batch): noisy logs, frontends, methods, scores."""
    for r in runs:
        os.makedirs(r.work, exist_ok=True)
    stages = [("simulate", lambda r: [r.simulate] if r.simulate else []),
              ("frontend", lambda r: r.frontend_jobs()),
              ("methods", lambda r: r.method_jobs(args)),
              ("eval", lambda r: [eval_job(t, r.reference, r.relations)
                                  for t in r.tums.values()])]
    for stage, jobs_of in stages:
        progress(f"{stage}: {len(runs)} runs")
        jobs = [[str(a) for a in job] for r in runs for job in jobs_of(r)]
        # the runs of a raw log share its frontend's trajectories: each is scored once
        run_batch(args, [list(job) for job in dict.fromkeys(map(tuple, jobs))], stage)


def main():
    p = parser(__doc__, "table1")
    count_option(p, "--runs", "runs per dataset", 10, 1)
    ranks_option(p)
    p.add_argument("--datasets", default=None,
                   help="comma-separated subset of " + ",".join(CORRECTED + [r[0] for r in RAW]))
    args = p.parse_args()
    check_program(args)
    head = header(args, "experiments/scripts/table1.py")  # the load before the runs
    datasets = [(name, None, None) for name in CORRECTED] + [(r[0], r, None) for r in RAW]
    chosen = args.datasets or (",".join(QUICK) if args.quick else None)
    if chosen:
        unknown = set(chosen.split(",")) - {d[0] for d in datasets}
        if unknown:
            p.error(f"--datasets: unknown {', '.join(sorted(unknown))}")
        datasets = [d for d in datasets if d[0] in chosen.split(",")]
    runs = [Run(args, name, raw, run) for name, raw, _ in datasets
            for run in range(1, args.runs + 1)]
    run_all(args, runs)
    rows, table, lengths = [], [], {}
    for name, _, _ in datasets:
        results = {m: [] for m in METHODS}
        for r in (r for r in runs if r.name == name):
            lengths[name] = path_length(r.reference)
            for method, tum in r.tums.items():
                ate, rot, rel = score(tum)
                results[method].append((ate, rot, rel))
                rows.append([name, method, r.run, lengths[name], ate, rot,
                             "" if rel is None else rel])
        for method in METHODS:
            ate = stats([r[0] for r in results[method]])
            rel = stats([r[2] for r in results[method]])
            table.append([name, f"{lengths[name]:.0f}", method, ate["n"], pm(ate),
                          pm(stats([r[1] for r in results[method]]), 2), pm(rel)])
    save_csv(args, "table1", ["dataset", "method", "run", "path_length_m", "ate_rmse_m",
                              "ate_rot_rmse_deg", "relations_translation_mean_m"], rows)
    plot(args, rows, [d[0] for d in datasets])
    text = ("ATE RMSE (m), mean +- std over runs; lowest mean in bold.\n\n"
            + matrix(rows, [d[0] for d in datasets], 4) + "\n"
            + "Relations metric, mean translational error (m):\n\n"
            + matrix([r for r in rows if r[6] != ""], [r[0] for r in RAW if r[3]], 6, 3) + "\n"
            + markdown_table(["dataset", "path (m)", "method", "runs", "ATE RMSE (m)",
                              "ATE rot RMSE (deg)", "relations transl. (m)"], table))
    save_table(args, head + text)
    print(text, end="")
    progress(f"wrote {args.out}/table1.csv, table.md, table1.png")


def matrix(rows, names, column, digits=2):
    """Datasets x methods: mean +- std of rows[column]; the lowest mean of a dataset in bold."""
    table = []
    for name in names:
        cells = {m: stats([r[column] for r in rows if r[0] == name and r[1] == m])
                 for m in METHODS}
        if all(c["n"] == 0 for c in cells.values()):
            continue
        best = min(cells[m]["mean"] for m in METHODS if cells[m]["n"])
        length = next(r[3] for r in rows if r[0] == name)
        table.append([f"{name} ({length:.0f} m)"] +
                     [f"**{pm(cells[m], digits)}**" if cells[m]["mean"] == best
                      else pm(cells[m], digits) for m in METHODS])
    return markdown_table(["dataset (path)"] + METHODS, table)


def plot(args, rows, names):
    fig, ax = plt.subplots(figsize=(1.6 * len(names) + 2, 4))
    width = 0.8 / len(METHODS)
    for k, method in enumerate(METHODS):
        s = [stats([r[4] for r in rows if r[0] == n and r[1] == method]) for n in names]
        ax.bar([i + (k - len(METHODS) / 2 + 0.5) * width for i in range(len(names))],
               [x["mean"] for x in s], width, yerr=[x["std"] for x in s], capsize=2,
               label=method, color=plt.cm.tab10(k))
    ax.set_xticks(range(len(names)))
    ax.set_xticklabels(names)
    ax.set_yscale("log")
    ax.set_ylabel("ATE RMSE (m), mean +- std over runs")
    ax.legend(fontsize=7, ncol=3)
    save_figure(args, fig, "table1")


if __name__ == "__main__":
    main()
