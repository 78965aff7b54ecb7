#!/usr/bin/python3
"""Island model against independent colonies at equal CPU time: per instance and seed s, one run
`mpirun -np 2 antslam tsp --colonies 2 --time T --seed s` (two colonies, one per rank, exchanging
their best tours every 25 iterations along a ring) and, right after it, two plain runs
`antslam tsp --time T` at the same time, one per core, seeded as the island run's colonies are
(colony 0: s, colony 1: aco::colony_seed(s, 1)), so that each pair differs only in the
exchange; the better of the two plain runs is "independent". Every run uses the TSP defaults
(MAX-MIN Ant System, 25 ants, rho 0.2, 3-opt local search) but builds its tours from nothing
(--focused-edges 0) with 10 local-search neighbours, as when docs/mpi-islands.md was measured.
Writes tsp-islands.csv (every run), table.md (mean excess over the optimum per instance, wins,
the share of the island runs' time spent in the exchange) and tsp-islands.png into the results
folder. pr2392 (data/tsplib) at 30 s with 5 seeds, d15112 (../shared/data/tsplib, when it is
there) at 120 s with 3 seeds: about 20 minutes; run it on an otherwise idle machine with two
cores free.

    /usr/bin/python3 experiments/scripts/tsp_islands.py [--quick] [--seeds 5] [--large-seeds 3]
        [--instances pr2392,d15112] [--no-mpi] [--publish]

--quick: pcb442 at 2 s, 1 seed, and a check that an island run without exchanges is the two
plain runs it pairs with. --no-mpi: the island run's two colonies share one process (a smoke
test only: each colony then has half the time).
"""
import os
import shutil
import subprocess

from experiment_common import (DATA, ROOT, check_program, count_option, header, load_average,
                               markdown_table, parser, plt, pm, progress, read_json, run_program,
                               save_csv, save_figure, save_table, stats)

SHARED = os.path.join(os.path.dirname(ROOT), "shared", "data", "tsplib")
BUDGET_S = {"pr2392": 30, "d15112": 120, "pcb442": 2}
LARGE = {"d15112"}  # instances that run --large-seeds seeds
MASK = (1 << 64) - 1


def splitmix64(state):
    z = (state + 0x9E3779B97F4A7C15) & MASK
    z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK
    z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK
    return z ^ (z >> 31)


def colony_seed(seed, colony):
    """aco::colony_seed (aco/islands.hpp): colony 0 keeps the seed, the others mix it."""
    if colony == 0:
        return seed
    h = splitmix64(seed)
    h = splitmix64(h ^ colony)
    return splitmix64(h ^ 0x151A2D5)


def instance_path(name):
    for folder in (os.path.join(DATA, "tsplib"), SHARED):
        path = os.path.join(folder, name + ".tsp")
        if os.path.exists(path):
            return path
    return None


def mpi_environment():
    env = dict(os.environ)
    if os.geteuid() == 0:  # Open MPI refuses root without these
        env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    return env


def tsp_command(args, path, seed, budget, json_path, *extra):
    return [args.antslam, "tsp", "-i", path, "--seed", str(seed), *budget, "--json", json_path,
            "--focused-edges", "0", "--neighbours", "10", "--quiet", *map(str, extra)]


def island_run(args, path, seed, budget, json_path, *extra):
    cmd = tsp_command(args, path, seed, budget, json_path, "--colonies", 2, *extra)
    if args.no_mpi:
        run_program(*cmd)
    else:
        done = subprocess.run([args.mpirun, "-np", "2", *cmd], capture_output=True, text=True,
                              env=mpi_environment())
        if done.returncode != 0:
            raise SystemExit(f"failed: mpirun -np 2 {' '.join(cmd)}: {done.stderr.strip()}")
    return read_json(json_path)


def plain_pair(args, path, seed, budget, json_stem):
    """The two colonies' seeds as plain runs, at the same time (one per core)."""
    jobs = []
    for colony in (0, 1):
        json_path = f"{json_stem}-{colony}.json"
        cmd = tsp_command(args, path, colony_seed(seed, colony), budget, json_path)
        jobs.append((subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                                      text=True), json_path, cmd))
    results = []
    for job, json_path, cmd in jobs:
        _, err = job.communicate()
        if job.returncode != 0:
            raise SystemExit(f"failed: {' '.join(cmd)}: {err.strip()}")
        results.append(read_json(json_path))
    return results


def check_pairing(args, path):
    """Without exchanges an island run is its two colonies' plain runs: the pairing holds."""
    stem = os.path.join(args.out, "pairing")
    budget = ["--iterations", "15"]
    island = island_run(args, path, 7, budget, stem + "-islands.json", "--exchange-every", 1000)
    plain = plain_pair(args, path, 7, budget, stem)
    lengths = [p["best_length"] for p in plain]
    if island["colony_best_lengths"] != lengths:
        raise SystemExit(f"pairing broken: island colonies {island['colony_best_lengths']}, "
                         f"plain runs {lengths}")
    progress(f"pairing holds: colonies {lengths} = plain runs")


def run_instance(args, name, seeds, rows):
    path = instance_path(name)
    if path is None:
        progress(f"{name}: not found in data/tsplib or ../shared/data/tsplib; skipped")
        return
    budget = ["--time", str(BUDGET_S[name])]
    for seed in range(1, seeds + 1):
        stem = os.path.join(args.out, f"{name}-{seed}")
        load = load_average()
        progress(f"{name} seed {seed}: islands, then two plain runs ({BUDGET_S[name]} s each); "
                 f"load {load:.2f}")
        island = island_run(args, path, seed, budget, stem + "-islands.json")
        rows.append([name, seed, "islands", "", seed, island["best_length"],
                     island["excess_percent"], island["iterations"], island["exchange_s"],
                     island["elapsed_s"], f"{load:.2f}"])
        load = load_average()
        for colony, r in enumerate(plain_pair(args, path, seed, budget, stem + "-plain")):
            rows.append([name, seed, "independent", colony, colony_seed(seed, colony),
                         r["best_length"], r["excess_percent"], r["iterations"], "",
                         r["elapsed_s"], f"{load:.2f}"])


def summarize(rows, instances):
    """Per instance: islands' and the better independent run's excess, wins, exchange share."""
    table, pairs = [], {}
    for name in instances:
        islands = {r[1]: r for r in rows if r[0] == name and r[2] == "islands"}
        if not islands:
            continue
        best_plain = {}
        for r in rows:
            if r[0] == name and r[2] == "independent":
                best_plain[r[1]] = min(best_plain.get(r[1], r[6]), r[6])
        seeds = sorted(islands)
        island_excess = [islands[s][6] for s in seeds]
        plain_excess = [best_plain[s] for s in seeds]
        pairs[name] = (seeds, island_excess, plain_excess)
        wins = sum(i < p for i, p in zip(island_excess, plain_excess))
        ties = sum(i == p for i, p in zip(island_excess, plain_excess))
        share = stats([100.0 * islands[s][8] / islands[s][9] for s in seeds])
        plain_iterations = stats([r[7] for r in rows if r[0] == name and r[2] == "independent"])
        table.append([name, BUDGET_S[name], len(seeds), pm(stats(island_excess)),
                      pm(stats(plain_excess)), f"{wins}/{ties}/{len(seeds) - wins - ties}",
                      f"{stats([islands[s][7] for s in seeds])['mean']:.0f} / "
                      f"{plain_iterations['mean']:.0f}", f"{share['mean']:.1f}"])
    return markdown_table(["instance", "s per colony", "seeds", "islands: excess %",
                           "independent (better of 2): excess %", "islands win/tie/lose",
                           "iterations per colony: islands / independent",
                           "exchange % of island time"], table), pairs


def plot(args, pairs):
    fig, axes = plt.subplots(1, max(1, len(pairs)), figsize=(4.5 * max(1, len(pairs)), 3.6),
                             squeeze=False)
    for ax, (name, (seeds, island, plain)) in zip(axes[0], pairs.items()):
        ax.plot(seeds, island, "o", label="islands (2 colonies, ring, E = 25)")
        ax.plot(seeds, plain, "s", mfc="none", label="independent (better of 2)")
        ax.set_title(f"{name}, {BUDGET_S[name]} s per colony")
        ax.set_xlabel("seed")
        ax.set_ylabel("excess over the optimum (%)")
        ax.set_xticks(seeds)
        ax.legend(fontsize=8)
    save_figure(args, fig, "tsp-islands")


def main():
    p = parser(__doc__, "tsp-islands")
    count_option(p, "--seeds", "seeds per instance", 5, 1)
    count_option(p, "--large-seeds", "seeds on d15112", 3, 1)
    p.add_argument("--instances", default="pr2392,d15112",
                   help="comma-separated, among " + ", ".join(BUDGET_S))
    p.add_argument("--mpirun", default=shutil.which("mpirun") or "mpirun",
                   help="the MPI launcher (Open MPI's mpirun)")
    p.add_argument("--no-mpi", action="store_true",
                   help="run the island run's colonies in one process (smoke test only)")
    args = p.parse_args()
    unknown = [name for name in args.instances.split(",") if name not in BUDGET_S]
    if unknown:
        p.error(f"--instances: unknown {', '.join(unknown)} (known: {', '.join(BUDGET_S)})")
    instances = ["pcb442"] if args.quick else args.instances.split(",")
    check_program(args)
    head = header(args, "experiments/scripts/tsp_islands.py")  # the load before the runs
    if args.quick:
        check_pairing(args, instance_path("pcb442"))
    rows = []
    for name in instances:
        run_instance(args, name, args.large_seeds if name in LARGE else args.seeds, rows)
    save_csv(args, "tsp-islands",
             ["instance", "seed", "mode", "colony", "run_seed", "length", "excess_percent",
              "iterations", "exchange_s", "elapsed_s", "load_before"], rows)
    text, pairs = summarize(rows, instances)
    plot(args, pairs)
    save_table(args, head + text + f"\nLoad average at the end: {load_average():.2f}.\n")
    print(text, end="")
    progress(f"wrote {args.out}/tsp-islands.csv, table.md, tsp-islands.png")


if __name__ == "__main__":
    main()
