"""What the experiment scripts share: running the `antslam` program, the machine's load,
statistics, CSV and Markdown output, and the step-function helpers of scripts/slam_experiments.py
(imported, not copied). Run the scripts with /usr/bin/python3 (Debian's matplotlib)."""
import argparse
import csv
import json
import math
import os
import shutil
import subprocess
import sys
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402,F401  (re-exported for the scripts)

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
from slam_experiments import read_traces, step_mean  # noqa: E402,F401

DATA = os.path.join(ROOT, "data")
FIGURES = os.path.join(ROOT, "docs", "figures")


def parser(description, default_out):
    """The options every experiment has."""
    p = argparse.ArgumentParser(description=description,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--antslam", default=os.path.join(ROOT, "build", "experiments", "antslam"),
                   help="the antslam program (build it first: cmake --build build --target "
                        "antslam)")
    p.add_argument("--out", default=os.path.join(ROOT, "results", default_out),
                   help="results folder (CSV, PNG, table.md)")
    p.add_argument("--quick", action="store_true",
                   help="few trials and small budgets: a smoke test of the whole experiment")
    p.add_argument("--publish", action="store_true",
                   help="also copy the PNG figures to docs/figures/results-*.png")
    return p


def check_program(args):
    if not os.access(args.antslam, os.X_OK):
        sys.exit(f"{args.antslam}: not found; build it with "
                 "cmake -S . -B build -DCMAKE_BUILD_TYPE=Release && "
                 "cmake --build build --target antslam")
    os.makedirs(args.out, exist_ok=True)


def has_subcommand(args, name):
    text = subprocess.run([args.antslam, "--help"], capture_output=True, text=True).stdout
    return any(line.split()[:1] == [name] for line in text.splitlines())


def antslam(args, *cmd, capture=False):
    """Runs one antslam subcommand; stops the experiment with its error line if it fails."""
    cmd = [args.antslam, *map(str, cmd)]
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"failed: {' '.join(cmd)}\n{done.stderr.strip()}")
    return done.stdout if capture else None


def load_average():
    with open("/proc/loadavg") as f:
        return float(f.read().split()[0])


def progress(message):
    """One line per step on stderr, so that long runs show where they are."""
    print(f"[{time.strftime('%H:%M:%S')}] {message}", file=sys.stderr, flush=True)


def stats(values):
    """Mean, sample standard deviation, min and max (NaNs for no values)."""
    values = [v for v in values if v is not None and not math.isnan(v)]
    if not values:
        return {"mean": math.nan, "std": math.nan, "min": math.nan, "max": math.nan, "n": 0}
    mean = sum(values) / len(values)
    var = sum((v - mean) ** 2 for v in values) / (len(values) - 1) if len(values) > 1 else 0.0
    return {"mean": mean, "std": math.sqrt(var), "min": min(values), "max": max(values),
            "n": len(values)}


def median(values):
    values = sorted(values)
    if not values:
        return math.nan
    mid = len(values) // 2
    return values[mid] if len(values) % 2 else 0.5 * (values[mid - 1] + values[mid])


def read_json(path):
    with open(path) as f:
        return json.load(f)


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def read_study(prefix):
    """The files of `antslam optimize -o PREFIX`: the trials (rows of PREFIX.trials.csv with
    elapsed_s and time_to_best_s from PREFIX.times.json) and, per trial, its convergence points
    (rows of PREFIX.convergence.csv with elapsed_s), in order."""
    times = read_json(prefix + ".times.json")["trials"]
    trials = read_csv(prefix + ".trials.csv")
    for row, t in zip(trials, times):
        row["elapsed_s"], row["time_to_best_s"] = t["elapsed_s"], t["time_to_best_s"]
    traces = {}
    for row in read_csv(prefix + ".convergence.csv"):
        traces.setdefault(int(row["trial"]), []).append(row)
    for t, points in traces.items():
        for row, (_, elapsed) in zip(points, times[t]["convergence"]):
            row["elapsed_s"] = elapsed
    return trials, [traces[t] for t in sorted(traces)]


def write_csv(path, header, rows):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        w.writerows(rows)


def markdown_table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(lines) + "\n"


def pm(s, digits=3):
    """'mean +- std' of a stats() dict."""
    if s["n"] == 0:
        return "-"
    return f"{s['mean']:.{digits}f} +- {s['std']:.{digits}f}"


def header(args, command):
    """The first lines of table.md: the command as run, the date, the machine and its load."""
    options = " ".join(sys.argv[1:])
    return (f"Generated by `/usr/bin/python3 {command}{' ' + options if options else ''}` on "
            f"{time.strftime('%Y-%m-%d %H:%M')} ({os.cpu_count()} cores, load average "
            f"{load_average():.2f} at the start; the machine is shared, so times are "
            f"indicative).\n\n")


def save_figure(args, fig, name):
    """Writes OUT/name.png and, with --publish, docs/figures/results-name.png."""
    path = os.path.join(args.out, name + ".png")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    if args.publish:
        os.makedirs(FIGURES, exist_ok=True)
        shutil.copyfile(path, os.path.join(FIGURES, f"results-{name}.png"))
    return path
