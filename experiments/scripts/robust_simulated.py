#!/usr/bin/python3
"""pcm-aco with and without the recalibrated check (`antslam robust --recalibrate`) on simulated
Manhattan pose graphs (simulated_graphs.py), none of them the public graphs it was designed on:
for every size, stated noise scale (1: as it is; 6: six times wider, as manhattan3500 and intel
state theirs), kind of false closures and graph seed, 1,000 false closures, then the false
closures kept, the recall and the position RMSE against the outlier-free least-squares map.
Writes robust-simulated.csv (one row per graph and setting) and table.md.

    PYTHONPATH=build/python /usr/bin/python3 experiments/scripts/robust_simulated.py
        [--poses 1000 3500] [--stated 1 6] [--kinds random random-group local-group]
        [--graphs 2] [--threads 2] [--out results/robust-simulated] [--publish] [--quick]

--quick: 1,000 poses, the noise stated 6 times wider, random false closures, one graph.
--antslam is not used (the back ends run in this process).
"""
import os
import sys
import time

import numpy as np

from experiment_common import (count_option, header, integer_at_least, markdown_table, parser,
                               progress, save_csv, save_table)
from simulated_graphs import WORLD_SIDE, manhattan_graph

try:
    import antslam
except ImportError:
    sys.exit("robust_simulated.py: error: the antslam Python module is not importable (build "
             "target antslam_python, then PYTHONPATH=build/python)")

def main():
    p = parser(__doc__, "robust-simulated")
    p.add_argument("--poses", type=int, nargs="+", choices=[1000, 3500], default=[1000, 3500])
    p.add_argument("--stated", type=float, nargs="+", default=[1.0, 6.0],
                   help="stated noise / real noise (standard deviations)")
    p.add_argument("--kinds", nargs="+", default=["random", "random-group", "local-group"],
                   help="kinds of false closures")
    count_option(p, "--graphs", "graph seeds per setting", 2, 1)
    p.add_argument("--threads", type=integer_at_least(1), default=2, help="threads of each run")
    args = p.parse_args()
    if args.quick:
        args.poses, args.stated, args.kinds = [1000], [6.0], ["random"]
    if not all(s > 0 for s in args.stated):
        p.error("--stated: scales must be > 0")
    os.makedirs(args.out, exist_ok=True)
    rows = []
    for poses in args.poses:
        for stated in args.stated:
            for kind in args.kinds:
                for seed in range(1, args.graphs + 1):
                    g = manhattan_graph(antslam, poses, 100 + seed, world=WORLD_SIDE[poses],
                                        stated_scale=stated)
                    clean = antslam.slam.robust(g, "ls").poses
                    spoiled, false = antslam.slam.add_outliers(g, 1000, kind=kind, seed=seed)
                    false_pairs = {tuple(f) for f in false.tolist()}
                    for recalibrate in (False, True):
                        start = time.perf_counter()
                        r = antslam.slam.robust(spoiled, "pcm-aco", recalibrate=recalibrate,
                                                threads=args.threads)
                        seconds = time.perf_counter() - start
                        kept = [tuple(c) for c in r.closures[r.accepted].tolist()]
                        kept_false = sum(c in false_pairs for c in kept)
                        recall = (len(kept) - kept_false) / (len(r.closures) - len(false))
                        rmse = float(np.sqrt(((r.poses[:, :2] - clean[:, :2]) ** 2).sum(1).mean()))
                        rows.append([poses, stated, kind, seed, recalibrate, kept_false, recall,
                                     rmse, seconds])
                    a, b = rows[-2], rows[-1]
                    progress(f"{poses} poses, stated x{stated:g}, {kind} #{seed}: false kept "
                             f"{a[5]} / {b[5]}, recall {a[6]:.3f} / {b[6]:.3f}, RMSE "
                             f"{a[7]:.3f} / {b[7]:.3f} m (without / with)")
    save_csv(args, "robust-simulated", ["poses", "stated", "kind", "graph", "recalibrate",
                                        "false_kept", "recall", "rmse_m", "time_s"], rows)
    table_rows = []
    for poses in args.poses:
        for stated in args.stated:
            for kind in args.kinds:
                cell = [r for r in rows if r[:3] == [poses, stated, kind]]
                without = [r for r in cell if not r[4]]
                with_ = [r for r in cell if r[4]]
                table_rows.append([poses, f"x{stated:g}", kind] + [
                    f"{np.mean([r[i] for r in without]):.{d}f} / {np.mean([r[i] for r in with_]):.{d}f}"
                    for i, d in ((5, 1), (6, 3), (7, 3), (8, 1))])
    table = markdown_table(["poses", "stated noise", "false closures",
                            "false kept (without / with)", "recall", "RMSE m", "time s"],
                           table_rows)
    save_table(args, header(args, "experiments/scripts/robust_simulated.py") + table)
    print(table, end="")


if __name__ == "__main__":
    main()
