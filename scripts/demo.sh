#!/usr/bin/env bash
# Installs what is missing, builds antslam, and runs the main job on data the project ships.
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j "$(nproc)" --target antslam
build/experiments/antslam tsp --instance data/tsplib/pr1002.tsp --variant mmas --local-search 3opt \
  --time 10 --stop-at-optimum --tour-out results/demo/pr1002.tour \
  --trace-csv results/demo/pr1002-trace.csv
