"""What the experiment scripts share: the options every experiment has, running the `antslam`
program and reading what `antslam optimize` writes, the machine's load, statistics (mean +- std,
median, the mean of step functions over trials), CSV, Markdown and PNG output written atomically,
and --publish. Run the scripts with /usr/bin/python3 (Debian's matplotlib)."""
import argparse
import concurrent.futures
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
DATA = os.path.join(ROOT, "data")
FIGURES = os.path.join(ROOT, "docs", "figures")


def integer_at_least(low):
    """An argparse type: an integer >= low, else one line naming the value."""

    def parse(text):
        try:
            value = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"'{text}' is not an integer") from None
        if value < low:
            raise argparse.ArgumentTypeError(f"{value} is below {low}")
        return value

    return parse


class OneLineErrorParser(argparse.ArgumentParser):
    """An argument parser whose errors are one line, `SCRIPT: error: PROBLEM`, exit status 2,
    and whose count options (count_option) default to one value for a full run and another
    with --quick."""

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self.count_defaults = {}

    def error(self, message):
        self.exit(2, f"{self.prog}: error: {message}\n")

    def parse_args(self, *arguments):
        args = super().parse_args(*arguments)
        for dest, (full, quick) in self.count_defaults.items():
            if getattr(args, dest) is None:
                setattr(args, dest, quick if args.quick else full)
        return args


def count_option(p, name, what, full, quick, low=1):
    """An integer option >= low (trials, runs, repeats ...): `full` by default, `quick` with
    --quick."""
    dest = name.lstrip("-").replace("-", "_")
    p.add_argument(name, type=integer_at_least(low), default=None,
                   help=f"{what} ({full}; quick {quick})")
    p.count_defaults[dest] = (full, quick)


def threads_option(p):
    """--threads of `antslam optimize`: 1 by default, so that every trial's time is its own."""
    p.add_argument("--threads", type=integer_at_least(1), default=1,
                   help="threads of antslam optimize (1: per-trial times are not shared)")


def parser(description, default_out):
    """The options every experiment has."""
    p = OneLineErrorParser(description=description,
                           formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--antslam", default=os.path.join(ROOT, "build", "app", "antslam"),
                   help="the antslam program (build it first: cmake --build build --target "
                        "antslam)")
    p.add_argument("--out", default=os.path.join(ROOT, "results", default_out),
                   help="results folder (CSV, PNG, table.md)")
    p.add_argument("--quick", action="store_true",
                   help="few trials and small budgets: a smoke test of the whole experiment")
    p.add_argument("--publish", action="store_true",
                   help="also copy the CSV and PNG files to docs/figures/results-*")
    return p


def check_program(args):
    if not os.access(args.antslam, os.X_OK):
        sys.exit(f"{args.antslam}: not found; build it with "
                 "cmake -S . -B build -DCMAKE_BUILD_TYPE=Release && "
                 "cmake --build build --target antslam")
    os.makedirs(args.out, exist_ok=True)


def run_program(*cmd):
    """Runs a program; stops the experiment with one line (the command and the program's last
    error line) if it fails. Returns its stdout."""
    cmd = [*map(str, cmd)]
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode != 0:
        lines = done.stderr.strip().splitlines()
        sys.exit(f"failed: {' '.join(cmd)}: "
                 f"{lines[-1] if lines else f'exit status {done.returncode}'}")
    return done.stdout


def antslam(args, *cmd):
    """Runs one antslam subcommand (see run_program); returns its stdout."""
    return run_program(args.antslam, *cmd)


def ranks_option(p):
    """--ranks K: the experiment's independent antslam runs as one MPI job of K ranks
    (run_batch), or one after the other (1, the default)."""
    p.add_argument("--ranks", type=integer_at_least(1), default=1,
                   help="run the independent antslam runs over K MPI ranks with "
                        "`mpirun -np K antslam batch` (1: one after the other, no MPI)")


def mpirun(ranks):
    """The Open MPI launcher for `ranks` processes: -q keeps its notices off stderr;
    --allow-run-as-root only as root, --oversubscribe only for more ranks than cores."""
    cmd = ["mpirun", "-q", "-np", str(ranks)]
    if os.geteuid() == 0:
        cmd.append("--allow-run-as-root")
    if ranks > (os.cpu_count() or 1):
        cmd.append("--oversubscribe")
    return cmd


def run_batch(args, jobs, name="jobs", keep_going=False, parallel=1):
    """Runs independent antslam command lines (lists of arguments, without the program): with
    --ranks 1 as antslam() does, `parallel` at a time, else as `mpirun -np K antslam batch` (job
    j on rank j % K, OUT/NAME.txt the jobs, OUT/NAME-logs/ their stdout). The outputs are the
    same either way. Returns the jobs' stdout in order; a failing job stops the experiment with
    one line, or with keep_going every job runs and each gives (stdout, None) or (None, the
    line antslam() would have stopped with)."""
    jobs = [[str(a) for a in job] for job in jobs]

    def one(job):
        if not keep_going:
            return antslam(args, *job)
        try:
            return antslam(args, *job), None
        except SystemExit as failure:
            return None, str(failure).splitlines()[-1]

    if args.ranks == 1 or not jobs:
        with concurrent.futures.ThreadPoolExecutor(max_workers=parallel) as pool:
            return list(pool.map(one, jobs))
    for job in jobs:
        if any(not a or any(c.isspace() for c in a) for a in job):
            sys.exit(f"antslam batch: a job argument is empty or holds a space: {' '.join(job)}")
    path = os.path.join(args.out, name + ".txt")
    write_text(path, "".join(" ".join(job) + "\n" for job in jobs))
    logs = os.path.join(args.out, name + "-logs")
    shutil.rmtree(logs, ignore_errors=True)  # so that only this batch's logs are read
    cmd = [*mpirun(args.ranks), args.antslam, "batch", path, "--log-dir", logs,
           *(["--keep-going"] if keep_going else [])]
    if not keep_going:
        run_program(*cmd)
    else:
        done = subprocess.run(cmd, capture_output=True, text=True)
        if done.returncode != 0 and not os.path.exists(os.path.join(logs, "line-1.out")):
            run_program(*cmd)  # the batch itself failed: stop with its line
    out = []
    for line, job in enumerate(jobs, 1):
        with open(os.path.join(logs, f"line-{line}.out")) as f:
            stdout = f.read()
        if not keep_going:
            out.append(stdout)
            continue
        error = os.path.join(logs, f"line-{line}.err")
        if os.path.exists(error):
            with open(error) as f:  # the job's own line, without the batch's "JOBS:LINE: "
                message = f.read().strip().replace(f"error: {path}:{line}: ", "error: ", 1)
            out.append((None, f"failed: {args.antslam} {' '.join(job)}: {message}"))
        else:
            out.append((stdout, None))
    return out


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


def step_mean(traces, grid):
    """Mean and std over trials of the best weight (a step function of time) on a grid; a grid
    point is drawn once 95% of the trials have a first result. A trace is a list of (time,
    weight) points in increasing time."""
    means, stds = [], []
    for t in grid:
        vals = []
        for trace in traces:
            v = None
            for (et, w) in trace:
                if et <= t:
                    v = w
            if v is not None:
                vals.append(v)
        if len(vals) < 0.95 * len(traces):
            means.append(float("nan"))
            stds.append(float("nan"))
            continue
        m = sum(vals) / len(vals)
        means.append(m)
        stds.append((sum((v - m) ** 2 for v in vals) / max(1, len(vals) - 1)) ** 0.5)
    return means, stds


def path_length(tum):
    """Metres along the positions of a TUM trajectory file."""
    poses = [tuple(map(float, line.split()[1:3])) for line in open(tum) if line[0] != "#"]
    return sum(math.dist(a, b) for a, b in zip(poses, poses[1:]))


def read_json(path):
    with open(path) as f:
        return json.load(f)


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def read_result(prefix):
    """The result file of `antslam optimize -o PREFIX` (PREFIX.json) with the wall-clock times
    of PREFIX.times.json as result["elapsed_s"] (mean, std, ... over the trials)."""
    result = read_json(prefix + ".json")
    result["elapsed_s"] = read_json(prefix + ".times.json")["elapsed_s"]
    return result


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


def write_atomically(path, write):
    """Calls write(temporary path), then renames the file to path: a reader never sees a half
    written file, and a failed run leaves the previous file as it was."""
    tmp = f"{path}.tmp-{os.getpid()}"
    try:
        write(tmp)
        os.replace(tmp, path)
    finally:
        if os.path.exists(tmp):
            os.remove(tmp)


def write_text(path, text):
    def write(tmp):
        with open(tmp, "w") as f:
            f.write(text)

    write_atomically(path, write)


def write_csv(path, header, rows):
    def write(tmp):
        with open(tmp, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(header)
            w.writerows(rows)

    write_atomically(path, write)


def publish(args, path, name):
    """With --publish, copies a result file to docs/figures/results-NAME."""
    if args.publish:
        os.makedirs(FIGURES, exist_ok=True)
        target = os.path.join(FIGURES, f"results-{name}")
        write_atomically(target, lambda tmp: shutil.copyfile(path, tmp))


def save_csv(args, name, header, rows):
    """Writes OUT/name.csv and, with --publish, docs/figures/results-name.csv."""
    path = os.path.join(args.out, name + ".csv")
    write_csv(path, header, rows)
    publish(args, path, name + ".csv")
    return path


def save_table(args, text):
    """Writes OUT/table.md (the Markdown the experiment's docs section shows)."""
    path = os.path.join(args.out, "table.md")
    write_text(path, text)
    return path


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
    write_atomically(path, lambda tmp: fig.savefig(tmp, dpi=110, format="png"))
    plt.close(fig)
    publish(args, path, name + ".png")
    return path
