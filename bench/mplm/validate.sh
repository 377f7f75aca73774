#!/usr/bin/env bash
# make validate: the strength table of thesis §4.4. Every 2D example — the scenario files
# examples/mplm/*.toml, as they are — through `pdq strength` twice, side by side: the
# quasi-static method (one run of dynamic relaxation under force control) and the dynamic
# bisection (two trials at a time), each on the same ranks, with their wall and CPU times.
# Printed as a Markdown table: the thesis's MPLM strength, the ACI 318 / classical value,
# pdq's quasi-static and dynamic brackets, quasi-static / thesis, the failure mode (of the
# dynamic failing trial when it ran, else of the quasi-static try beyond the peak) and the
# times. The dynamic bisection's lowest failing trial of each is drawn by `pdq post picture` into
# docs/mplm/<example>.png: the damage at failure. Reports and logs stay in the work folder
# printed at the end.
# Usage: bench/mplm/validate.sh [build-dir] [ranks] [examples...]
# QS_MASSES=assembled (or model) gives the quasi-static runs those fictitious masses (the
# strength search's qs_masses).
#   METHODS="quasi_static bisection" (default) or either one alone (the other's columns say
#   "not run"). ~25 minutes for the bisection on 2 cores, a few for the quasi-static runs.
# The 3D members are not in the default list (hours each, docs/mplm3d.md): name them,
#   bench/mplm/validate.sh build 2 cantilever3d rc_cantilever3d rc_beam3d
# SPACING=0.04 runs each example at that lattice spacing ([model] spacing added to a copy
# of its file; the 3D members then take minutes); its pictures stay in the work folder.
set -euo pipefail
build=$(cd "${1:-build}" && pwd)
ranks=${2:-2}
examples=("${@:3}")
[ ${#examples[@]} -gt 0 ] || examples=(tension_x tension_y compression_x compression_y plain_beam
  rc_beam rc_beam_stirrups rc_beam_shear deep_beam)
methods=${METHODS:-quasi_static bisection}
src=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
mkdir -p "$src/docs/mplm"
cd "$work"
field() { sed -n "s/^$1: //p" "$rep"; }  # a "key: value" line of the current report
TIMEFORMAT='%R %U %S'                      # wall, user and system seconds of `time`
# pdq strength of example $1 by method $2 in folder $2/; sets bracket, mode, times, rep.
strength() {
  local e=$1 m=$2 t
  mkdir -p "$m"
  bracket="not run" mode="" times="-" rep=/dev/null
  case " $methods " in *" $m "*) ;; *) return 0 ;; esac
  if ! t=$( { time (cd "$m" && OMP_NUM_THREADS=1 mpirun --oversubscribe --allow-run-as-root \
    -np "$ranks" "$build/pdq" strength "$sc" --set "method=$m" \
    ${QS_MASSES:+$( [ "$m" = quasi_static ] && echo "--set qs_masses=$QS_MASSES")} \
    >"$e.log" 2>&1); } 2>&1); then
    bracket="failed: see $work/$m/$e.log"
    return 0
  fi
  times=$(echo "$t" | awk '{printf "%.1f s (CPU %.1f s)", $1, $2 + $3}')
  rep=$m/${e}_out/strength/strength.txt
  bracket=$(field strength | sed -E 's/^([^ ]+) to ([^ ]+) ([^ ]+) .*/\1–\2 \3/')
  [ -n "$bracket" ] || bracket="not found ($(grep -m1 -E '^(in equilibrium|no failure|fails at)' "$rep"))"
  mode=$(field "failure mode")
}
echo "| example | thesis MPLM | ACI 318 / classical | pdq quasi-static | quasi-static / thesis |" \
  "pdq dynamic | failure mode | quasi-static time | dynamic time |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"
for e in "${examples[@]}"; do
  sc=$src/examples/mplm/$e.toml picture=$src/docs/mplm/$e.png
  if [ -n "${SPACING:-}" ]; then
    sed "/^\[model\]/a spacing = $SPACING" "$sc" >"$work/$e.toml"
    sc=$work/$e.toml picture=$work/$e.png
  fi
  strength "$e" quasi_static
  qs=$bracket qsTime=$times qsMode=$mode
  aci=$(field "ACI 318"; field classical)
  ref=$(field reference | sed -E 's/ \(.*//')
  ratio=$(field reference | sed -nE 's/.*= ([0-9.]+)\)$/\1/p')
  strength "$e" bisection
  dyn=$bracket dynTime=$times
  [ -n "$mode" ] || mode=$qsMode
  if [ "$rep" != /dev/null ]; then
    [ -n "$aci" ] || aci=$(field "ACI 318"; field classical)
    [ -n "$ref" ] || ref=$(field reference | sed -E 's/ \(.*//')
    restart=$(field "failing trial" | sed -nE 's/.*--restart ([^ )]+)\)$/\1/p')
    if [ -n "$restart" ]; then
      load=$(field strength | sed -E 's/^[^ ]+ to ([^ ]+ [^ ]+) .*/\1/')
      (cd bisection && "$build/pdq" post picture "$sc" --restart "$restart" \
        -o "$picture" \
        --set "title=$e: damage in the lowest failing trial, $load" >>"$e.log" 2>&1) ||
        echo "(picture of $e failed: see $work/bisection/$e.log)"
    fi
  fi
  echo "| $e | $ref | $aci | $qs | ${ratio:--} | $dyn | $mode | $qsTime | $dynTime |"
done
echo
echo "reports: $work/{quasi_static,bisection}/*_out/strength/strength.txt; pictures:" \
  "$(dirname "$picture")/"
