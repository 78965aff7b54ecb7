#!/usr/bin/env bash
# Installs what is missing, builds antslam, and runs the main job on data the project ships.
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j "$(nproc)" --target antslam
# AntSLAM on the bundled one-loop Malaga log (laser 0.78 m ahead of the robot origin, as the
# log's header says): frontend, hybrid ACO + NLopt, corrected trajectory, maps, report.
# (The former TSP demo is documented in docs/tsp.md.)
build/app/antslam map data/laser/malaga-oneloop.clf --laser-offset 0.78 \
  --out-dir results/demo/malaga-oneloop
