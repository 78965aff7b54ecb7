#!/usr/bin/python3
"""Generalisation benchmark: the default pipeline (`antslam map`, default options) on every
corrected log x odometry-noise levels x seeds, and on the raw logs. Writes generalisation.csv
(one row per run), table.md (also on stdout) and generalisation.png.

    /usr/bin/python3 experiments/scripts/generalisation.py [--quick] [--seeds 3]
        [--levels 0.5,1,2] [--jobs 2 | --ranks K] [--data DIR] [--logs a,b]
        [--out results/generalisation]
        [--map-option=--opt=value ...] [--sweep option=v1,v2,...] [--publish]

Corrected logs (every DATA/laser/corrected/*-corrected.log.gz; DATA is the shared data folder
beside the checkout, ../shared/data, if it is there, else the project's data/): run (level k,
seed s) = `antslam simulate-odometry` with every noise parameter (0.05 m/m, 0.05 rad/rad,
0.01 rad/m, bias 0.002 rad/m) times k and noise seed s, then `antslam map` with default options
(seed 1, one thread per run) against the corrected poses. Raw logs: mit-csail and intel-subset
(with their references; intel-subset also with the relations metric) and malaga-oneloop (no
reference: closures only; `--laser-offset 0.78` as its header says), once each. --quick: one
small corrected log (seattle, else aces) at the default noise, seed 1, and malaga, with 2 trials
of 100 iterations.

Per run: ATE RMSE of odometry, scan matcher and the map; Ceres least squares on the same
fragment set (`antslam optimize --method ceres`); loop closures found, within 2 sigma after
optimisation, correct against the reference (precision) and revisits closed (recall,
`antslam eval --fragment-set`); scan-matcher fallbacks to odometry; the verdict; run time; and
for every run above 0.30 m its failure class, the first that applies:
  optimizer        Ceres on the same set is below 0.30 m and below 0.95 x the map's ATE
  false closure    Ceres on the set without its wrong closures (> 0.3 m or 3 deg from the
                   reference) is below 0.30 m
  scan matcher     an alignment of the set is more than 5 sigma from the reference
  missed closure   none of the above: the set does not close enough loops to correct the drift

The runs go stage by stage (noisy logs, maps, evaluations and Ceres, Ceres on the true closures),
each stage's commands independent of each other: --jobs at a time, or with --ranks K as one
`mpirun -np K antslam batch --keep-going` (the same files). A run whose command fails is a failed
run (its error in the CSV); the others go on. Run time: the map's own total (report.json).

--sweep option=v1,v2,... runs the whole benchmark once per value of an `antslam map` option
and writes lolo.md: leave-one-log-out, for every log the value that gives the lowest mean ATE
over all the other logs, and that log's own mean ATE with it (a held-out figure) beside its
mean ATE with each value (training figures).
"""
import glob
import json
import math
import os

from experiment_common import (DATA, ROOT, check_program, count_option, header,
                               integer_at_least, markdown_table, parser, path_length, plt,
                               progress, ranks_option, read_json, run_batch, save_csv,
                               save_figure, save_table, stats, write_text)

LEVELS = {0.5: "half", 1.0: "default", 2.0: "double"}
NOISE = {"--linear-noise": 0.05, "--angular-noise": 0.05, "--drift-noise": 0.01,
         "--heading-bias": 0.002}
RAW = [("mit-csail", "mit-csail.clf", "mit-csail.ref.tum", None, []),
       ("intel-subset", "intel-subset.clf", "intel-subset.ref.tum", "intel.relations", []),
       ("malaga", "malaga-oneloop.clf", None, None, ["--laser-offset", "0.78"])]
QUICK_CORRECTED = ["seattle", "aces"]  # the first one there is
QUICK_RAW = ["malaga"]
TARGET = 0.30
COLUMNS = ["sweep", "log", "level", "seed", "scans", "path_m", "odometry_ate_m",
           "scan_matcher_ate_m", "ate_m", "ceres_ate_m", "ceres_true_closures_ate_m",
           "relations_m", "closures", "closures_within_2_sigma", "closures_checked",
           "closures_correct", "closures_distrusted", "revisits", "revisits_closed",
           "alignments_beyond_3_sigma",
           "alignment_mahalanobis_max", "fallbacks", "recovered", "doubtful", "seconds",
           "failure_class", "error"]


def default_data():
    shared = os.path.join(os.path.dirname(ROOT), "shared", "data")
    return shared if os.path.isdir(os.path.join(shared, "laser", "corrected")) else DATA


def runs(args, p):
    """Every run: log, level, seed and where its log comes from."""
    corrected = {os.path.basename(f).replace("-corrected.log.gz", ""): f for f in
                 sorted(glob.glob(os.path.join(args.data, "laser", "corrected",
                                               "*-corrected.log.gz")))}
    raw = {r[0]: r for r in RAW}
    if args.logs:
        chosen = args.logs.split(",")
        unknown = [n for n in chosen if n not in corrected and n not in raw]
        if unknown:
            p.error(f"--logs: unknown {','.join(unknown)} (there are "
                    f"{','.join(list(corrected) + list(raw))})")
    elif args.quick:
        chosen = [next(n for n in QUICK_CORRECTED if n in corrected)] + QUICK_RAW
    else:
        chosen = list(corrected) + list(raw)
    out = []
    for name in chosen:
        if name in corrected:
            out += [{"log": name, "level": level, "seed": seed, "corrected": corrected[name]}
                    for level in args.levels for seed in range(1, args.seeds + 1)]
        else:
            _, log, reference, relations, options = raw[name]
            laser = os.path.join(args.data, "laser")
            out.append({"log": name, "level": "raw", "seed": 1, "raw": os.path.join(laser, log),
                        "reference": os.path.join(laser, reference) if reference else None,
                        "relations": os.path.join(laser, relations) if relations else None,
                        "options": options})
    return out


def classify(row):
    """The failure class of a run above the target (module docstring), else ''."""
    if row["ate_m"] == "" or row["ate_m"] <= TARGET:
        return ""
    if row["ceres_ate_m"] != "" and row["ceres_ate_m"] <= TARGET and \
            row["ceres_ate_m"] < 0.95 * row["ate_m"]:
        return "optimizer"
    if row["ceres_true_closures_ate_m"] != "" and row["ceres_true_closures_ate_m"] <= TARGET:
        return "false closure"
    if row["alignment_mahalanobis_max"] != "" and row["alignment_mahalanobis_max"] > 5.0:
        return "scan matcher"
    return "missed closure"


def eval_job(estimate, reference, work, *extra):
    """The `antslam eval` job of a trajectory; its result: read_json(eval_path(...))."""
    return ["eval", estimate, reference, "--json", eval_path(estimate, work), *extra]


def eval_path(estimate, work):
    return os.path.join(work, os.path.basename(estimate) + ".eval.json")


def ceres_job(fragment_set, work, name):
    """Ceres on a fragment set: the `antslam optimize` job, writing WORK/NAME.tum."""
    prefix = os.path.join(work, name)
    return ["optimize", fragment_set, "--method", "ceres", "-o", prefix, "--tum-out",
            prefix + ".tum"]


def ate_of(estimate, work):
    return read_json(eval_path(estimate, work))["ate"]["translation_m"]["rmse"]


def without_wrong_closures(fragment_set, check, path):
    """The fragment set without the closures the reference calls wrong, written to path;
    None if it has none (or no closure would be left)."""
    wrong = {(c["from"], c["to"]) for c in check["closures"]
             if c["has_reference"] and not c["correct"]}
    s = read_json(fragment_set)
    kept = [c for c in s["closures"] if (c["from"], c["to"]) not in wrong]
    if not wrong or not kept:
        return None
    s["closures"] = kept
    write_text(path, json.dumps(s))
    return path


class Run:
    """One benchmark run: its CSV row (a dict), where its files go, and its commands stage by
    stage; a failed command fills row["error"] and ends the run (the benchmark goes on)."""

    def __init__(self, args, run):
        level = run["level"]
        tag = f"{run['log']}-{LEVELS.get(level, level)}-{run['seed']}"
        self.run = run
        self.work = os.path.join(args.out, "runs", *([run["sweep"]] if run.get("sweep") else []),
                                 tag)
        os.makedirs(self.work, exist_ok=True)
        self.row = {c: "" for c in COLUMNS}
        self.row.update(log=run["log"], level=LEVELS.get(level, level), seed=run["seed"],
                        sweep=run.get("sweep", ""))
        if "corrected" in run:
            self.log = os.path.join(self.work, "log.clf")
            self.reference, self.relations, self.options = (
                os.path.join(self.work, "reference.tum"), None, [])
        else:
            self.log, self.reference, self.relations, self.options = (
                run["raw"], run["reference"], run["relations"], run["options"])
        self.mapped = os.path.join(self.work, "map")
        self.fragment_set = os.path.join(self.mapped, "fragment-set.json")
        self.check = None
        self.true_closures = None  # the set without its wrong closures, if Ceres runs on it

    def simulate_jobs(self, args):
        if "corrected" not in self.run:
            return []
        noise = [x for flag, value in NOISE.items() for x in (flag, value * self.run["level"])]
        return [["simulate-odometry", self.run["corrected"], "--out", self.work, "--seed",
                 self.run["seed"], *noise]]

    def simulated(self):
        if "corrected" in self.run:
            sim = read_json(os.path.join(self.work, "report.json"))
            self.row.update(odometry_ate_m=sim["odometry_ate_rmse_m"],
                            path_m=sim["path_length_m"])

    def map_jobs(self, args):
        return [["map", self.log, "--out", self.mapped, "--threads", 1, *self.options,
                 *(["--reference", self.reference] if self.reference else []),
                 *(["--no-maps"] if not args.maps else []), *args.map_option,
                 *(["--trials", 2, "--iterations", 100] if args.quick else []),
                 *self.run.get("sweep_options", [])]]

    def mapped_done(self):
        report = read_json(os.path.join(self.mapped, "report.json"))
        closures = report["closures"]
        counts = report["frontend"]["stats"]
        self.row.update(
            seconds=report["times"]["total_s"], scans=report["scans"], closures=len(closures),
            closures_within_2_sigma=sum(c["within_2_sigma"] for c in closures),
            fallbacks=report["verdict"]["odometry_fallbacks"],
            recovered=counts["recovered_scans"], doubtful=report["verdict"]["doubtful"],
            closures_distrusted=len(report["optimization"]["closing"].get("distrusted", [])))

    def evaluate_jobs(self, args):
        if not self.reference:
            return []
        return [eval_job(os.path.join(self.mapped, "trajectory.tum"), self.reference, self.work,
                         "--fragment-set", self.fragment_set,
                         *(["--relations", self.relations] if self.relations else [])),
                eval_job(os.path.join(self.mapped, "trajectory-scan-matcher.tum"),
                         self.reference, self.work),
                ceres_job(self.fragment_set, self.work, "ceres")]

    def evaluated(self):
        if not self.reference:
            return
        e = read_json(eval_path(os.path.join(self.mapped, "trajectory.tum"), self.work))
        self.check = e["fragment_set"]
        self.row.update(ate_m=e["ate"]["translation_m"]["rmse"],
                        closures_checked=self.check["closures_checked"],
                        closures_correct=self.check["closures_correct"],
                        revisits=self.check["revisits"],
                        revisits_closed=self.check["revisits_closed"],
                        alignments_beyond_3_sigma=self.check["alignments_beyond_3_sigma"],
                        alignment_mahalanobis_max=self.check["alignment_mahalanobis_max"])
        if e.get("relations"):
            self.row["relations_m"] = e["relations"]["translation_m"]["mean"]
        self.row["scan_matcher_ate_m"] = ate_of(
            os.path.join(self.mapped, "trajectory-scan-matcher.tum"), self.work)
        if "corrected" not in self.run:
            self.row["path_m"] = path_length(self.reference)

    def ceres_jobs(self, args):
        if not self.reference:
            return []
        jobs = [eval_job(os.path.join(self.work, "ceres.tum"), self.reference, self.work)]
        if self.row["ate_m"] > TARGET:
            self.true_closures = without_wrong_closures(
                self.fragment_set, self.check, os.path.join(self.work, "true-closures.json"))
        if self.true_closures:
            jobs.append(ceres_job(self.true_closures, self.work, "ceres-true-closures"))
        return jobs

    def ceres_done(self):
        if self.reference:
            self.row["ceres_ate_m"] = ate_of(os.path.join(self.work, "ceres.tum"), self.work)

    def true_closures_jobs(self, args):
        if not self.true_closures:
            return []
        return [eval_job(os.path.join(self.work, "ceres-true-closures.tum"), self.reference,
                         self.work)]

    def true_closures_done(self):
        if self.true_closures:
            self.row["ceres_true_closures_ate_m"] = ate_of(
                os.path.join(self.work, "ceres-true-closures.tum"), self.work)


STAGES = [("simulate", Run.simulate_jobs, Run.simulated), ("map", Run.map_jobs, Run.mapped_done),
          ("evaluate", Run.evaluate_jobs, Run.evaluated), ("ceres", Run.ceres_jobs,
                                                            Run.ceres_done),
          ("true-closures", Run.true_closures_jobs, Run.true_closures_done)]


def run_all(args, todo):
    """Every run, stage by stage: each stage's commands of every run still going are
    independent of each other, one batch (run_batch: --jobs at a time, or over --ranks MPI
    ranks); a run whose command fails keeps its error and stops there. Returns the rows."""
    runs = [Run(args, r) for r in todo]
    for stage, jobs_of, done in STAGES:
        going = [r for r in runs if not r.row["error"]]
        pending = [(r, job) for r in going for job in jobs_of(r, args)]
        progress(f"{stage}: {len(pending)} commands of {len(going)} runs")
        results = run_batch(args, [job for _, job in pending], stage, keep_going=True,
                            parallel=args.jobs)
        for (r, _), (_, error) in zip(pending, results):
            r.row["error"] = r.row["error"] or (error or "")
        for r in going:
            if not r.row["error"]:
                done(r)
    for r in runs:
        r.row["failure_class"] = classify(r.row) if not r.row["error"] else "run failed"
        row = r.row
        progress(f"{row['log']} {row['level']} seed {row['seed']} {row['sweep']}: "
                 f"ATE {fmt(row['ate_m'])} m (Ceres {fmt(row['ceres_ate_m'])}), closures "
                 f"{row['closures_within_2_sigma']} of {row['closures']} within 2 sigma, "
                 f"{fmt(row['seconds'], 1)} s {row['failure_class']} {row['error']}")
    return [r.row for r in runs]


def fmt(value, digits=3):
    """A number to `digits` decimals; '-' for none or NaN."""
    if value == "" or value is None or (isinstance(value, float) and math.isnan(value)):
        return "-"
    return f"{value:.{digits}f}" if isinstance(value, float) else str(value)


def total(group, column):
    return sum(r[column] or 0 for r in group)


def summary(rows):
    """Per log and level: ATE mean and max, runs above the target, Ceres, closures, time."""
    order = ["half", "default", "double", "raw"]
    keys = sorted({(r["log"], r["level"]) for r in rows},
                  key=lambda k: (k[1] == "raw", k[0], order.index(k[1]) if k[1] in order else 9))
    table = []
    for log, level in keys:
        group = [r for r in rows if r["log"] == log and r["level"] == level]
        column = {c: stats([r[c] for r in group if r[c] != ""]) for c in
                  ("odometry_ate_m", "scan_matcher_ate_m", "ate_m", "ceres_ate_m", "seconds")}
        worse = sum(1 for r in group if r["ate_m"] != "" and r["ceres_ate_m"] != "" and
                    r["ate_m"] > 1.05 * r["ceres_ate_m"])
        checked, revisits = total(group, "closures_checked"), total(group, "revisits")
        table.append([
            log, level, len(group), fmt(column["odometry_ate_m"]["mean"], 2),
            fmt(column["scan_matcher_ate_m"]["mean"], 2),
            f"{fmt(column['ate_m']['mean'])} / {fmt(column['ate_m']['max'])}",
            fmt(column["ceres_ate_m"]["mean"]), worse,
            f"{sum(1 for r in group if r['failure_class'])} of {len(group)}",
            f"{total(group, 'closures_within_2_sigma')} of {total(group, 'closures')}",
            f"{total(group, 'closures_correct')} of {checked}" if checked else "-",
            f"{total(group, 'revisits_closed')} of {revisits}" if revisits else "-",
            total(group, "closures_distrusted"), total(group, "fallbacks"),
            sum(1 for r in group if r["doubtful"] is True),
            fmt(column["seconds"]["mean"], 1)])
    return markdown_table(
        ["log", "noise", "runs", "odometry ATE", "scan matcher ATE", "ATE mean / max (m)",
         "Ceres ATE", "runs > 1.05 x Ceres", f"runs > {TARGET:.2f} m",
         "closures within 2 sigma", "closures correct (precision)", "revisits closed (recall)",
         "closures distrusted", "matcher fallbacks", "doubtful verdicts", "s per run"], table)


def failures(rows):
    bad = [r for r in rows if r["failure_class"]]
    if not bad:
        return f"No run above {TARGET:.2f} m.\n"
    return markdown_table(
        ["log", "noise", "seed", "ATE (m)", "Ceres (m)", "Ceres, true closures (m)",
         "closures within 2 sigma", "correct closures", "worst alignment (sigma)", "verdict",
         "class", "error"],
        [[r["log"], r["level"], r["seed"], fmt(r["ate_m"]), fmt(r["ceres_ate_m"]),
          fmt(r["ceres_true_closures_ate_m"]),
          f"{r['closures_within_2_sigma']} of {r['closures']}",
          f"{r['closures_correct']} of {r['closures_checked']}",
          fmt(r["alignment_mahalanobis_max"], 1),
          {True: "doubtful", False: "consistent"}.get(r["doubtful"], "-"), r["failure_class"],
          r["error"]] for r in bad])


def lolo(rows, option, values):
    """Leave one log out: per log, the value best on the other logs and the log's ATE with it."""
    logs = sorted({r["log"] for r in rows if r["ate_m"] != ""})
    mean = {(log, v): stats([r["ate_m"] for r in rows if r["log"] == log and r["sweep"] == v
                             and r["ate_m"] != ""])["mean"] for log in logs for v in values}
    table = []
    for log in logs:
        others = {v: sum(mean[(o, v)] for o in logs if o != log) / max(1, len(logs) - 1)
                  for v in values}
        chosen = min(values, key=lambda v: others[v])
        table.append([log, chosen, fmt(mean[(log, chosen)])] +
                     [fmt(mean[(log, v)]) for v in values])
    overall = min(values, key=lambda v: sum(mean[(o, v)] for o in logs))
    return (f"Leave-one-log-out for --{option}: per log, the value with the lowest mean ATE over "
            f"the other logs and the held-out log's mean ATE with it; then its mean ATE with "
            f"each value (training figures). Chosen on all logs at once: {overall}.\n\n" +
            markdown_table(["log", "value chosen without it", "held-out ATE (m)"] +
                           [f"ATE with {v}" for v in values], table))


def plot(args, rows):
    """ATE of every run, per log and noise level, against the target."""
    runs_with_ate = [r for r in rows if r["ate_m"] != "" and not r["sweep"]]
    logs = sorted({r["log"] for r in runs_with_ate})
    fig, ax = plt.subplots(figsize=(1.3 * len(logs) + 2, 4))
    colours = {"half": "tab:green", "default": "tab:blue", "double": "tab:red",
               "raw": "tab:grey"}
    for i, log in enumerate(logs):
        for k, level in enumerate(["half", "default", "double", "raw"]):
            ates = [r["ate_m"] for r in runs_with_ate if r["log"] == log and r["level"] == level]
            ax.scatter([i + (k - 1.5) * 0.15] * len(ates), ates, s=12, color=colours[level],
                       label=level if i == 0 or level == "raw" else None)
    ax.axhline(TARGET, color="black", linestyle="--", linewidth=0.8, label=f"{TARGET} m")
    ax.set_xticks(range(len(logs)))
    ax.set_xticklabels(logs, rotation=20)
    ax.set_yscale("log")
    ax.set_ylabel("ATE RMSE (m)")
    handles, labels = ax.get_legend_handles_labels()
    unique = dict(zip(labels, handles))
    ax.legend(unique.values(), unique.keys(), fontsize=7)
    save_figure(args, fig, "generalisation")


def main():
    p = parser(__doc__, "generalisation")
    count_option(p, "--seeds", "noise seeds per noise level", 3, 1)
    p.add_argument("--levels", default=None,
                   help="noise levels as multiples of the default noise (0.5,1,2; quick 1)")
    p.add_argument("--jobs", type=integer_at_least(1), default=2,
                   help="commands at the same time (each on one thread) without --ranks")
    ranks_option(p)
    p.add_argument("--data", default=default_data(), help="data folder (laser/, laser/corrected/)")
    p.add_argument("--logs", default=None, help="comma-separated subset of the logs")
    p.add_argument("--maps", action="store_true", help="also draw the maps (slower)")
    p.add_argument("--map-option", action="append", default=[],
                   help="extra option for antslam map, e.g. --map-option=--trials=5")
    p.add_argument("--sweep", default=None,
                   help="option=v1,v2,...: the benchmark once per value, and lolo.md")
    args = p.parse_args()
    try:
        args.levels = [float(x) for x in (args.levels or ("1" if args.quick else "0.5,1,2"))
                       .split(",")]
    except ValueError:
        p.error(f"--levels: '{args.levels}' is not a comma-separated list of numbers")
    if any(not (v > 0 and math.isfinite(v)) for v in args.levels):
        p.error("--levels: every level must be a positive number")
    check_program(args)
    head = header(args, "experiments/scripts/generalisation.py")
    todo = runs(args, p)
    option, values = None, [""]
    if args.sweep:
        option, _, listed = args.sweep.partition("=")
        values = listed.split(",")
        if not option or not listed:
            p.error("--sweep: expected option=v1,v2,...")
        todo = [dict(r, sweep=v, sweep_options=[f"--{option}", v]) for v in values for r in todo]
    rows = run_all(args, todo)
    rows.sort(key=lambda r: (r["sweep"], r["level"] == "raw", r["log"], str(r["level"]), r["seed"]))
    save_csv(args, "generalisation", COLUMNS, [[r[c] for c in COLUMNS] for r in rows])
    text = (f"ATE RMSE in metres against the reference; noise levels multiply every "
            f"simulated-odometry noise parameter; {args.seeds} seed(s) per level.\n\n")
    for v in values:
        group = [r for r in rows if r["sweep"] == v]
        text += (f"### --{option} {v}\n\n" if option else "") + summary(group) + "\n"
        text += f"Runs above {TARGET:.2f} m:\n\n" + failures(group) + "\n"
    if option:
        text += lolo(rows, option, values)
    else:
        plot(args, rows)
    save_table(args, head + text)
    print(text, end="")


if __name__ == "__main__":
    main()
