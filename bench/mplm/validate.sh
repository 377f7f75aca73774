#!/usr/bin/env bash
# The table of issue 4: every 2D example of thesis §4.4 with the thesis's MPLM strength,
# the classical / ACI 318 value, pdq's strength (bisection, 2% bracket) and failure mode.
# Beams run the thesis's simulated time at the lattice's stable time step.
# Usage: bench/mplm/validate.sh [build-dir] [ranks-for-deep-beam]   (takes ~15 min on 1 core)
set -euo pipefail
build=$(cd "${1:-build}" && pwd)
ranks=${2:-2}
exe=$build/bench/mplm/mplm_bench
cd "$(mktemp -d)"
echo "| example | thesis MPLM | thesis classical/ACI | ACI 318 here | pdq strength | pdq mode |"
echo "| --- | --- | --- | --- | --- | --- |"
row() {
  # "<name>: strength in [lo, hi] unit, failure mode m (thesis MPLM t, thesis classical c,
  #  ACI/classical here a mode)"
  sed -E 's/^([a-z_]+): strength in \[([^,]+), ([^]]+)\] ([^,]+), failure mode ([a-z]+) \(thesis MPLM ([^,]+), thesis classical ([^,]+), ACI\/classical here ([^ ]+) ([a-z]+)\)$/| \1 | \6 \4 | \7 \4 | \8 \4 (\9) | \2–\3 \4 | \5 |/'
}
for e in tension_x tension_y compression_x compression_y; do
  OMP_NUM_THREADS=1 "$exe" strength "$e" 1 8 rel_tol=0.02 | tail -1 | row
done
for e in plain_beam rc_beam rc_beam_stirrups rc_beam_shear; do
  OMP_NUM_THREADS=1 "$exe" strength "$e" 30 120 rel_tol=0.02 stable_step=true | tail -1 | row
done
OMP_NUM_THREADS=1 mpirun --oversubscribe --allow-run-as-root -np "$ranks" "$exe" strength \
  deep_beam 300 700 rel_tol=0.05 stable_step=true | tail -1 | row
