#!/usr/bin/env bash
# Speed goals, timed through `pdq run` on the example scenario files as they are:
# the §4.4.4 beam (80 000 steps) on one core in under 10 s, and the 4.06 m beam of §4.4.6
# (45 000 steps) on 2 ranks in under a minute. Wall-clock time of the whole command
# (start-up, power iteration, outputs included), and the force phase from timing.out.
# Usage: bench/mplm/run.sh [build-dir]
set -euo pipefail
build=$(cd "${1:-build}" && pwd)
src=$(cd "$(dirname "$0")/../.." && pwd)
cd "$(mktemp -d)"
timed() {  # name ranks goal-seconds
  local t0 t1
  t0=$(date +%s.%N)
  OMP_NUM_THREADS=1 mpirun --oversubscribe --allow-run-as-root -np "$2" "$build/pdq" run \
    "$src/examples/mplm/$1.toml" --quiet --out "$1"
  t1=$(date +%s.%N)
  local steps particles force
  steps=$(sed -nE 's/.* over [0-9]+ rank\(s\), ([0-9]+) steps/\1/p' "$1/timing.out")
  force=$(awk '$1 == "force" {print $4}' "$1/timing.out")
  particles=$("$build/pdq" info "$src/examples/mplm/$1.toml" | awk '$1 == "particles" {print $2}')
  awk -v n="$1" -v r="$2" -v g="$3" -v s="$steps" -v p="$particles" -v f="$force" \
    -v t0="$t0" -v t1="$t1" 'BEGIN { w = t1 - t0
      printf "%s: %d particles, %d steps on %d rank(s): %.2f s wall (goal < %d s: %s), force %.2f s = %.0f ns per particle-step\n",
        n, p, s, r, w, g, (w < g ? "met" : "NOT met"), f, 1e9 * f * r / (p * s) }'
}
timed rc_beam 1 10
timed deep_beam 2 60
