#!/usr/bin/env bash
# make run: the flagship example — a lattice torn open, and the picture of its damage.
# Usage: examples/flagship.sh PATH/TO/pdq
set -euo pipefail
PDQ=$(realpath "${1:-build/pdq}")
cd "$(dirname "$0")/spring"
"$PDQ" run tear.toml
"$PDQ" post picture tear.toml
echo
echo "damage picture: $(pwd)/tear_out/damage_000600.png"
