#!/usr/bin/env bash
# Speed of the visual outputs (ParaView step, damage picture) for 490,000 particles on
# 1 and 2 ranks. Usage: bench/post/run.sh BUILD_DIR
set -euo pipefail
build=${1:-build}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for np in 1 2; do
  mpirun --oversubscribe --allow-run-as-root -np "$np" "$build/bench/post/post_bench" 700 700 "$out/np$np"
done
