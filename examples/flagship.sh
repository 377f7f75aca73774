#!/usr/bin/env bash
# make run: the flagship example — the reinforced-concrete beam of thesis §4.4.4 loaded
# until it cracks, the picture of its damage and its load–deflection curve.
# Usage: examples/flagship.sh PATH/TO/pdq
set -euo pipefail
PDQ=$(realpath "${1:-build/pdq}")
cd "$(dirname "$0")/mplm"
ranks=$(($(nproc) >= 2 ? 2 : 1))
OMP_NUM_THREADS=1 mpirun --oversubscribe --allow-run-as-root -np "$ranks" "$PDQ" run rc_beam.toml
"$PDQ" post picture rc_beam.toml
"$PDQ" post plot rc_beam_out/history.csv --x uy --y load_factor --x-scale -1000 \
  --title "RC beam, thesis §4.4.4" --xlabel "midspan deflection (mm)" \
  --ylabel "line load (kN/m)" --label "load ramped to 60 kN/m, then held" \
  -o rc_beam_out/load_deflection.png
echo
echo "damage picture:         $(pwd)/rc_beam_out/damage_080000.png"
echo "load-deflection curve:  $(pwd)/rc_beam_out/load_deflection.png"
