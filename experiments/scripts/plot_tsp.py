#!/usr/bin/python3
"""Figures for docs/tsp*.md. Run with /usr/bin/python3 (needs matplotlib).

  plot_tsp.py tour INSTANCE.tsp TOUR.tour OUT.png       a tour drawn over its cities
  plot_tsp.py trace OPTIMUM OUT.png LABEL=TRACE.csv...  % over the optimum against time
  plot_tsp.py construction BENCH.json OUT.png           tours/s against size and threads
"""
import csv
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_tsplib_section(path, section):
    """Rows of numbers of a TSPLIB section (NODE_COORD_SECTION or TOUR_SECTION)."""
    rows, inside = [], False
    with open(path) as f:
        for line in f:
            text = line.strip()
            if not text:
                continue
            if text.split(":")[0].strip() == section:
                inside = True
                continue
            if inside:
                if text[0].isalpha():
                    break
                rows.append(text.split())
    return rows


def plot_tour(instance, tour, out):
    coords = {int(r[0]): (float(r[1]), float(r[2]))
              for r in read_tsplib_section(instance, "NODE_COORD_SECTION")}
    order = [int(t) for row in read_tsplib_section(tour, "TOUR_SECTION") for t in row]
    order = order[: order.index(-1)] if -1 in order else order
    xs = [coords[i][0] for i in order + order[:1]]
    ys = [coords[i][1] for i in order + order[:1]]
    fig, ax = plt.subplots(figsize=(7, 7))
    ax.plot(xs, ys, "-", lw=0.7, color="tab:blue")
    ax.plot(xs, ys, ".", ms=2, color="black")
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_yticks([])
    ax.set_title(f"{tour.split('/')[-1]} ({len(order)} cities)")
    fig.tight_layout()
    fig.savefig(out, dpi=120)


def plot_trace(optimum, out, traces):
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for spec in traces:
        label, path = spec.split("=", 1)
        with open(path) as f:
            rows = list(csv.DictReader(f))
        t = [float(r["elapsed_s"]) for r in rows]
        excess = [100.0 * (float(r["global_best"]) / optimum - 1.0) for r in rows]
        ax.step(t, excess, where="post", label=label)
    ax.set_xlabel("wall-clock time (s)")
    ax.set_ylabel("best tour, % over the optimum")
    ax.set_yscale("symlog", linthresh=0.1)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(out, dpi=120)


def plot_construction(bench, out):
    with open(bench) as f:
        runs = json.load(f)["benchmarks"]
    medians = any(r.get("aggregate_name") == "median" for r in runs)
    series = {}
    for r in runs:
        if not r["name"].startswith("BM_Construct/"):
            continue
        if medians != (r.get("aggregate_name") == "median"):
            continue  # the medians of repetitions when there are some, else every run
        fields = dict(part.split(":") for part in r["run_name"].split("/")[1:] if ":" in part)
        label = r.get("label", "").split()[0]
        series.setdefault(int(fields["threads"]), []).append((label, r["items_per_second"]))
    fig, ax = plt.subplots(figsize=(7, 4.5))
    names = [label for label, _ in series[min(series)]]
    width = 0.8 / len(series)
    base = dict(series[min(series)])
    for k, (threads, points) in enumerate(sorted(series.items())):
        xs = [names.index(label) + (k - (len(series) - 1) / 2) * width for label, _ in points]
        ax.bar(xs, [v for _, v in points], width, label=f"{threads} thread(s)")
        if threads != min(series):
            for x, (label, v) in zip(xs, points):
                ax.annotate(f"{v / base[label]:.2f}x", (x, v), ha="center", va="bottom")
    ax.set_xticks(range(len(names)))
    ax.set_xticklabels(names)
    ax.set_yscale("log")
    ax.set_ylabel("tours constructed per second")
    ax.grid(True, axis="y", which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(out, dpi=120)


def main(argv):
    if len(argv) >= 5 and argv[1] == "tour":
        plot_tour(argv[2], argv[3], argv[4])
    elif len(argv) >= 5 and argv[1] == "trace":
        plot_trace(float(argv[2]), argv[3], argv[4:])
    elif len(argv) == 4 and argv[1] == "construction":
        plot_construction(argv[2], argv[3])
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main(sys.argv)
