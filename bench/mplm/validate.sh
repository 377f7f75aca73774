#!/usr/bin/env bash
# make validate: the strength table of thesis §4.4. Every 2D example — the scenario files
# examples/mplm/*.toml, as they are — through `pdq strength` (two trials side by side on
# two ranks), printed as a Markdown table: the thesis's MPLM strength, the ACI 318 /
# classical value, pdq's bracket, pdq / thesis and the failure mode. The lowest failing
# trial of each is drawn by `pdq post picture` into docs/mplm/<example>.png: the damage at
# failure. Reports and logs stay in the work folder printed at the end.
# Usage: bench/mplm/validate.sh [build-dir] [ranks] [examples...]   (~25 minutes on 2 cores)
# The 3D members are not in the default list (hours each, docs/mplm3d.md): name them,
#   bench/mplm/validate.sh build 2 cantilever3d rc_cantilever3d rc_beam3d
set -euo pipefail
build=$(cd "${1:-build}" && pwd)
ranks=${2:-2}
examples=("${@:3}")
[ ${#examples[@]} -gt 0 ] || examples=(tension_x tension_y compression_x compression_y plain_beam
  rc_beam rc_beam_stirrups rc_beam_shear deep_beam)
src=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
mkdir -p "$src/docs/mplm"
cd "$work"
field() { sed -n "s/^$1: //p" "$rep"; }  # a "key: value" line of the current report
echo "| example | thesis MPLM | ACI 318 / classical | pdq | pdq / thesis | failure mode |"
echo "| --- | --- | --- | --- | --- | --- |"
for e in "${examples[@]}"; do
  sc=$src/examples/mplm/$e.toml
  OMP_NUM_THREADS=1 mpirun --oversubscribe --allow-run-as-root -np "$ranks" "$build/pdq" \
    strength "$sc" >"$e.log" 2>&1 || { echo "| $e | pdq strength failed: see $work/$e.log |"; continue; }
  rep=${e}_out/strength/strength.txt
  bracket=$(field strength | sed -E 's/^([^ ]+) to ([^ ]+) ([^ ]+) .*/\1–\2 \3/')
  [ -n "$bracket" ] || bracket="not found ($(tail -1 "$e.log"))"
  aci=$(field "ACI 318"; field classical)
  ref=$(field reference | sed -E 's/ \(.*//')
  ratio=$(field reference | sed -nE 's/.*= ([0-9.]+)\)$/\1/p')
  echo "| $e | $ref | $aci | $bracket | ${ratio:--} | $(field "failure mode") |"
  restart=$(field "failing trial" | sed -nE 's/.*--restart ([^ )]+)\)$/\1/p')
  if [ -n "$restart" ]; then
    load=$(field strength | sed -E 's/^[^ ]+ to ([^ ]+ [^ ]+) .*/\1/')
    "$build/pdq" post picture "$sc" --restart "$restart" -o "$src/docs/mplm/$e.png" \
      --set "title=$e: damage in the lowest failing trial, $load" >>"$e.log" 2>&1 ||
      echo "(picture of $e failed: see $work/$e.log)"
  fi
done
echo
echo "reports: $work/*_out/strength/strength.txt; pictures: $src/docs/mplm/"
