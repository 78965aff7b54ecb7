#!/usr/bin/env bash
# Installs what is missing, builds antslam, and runs the main job on data the project ships.
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j "$(nproc)" --target antslam
build/experiments/antslam tsp --instance data/tsplib/kroA100.tsp --variant mmas --time 10 \
  --tour-out results/demo/kroA100.tour --trace-csv results/demo/kroA100-trace.csv
