#!/usr/bin/python3
"""Generalisation benchmark: the default pipeline (`antslam map`, default options) on every
corrected log x odometry-noise levels x seeds, and on the raw logs. Writes generalisation.csv
(one row per run), table.md and prints one progress line per run.

    /usr/bin/python3 experiments/scripts/generalisation.py [--quick] [--seeds 10]
        [--levels 0.5,1,2] [--jobs 2] [--data DIR] [--out results/generalisation]
        [--map-option=--opt=value ...]

Corrected logs (every DATA/laser/corrected/*-corrected.log.gz; DATA is the shared data folder
beside the checkout, ../shared/data, if it is there, else the project's data/): run (level k,
seed s) = `antslam simulate-odometry` with every noise parameter (0.05 m/m, 0.05 rad/rad,
0.01 rad/m, bias 0.002 rad/m) times k and noise seed s, then `antslam map` with default options
(seed 1) against the corrected poses. Raw logs: mit-csail and intel-subset (with their
references; intel-subset also with the relations metric) and malaga-oneloop (no reference:
closures only; `--laser-offset 0.78` as its header says), once each.

Per run: ATE RMSE of odometry, scan matcher and the map; Ceres least squares on the same
fragment set (`antslam optimize --method ceres`); loop closures found, within 2 sigma after
optimisation, correct against the reference (precision) and revisits closed (recall,
`antslam eval --fragment-set`); scan-matcher fallbacks to odometry; run time; and for every
run above 0.30 m its failure class, the first that applies:
  optimizer        Ceres on the same set is below 0.30 m and below 0.95 x the map's ATE
  false closure    a closure of the set is wrong (> 0.3 m or 3 deg from the reference)
  scan matcher     an alignment of the set is more than 5 sigma from the reference
  missed closure   none of the above: the set is right but does not close enough loops
"""
import concurrent.futures
import glob
import math
import os
import time

from experiment_common import (DATA, ROOT, antslam, check_program, header, markdown_table, parser,
                               progress, read_json, stats, write_csv)

LEVELS = {0.5: "half", 1.0: "default", 2.0: "double"}
NOISE = {"--linear-noise": 0.05, "--angular-noise": 0.05, "--drift-noise": 0.01,
         "--heading-bias": 0.002}
RAW = [("mit-csail", "mit-csail.clf", "mit-csail.ref.tum", None, []),
       ("intel-subset", "intel-subset.clf", "intel-subset.ref.tum", "intel.relations", []),
       ("malaga", "malaga-oneloop.clf", None, None, ["--laser-offset", "0.78"])]
TARGET = 0.30
COLUMNS = ["log", "level", "seed", "scans", "path_m", "odometry_ate_m", "scan_matcher_ate_m",
           "ate_m", "ceres_ate_m", "relations_m", "closures", "closures_within_2_sigma",
           "closures_checked", "closures_correct", "revisits", "revisits_closed",
           "alignments_beyond_3_sigma", "alignment_mahalanobis_max", "fallbacks", "recovered",
           "verdict", "seconds", "failure_class", "error"]


def default_data():
    shared = os.path.join(os.path.dirname(ROOT), "shared", "data")
    return shared if os.path.isdir(os.path.join(shared, "laser", "corrected")) else DATA


def runs(args):
    """Every run: (name, level, seed, how to get its log)."""
    out = []
    logs = sorted(glob.glob(os.path.join(args.data, "laser", "corrected", "*-corrected.log.gz")))
    for path in logs:
        name = os.path.basename(path).replace("-corrected.log.gz", "")
        for level in args.levels:
            for seed in range(1, args.seeds + 1):
                out.append({"log": name, "level": level, "seed": seed, "corrected": path})
    for name, log, reference, relations, options in RAW:
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
    if row["closures_checked"] != "" and row["closures_correct"] < row["closures_checked"]:
        return "false closure"
    if row["alignment_mahalanobis_max"] != "" and row["alignment_mahalanobis_max"] > 5.0:
        return "scan matcher"
    return "missed closure"


def ate(args, estimate, reference, work, extra=()):
    out = os.path.join(work, os.path.basename(estimate) + ".eval.json")
    antslam(args, "eval", estimate, reference, "--json", out, *extra)
    return read_json(out)


def run_one(args, run):
    """One benchmark run; returns its CSV row (a dict)."""
    level = run["level"]
    tag = f"{run['log']}-{level if level == 'raw' else LEVELS.get(level, level)}-{run['seed']}"
    work = os.path.join(args.out, "runs", tag)
    os.makedirs(work, exist_ok=True)
    row = {c: "" for c in COLUMNS}
    row.update(log=run["log"], level=LEVELS.get(level, level), seed=run["seed"])
    start = time.time()
    try:
        if "corrected" in run:
            noise = [x for flag, value in NOISE.items() for x in (flag, value * level)]
            antslam(args, "simulate-odometry", run["corrected"], "--out", work, "--seed",
                    run["seed"], *noise)
            sim = read_json(os.path.join(work, "report.json"))
            row.update(odometry_ate_m=sim["odometry_ate_rmse_m"], path_m=sim["path_length_m"])
            log, reference, relations, options = (os.path.join(work, "log.clf"),
                                                  os.path.join(work, "reference.tum"), None, [])
        else:
            log, reference, relations, options = (run["raw"], run["reference"], run["relations"],
                                                  run["options"])
        mapped = os.path.join(work, "map")
        start = time.time()
        antslam(args, "map", log, "--out", mapped, "--threads", 1, *options,
                *(["--reference", reference] if reference else []),
                *(["--no-maps"] if not args.maps else []), *args.map_option, *args.quick_options)
        row["seconds"] = time.time() - start
        report = read_json(os.path.join(mapped, "report.json"))
        closures = report["closures"]
        stats_ = report["frontend"]["stats"]
        row.update(scans=report["scans"], closures=len(closures),
            closures_within_2_sigma=sum(c["within_2_sigma"] for c in closures),
            fallbacks=stats_.get("diverged_scans", 0) + stats_["unmatched_scans"],
            recovered=stats_["recovered_scans"], verdict=report.get("verdict", {}).get("line", ""))
        if reference:
            fragment_set = os.path.join(mapped, "fragment-set.json")
            e = ate(args, os.path.join(mapped, "trajectory.tum"), reference, work,
                    ["--fragment-set", fragment_set] +
                    (["--relations", relations] if relations else []))
            check = e["fragment_set"]
            row.update(ate_m=e["ate"]["translation_m"]["rmse"],
                       closures_checked=check["closures_checked"],
                       closures_correct=check["closures_correct"], revisits=check["revisits"],
                       revisits_closed=check["revisits_closed"],
                       alignments_beyond_3_sigma=check["alignments_beyond_3_sigma"],
                       alignment_mahalanobis_max=check["alignment_mahalanobis_max"])
            if e.get("relations"):
                row["relations_m"] = e["relations"]["translation_m"]["mean"]
            row["scan_matcher_ate_m"] = ate(args, os.path.join(mapped, "trajectory-scan-matcher.tum"),
                                            reference, work)["ate"]["translation_m"]["rmse"]
            prefix = os.path.join(work, "ceres")
            antslam(args, "optimize", fragment_set, "--method", "ceres", "-o", prefix,
                    "--tum-out", prefix + ".tum")
            row["ceres_ate_m"] = ate(args, prefix + ".tum", reference, work)["ate"][
                "translation_m"]["rmse"]
            if "corrected" not in run:
                row["path_m"] = path_length(reference)
    except SystemExit as failure:  # antslam failed: the run is a failure, the benchmark goes on
        row["error"] = str(failure).splitlines()[-1]
        row["seconds"] = row["seconds"] or time.time() - start
    row["failure_class"] = classify(row) if not row["error"] else "run failed"
    return row


def path_length(tum):
    poses = [tuple(map(float, line.split()[1:3])) for line in open(tum) if line[0] != "#"]
    return sum(math.dist(a, b) for a, b in zip(poses, poses[1:]))


def fmt(value, digits=3):
    return "-" if value == "" or value is None else (
        f"{value:.{digits}f}" if isinstance(value, float) else str(value))


def summary(rows):
    """Per log and level: ATE mean and max, runs above the target, Ceres, closures, time."""
    table = []
    keys = sorted({(r["log"], r["level"]) for r in rows},
                  key=lambda k: (k[1] == "raw", k[0], ["half", "default", "double", "raw"].index(
                      k[1]) if k[1] in ("half", "default", "double", "raw") else 9))
    for log, level in keys:
        group = [r for r in rows if r["log"] == log and r["level"] == level]
        a = stats([r["ate_m"] for r in group if r["ate_m"] != ""])
        c = stats([r["ceres_ate_m"] for r in group if r["ceres_ate_m"] != ""])
        o = stats([r["odometry_ate_m"] for r in group if r["odometry_ate_m"] != ""])
        s = stats([r["scan_matcher_ate_m"] for r in group if r["scan_matcher_ate_m"] != ""])
        over = sum(1 for r in group if r["failure_class"])
        found = sum(r["closures"] or 0 for r in group)
        within = sum(r["closures_within_2_sigma"] or 0 for r in group)
        checked = sum(r["closures_checked"] or 0 for r in group)
        correct = sum(r["closures_correct"] or 0 for r in group)
        revisits = sum(r["revisits"] or 0 for r in group)
        closed = sum(r["revisits_closed"] or 0 for r in group)
        fallbacks = sum(r["fallbacks"] or 0 for r in group)
        worse = sum(1 for r in group if r["ate_m"] != "" and r["ceres_ate_m"] != "" and
                    r["ate_m"] > 1.05 * r["ceres_ate_m"])
        table.append([log, level, len(group), fmt(o["mean"], 2), fmt(s["mean"], 2),
                      f"{fmt(a['mean'])} / {fmt(a['max'])}", fmt(c["mean"]), worse,
                      f"{over} of {len(group)}", f"{within} of {found}",
                      f"{correct} of {checked}" if checked else "-",
                      f"{closed} of {revisits}" if revisits else "-", fallbacks,
                      fmt(stats([r["seconds"] for r in group])["mean"], 1)])
    return markdown_table(["log", "noise", "runs", "odometry ATE", "scan matcher ATE",
                           "ATE mean / max (m)", "Ceres ATE", "runs > 1.05 x Ceres",
                           f"runs > {TARGET:.2f} m", "closures within 2 sigma",
                           "closures correct (precision)", "revisits closed (recall)",
                           "matcher fallbacks", "s per run"], table)


def failures(rows):
    bad = [r for r in rows if r["failure_class"]]
    if not bad:
        return f"No run above {TARGET:.2f} m.\n"
    return markdown_table(
        ["log", "noise", "seed", "ATE (m)", "Ceres (m)", "closures within 2 sigma",
         "correct closures", "worst alignment (sigma)", "class", "error"],
        [[r["log"], r["level"], r["seed"], fmt(r["ate_m"]), fmt(r["ceres_ate_m"]),
          f"{r['closures_within_2_sigma']} of {r['closures']}",
          f"{r['closures_correct']} of {r['closures_checked']}",
          fmt(r["alignment_mahalanobis_max"], 1), r["failure_class"], r["error"]] for r in bad])


def main():
    p = parser(__doc__, "generalisation")
    p.add_argument("--seeds", type=int, default=None, help="noise seeds per level (10; quick 1)")
    p.add_argument("--levels", default=None,
                   help="noise levels as multiples of the default (0.5,1,2; quick 1)")
    p.add_argument("--jobs", type=int, default=2, help="runs in parallel (one thread each)")
    p.add_argument("--data", default=default_data(), help="data folder (laser/, laser/corrected/)")
    p.add_argument("--logs", default=None, help="comma-separated subset of the logs")
    p.add_argument("--maps", action="store_true", help="also draw the maps (slower)")
    p.add_argument("--map-option", action="append", default=[],
                   help="extra option for antslam map, e.g. --map-option=--trials=5")
    args = p.parse_args()
    args.seeds = args.seeds or (1 if args.quick else 10)
    args.levels = [float(x) for x in (args.levels or ("1" if args.quick else "0.5,1,2")).split(",")]
    args.quick_options = ["--trials", 2, "--iterations", 100] if args.quick else []
    check_program(args)
    head = header(args, "experiments/scripts/generalisation.py")
    todo = runs(args)
    if args.logs:
        todo = [r for r in todo if r["log"] in args.logs.split(",")]
    rows = []
    with concurrent.futures.ProcessPoolExecutor(max_workers=args.jobs) as pool:
        futures = [pool.submit(run_one, args, r) for r in todo]
        for n, future in enumerate(concurrent.futures.as_completed(futures), 1):
            r = future.result()
            rows.append(r)
            progress(f"{n}/{len(todo)} {r['log']} {r['level']} seed {r['seed']}: ATE "
                     f"{fmt(r['ate_m'])} m (Ceres {fmt(r['ceres_ate_m'])}), closures "
                     f"{r['closures_within_2_sigma']} of {r['closures']} within 2 sigma, "
                     f"{fmt(r['seconds'], 1)} s {r['failure_class']} {r['error']}")
    rows.sort(key=lambda r: (r["level"] == "raw", r["log"], str(r["level"]), r["seed"]))
    write_csv(os.path.join(args.out, "generalisation.csv"), COLUMNS,
              [[r[c] for c in COLUMNS] for r in rows])
    with open(os.path.join(args.out, "table.md"), "w") as f:
        f.write(head)
        f.write(f"ATE RMSE in metres against the reference; noise levels multiply every "
                f"simulated-odometry noise parameter; {args.seeds} seeds per level.\n\n")
        f.write(summary(rows) + "\n")
        f.write(f"Runs above {TARGET:.2f} m:\n\n" + failures(rows))
    progress(f"wrote {args.out}/generalisation.csv and table.md")


if __name__ == "__main__":
    main()
