#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/) with clang in a build folder of their own and runs
# each from its seed corpus (fuzz/corpus/<target>, which stays as it is).
# Usage: tools/fuzz.sh [SECONDS [TARGET...]]   (default: 5 seconds each, all targets)
# Findings (crashes, leaks, hangs, out-of-memory) are written to $FUZZ_OUT (default:
# build-fuzz/findings); the exit code is non-zero when a target found one. With $FUZZ_BIN
# (the folder of targets already built: the suite's short run), nothing is built.
set -euo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)
build=${FUZZ_BUILD:-$src/build-fuzz}
seconds=${1:-5}
shift || true
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(scenario thesis restart checkpoint cli)
out=${FUZZ_OUT:-$build/findings}
bin=${FUZZ_BIN:-}
if [ -z "$bin" ]; then
  clang=$(command -v clang++ || command -v clang++-14)
  cmake -S "$src" -B "$build" -DPDQ_FUZZ=ON -DCMAKE_CXX_COMPILER="$clang" \
    -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$build" -j"${JOBS:-$(nproc)}" --target $(printf 'fuzz_%s ' "${targets[@]}") >/dev/null
  bin=$build/fuzz
fi
status=0
for t in "${targets[@]}"; do
  corpus="$out/$t/corpus"
  mkdir -p "$corpus" "$out/$t/artifacts"
  cp -n "$src/fuzz/corpus/$t/"* "$corpus/"
  # Leaks are checked; one input may take 10 s and 2 GB at most.
  if ASAN_OPTIONS=detect_leaks=1 "$bin/fuzz_$t" -max_total_time="$seconds" -timeout=10 \
      -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$out/$t/artifacts/" \
      "$corpus" >"$out/$t/log" 2>&1; then
    echo "fuzz_$t: $(grep -E '^stat::number_of_executed_units' "$out/$t/log" | awk '{print $2}') runs in ${seconds} s, nothing found"
  else
    status=1
    echo "fuzz_$t: found something; see $out/$t/log and $out/$t/artifacts/" >&2
    tail -30 "$out/$t/log" >&2
  fi
done
exit $status
