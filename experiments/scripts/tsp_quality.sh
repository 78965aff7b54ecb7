#!/usr/bin/env bash
# Reproduces the quality table of docs/tsp-results.md from a clean clone: MMAS + 3-opt on the
# seven TSPLIB target instances, 5 seeds, 10 s wall clock per run, 1 and 2 threads.
# Writes results/tsp/quality.csv (every run) and results/tsp/quality.md (the table).
# Takes about 7 x 5 x 2 x 10 s = 12 minutes; run it on an otherwise idle machine.
set -euo pipefail
cd "$(dirname "$0")/../.."

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build build -j "$(nproc)" --target antslam
build/experiments/antslam tsp-experiment \
  --instances d198,lin318,pcb442,att532,rat783,pr1002,pr2392 \
  --variants mmas --local-search 3opt --threads 1,2 --seeds 5 --time 10 \
  --csv results/tsp/quality.csv --markdown results/tsp/quality.md
