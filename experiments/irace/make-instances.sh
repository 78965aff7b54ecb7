#!/bin/bash
# Writes the tuning instances into DIR (default: ./instances): random uniform and clustered
# instances of 500 to 20,000 cities (antslam tsp-generate; DIMACS portgen/portcgen kinds, the
# clustered ones also at a fifth of DIMACS's spread, as drilling instances). None of them is an
# instance that docs/tsp-results.md reports; the seeds (SEED_BASE + size index, default 1000, and
# 1000 more for the drilling ones) are used nowhere else. SEED_BASE=3000 writes the fresh
# instances on which irace's choices were checked (docs/tsp-results.md, "irace").
set -eu
here="$(cd "$(dirname "$0")" && pwd)"
exe="${ANTSLAM:-$here/../../build/app/antslam}"
dir="${1:-instances}"
sizes="${SIZES:-500 1000 2000 5000 10000 20000}"
base="${SEED_BASE:-1000}"
mkdir -p "$dir"
i=0
for n in $sizes; do
  i=$((i + 1))
  "$exe" tsp-generate --cities "$n" --seed $((base + i)) --out "$dir/E$n.tsp" > /dev/null
  "$exe" tsp-generate --cities "$n" --seed $((base + i)) --kind clustered \
    --out "$dir/C$n.tsp" > /dev/null
  "$exe" tsp-generate --cities "$n" --seed $((base + 1000 + i)) --kind clustered --spread 0.2 \
    --out "$dir/D$n.tsp" > /dev/null
done
echo "wrote $(ls "$dir" | wc -l) instances to $dir"
