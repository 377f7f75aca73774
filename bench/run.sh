#!/usr/bin/env bash
# make bench: every benchmark, each beside its peer where one exists (LAMMPS).
# Usage: bash bench/run.sh BUILD_DIR [quick]
set -uo pipefail
BUILD=${1:?usage: bench/run.sh BUILD_DIR [quick]}
cd "$(dirname "$0")/.."
status=0
for area in lj pd mplm post scaling; do
  script=bench/$area/run.sh
  [ -f "$script" ] || continue
  echo
  echo "################ $area ################"
  bash "$script" "$BUILD" "${@:2}" || { echo "bench $area FAILED"; status=1; }
done
exit $status
