#!/usr/bin/env bash
# Runs `antslam map` with every optimizer on the bundled logs and prints the Markdown table of
# docs/mapping.md: eq. (10) weight, closures within 2 sigma, ATE RMSE (against the reference
# where the log has one) and run times. Usage: scripts/map-methods.sh [OUT_DIR] (default
# results/map-methods). Serial, one thread per run, so the times are comparable.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-results/map-methods}
antslam=build/experiments/antslam
methods=(hybrid+nlopt hybrid+nlopt-plain hybrid mmas nlopt ceres ceres-robust)

run() {  # run LOG METHOD [extra antslam options...]
  local log=$1 method=$2
  shift 2
  local options=(--method "$method")
  if [[ $method == hybrid+nlopt-plain ]]; then options=(--method hybrid+nlopt --no-graduated); fi
  "$antslam" map "data/laser/$log.clf" "${options[@]}" --threads 1 --no-maps \
    --out "$out/$log-$method" "$@" > "$out/$log-$method.txt"
}

mkdir -p "$out"
for method in "${methods[@]}"; do
  run malaga-oneloop "$method" --laser-offset 0.78
  for log in intel-subset mit-csail; do
    run "$log" "$method" --reference "data/laser/$log.ref.tum"
  done
done

/usr/bin/python3 - "$out" "${methods[@]}" <<'EOF'
import json, sys
out, methods = sys.argv[1], sys.argv[2:]
print("| log | method | weight (eq. 10) best / mean of trials | closures within 2 sigma | "
      "largest closure Mahalanobis | ATE RMSE m | optimisation s (20 trials) | total s |")
print("|---|---|---|---|---|---|---|---|")
for log in ["malaga-oneloop", "intel-subset", "mit-csail"]:
    for method in methods:
        r = json.load(open(f"{out}/{log}-{method}/report.json"))
        o, c, t = r["optimization"], r["closures"], r["times"]
        within = sum(x["within_2_sigma"] for x in c)
        worst = max(x["optimized"]["mahalanobis"] for x in c)
        ate = "-"
        if "evaluation" in r:
            ate = "%.3f" % r["evaluation"]["optimized"]["ate"]["translation_m"]["rmse"]
        print(f"| {log} | {method} | {o['best']['weight']:.2f} / {o['weight']['mean']:.2f} | "
              f"{within} of {len(c)} | {worst:.2f} | {ate} | {t['optimization_s']:.2f} | "
              f"{t['total_s']:.1f} |")
    r = json.load(open(f"{out}/{log}-{methods[0]}/report.json"))
    ate = "-"
    if "evaluation" in r:
        ate = "%.3f" % r["evaluation"]["scan_matcher"]["ate"]["translation_m"]["rmse"]
    c = r["closures"]
    worst = max(x["scan_matcher"]["mahalanobis"] for x in c)
    within = sum(x["scan_matcher"]["mahalanobis"] <= 2 for x in c)
    print(f"| {log} | scan matcher alone | {r['optimization']['scan_matcher']['weight']:.2f} | "
          f"{within} of {len(c)} | {worst:.2f} | {ate} | - | {r['times']['frontend_s']:.1f} (frontend) |")
EOF
