#!/usr/bin/env bash
# Speed goals of issue 4: the §4.4.4 beam (80 000 steps) on one core in under 10 s, and the
# 4.06 m beam of §4.4.6 (45 000 steps) on 2 ranks in under a minute.
# Usage: bench/mplm/run.sh [build-dir]
set -euo pipefail
build=$(cd "${1:-build}" && pwd)
exe=$build/bench/mplm/mplm_bench
mpirun=(mpirun --oversubscribe --allow-run-as-root)
cd "$(mktemp -d)"
OMP_NUM_THREADS=1 "${mpirun[@]}" -np 1 "$exe" time rc_beam 40
OMP_NUM_THREADS=1 "${mpirun[@]}" -np 2 "$exe" time deep_beam 300
