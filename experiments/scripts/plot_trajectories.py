#!/usr/bin/python3
"""Plots TUM trajectories (x, y) on one figure: the reference in black, estimates in colour.

Usage: plot_trajectories.py --out FIG.png [--title T] REF.tum EST.tum [EST.tum ...]
Labels are the file names; pass `antslam eval --aligned-out` files to see the aligned estimates.
"""
import argparse
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_tum(path):
    xs, ys = [], []
    with open(path) as f:
        for number, line in enumerate(f, 1):
            fields = line.split()
            if not fields or fields[0].startswith("#"):
                continue
            if len(fields) != 8:
                sys.exit(f"{path}:{number}: expected 8 fields `timestamp x y z qx qy qz qw`")
            try:
                xs.append(float(fields[1]))
                ys.append(float(fields[2]))
            except ValueError:
                sys.exit(f"{path}:{number}: x or y is not a number")
    if not xs:
        sys.exit(f"{path}: no poses")
    return xs, ys


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("reference")
    parser.add_argument("estimates", nargs="+")
    parser.add_argument("--out", required=True, help="PNG file to write")
    parser.add_argument("--title", default="")
    args = parser.parse_args()

    fig, ax = plt.subplots(figsize=(7, 7), dpi=120)
    x, y = read_tum(args.reference)
    ax.plot(x, y, color="black", linewidth=1.2,
            label=f"reference ({args.reference.split('/')[-1]})")
    for path in args.estimates:
        x, y = read_tum(path)
        ax.plot(x, y, linewidth=0.9, alpha=0.85, label=path.split("/")[-1])
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.grid(True, linewidth=0.3)
    ax.legend(loc="best", fontsize=8)
    if args.title:
        ax.set_title(args.title)
    fig.tight_layout()
    fig.savefig(args.out)


if __name__ == "__main__":
    main()
