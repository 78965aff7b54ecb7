#!/bin/bash
# Runs the shipped irace scenario (experiments/irace) end to end with irace's smallest budget for
# its parameters (300 runs of 0.02 s CPU on two generated 200-city instances): the target runner,
# the parameter file, the default configuration and antslam's ACOTSP options must work together.
#   irace_scenario.sh ANTSLAM IRACE SCRATCH_DIR
set -eu
antslam="$1"; irace="$2"; scratch="$3"
scenario="$(cd "$(dirname "$0")/../../experiments/irace" && pwd)"
rm -rf "$scratch"
mkdir -p "$scratch/exec"
ANTSLAM="$antslam" SIZES="200" "$scenario/make-instances.sh" "$scratch/instances"
ANTSLAM="$antslam" ANTSLAM_TIME=0.02 "$irace" --scenario "$scenario/scenario.txt" \
  --train-instances-dir "$scratch/instances" --exec-dir "$scratch/exec" \
  --max-experiments 300 > "$scratch/irace.log" 2>&1 || { tail -20 "$scratch/irace.log"; exit 1; }
grep -A1 "Best configurations as commandlines" "$scratch/irace.log"
