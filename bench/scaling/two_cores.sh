#!/usr/bin/env bash
# 1 -> 2 ranks on this machine: what pdq reaches and what the two cores allow.
# For each work (PMB and LPS 47^3 blocks, LJ 256,000 atoms), three rounds of
#   one:   1 rank, the whole problem;
#   two:   2 ranks, the whole problem (efficiency = one's CPU time over the sum of both
#          ranks' CPU time; speed-up = one's wall time over two's);
#   alone: 1 rank, about half the problem (a 37^3 block, 32^3 fcc cells), alone;
#   pair:  two INDEPENDENT 1-rank runs of that half at once, pinned one to each core as
#          the 2-rank run's ranks are (no messages, nothing shared but the machine: its
#          memory bus, last-level cache, and each core's own speed, which on this virtual
#          machine differs between the cores while both work: docs/scaling.md).
# The ceiling is alone's time per unit of work over pair's: what any 2-rank run can reach
# here, whatever its code (CPU time and wall time; work = bond-steps for the blocks,
# atom-steps for LJ). Medians over the rounds. Meaningful on a quiet machine only: another
# user's job shares the bus too, and in wall time it takes the cores.
# Usage: bench/scaling/two_cores.sh BUILD_DIR [quick]   (about 5 minutes on a quiet machine)
set -euo pipefail
build=$(cd "${1:?usage: two_cores.sh BUILD_DIR [quick]}" && pwd)
quick=${2:-}
pd=$build/bench/pd/pd_bench
lj=$build/bench/lj/lj_bench
for b in "$pd" "$lj"; do [[ -x $b ]] || { echo "two_cores.sh: $b not built" >&2; exit 1; }; done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMP_NUM_THREADS=1
mpirun=(mpirun --oversubscribe --allow-run-as-root --mca mpi_yield_when_idle 1 -x OMP_NUM_THREADS=1)
rounds=3 full=47 half=37 pdsteps=100 ljfull=40 ljhalf=32 ljsteps=60
if [[ $quick == quick ]]; then rounds=1 full=16 half=13 pdsteps=10 ljfull=8 ljhalf=6 ljsteps=10; fi

field() { sed -nE "s/(^|.* )$1=([^ ]*).*/\2/p" | head -1; }  # key=value from stdin
# One run in its own folder: prints "wall cpu_sum work" (work: bond-steps or atom-steps).
run() {  # dir ranks work-kind [core N] args...
  local dir=$1 np=$2 kind=$3 out
  shift 3
  # Two separate 1-rank launches at once would otherwise both be bound to core 0.
  local -a mpirun=("${mpirun[@]}") pin=()
  if [[ $1 == core ]]; then mpirun+=(--bind-to none); pin=(taskset -c "$2"); shift 2; fi
  mkdir -p "$dir"
  if [[ $kind == pd ]]; then
    out=$(cd "$dir" && "${mpirun[@]}" -np "$np" "${pin[@]}" "$pd" block "$@")
    awk -v t="$(field time <<<"$out")" -v c="$(field cpu_sum <<<"$out")" \
      -v b="$(field bonds <<<"$out")" -v s="$3" 'BEGIN { print t, c, b * s }'
  else
    out=$(cd "$dir" && "${mpirun[@]}" -np "$np" "${pin[@]}" "$lj" "$@")
    awk -v t="$(field seconds <<<"$out")" -v c="$(field cpu_sum <<<"$out")" \
      -v a="$(field atoms <<<"$out")" -v s="$2" 'BEGIN { print t, c, a * s }'
  fi
}
median() { sort -g | awk '{ v[NR] = $1 } END { print NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

echo "# $(date -u +%Y-%m-%dT%H:%MZ), $(nproc --all) cores, load average $(cut -d' ' -f1-3 /proc/loadavg)"
printf '%-4s %5s | %8s %8s | %8s %8s | %8s %8s\n' work round eff speedup cpu_ceil wall_ceil \
  pair_cpu pair_wall
declare -A summary
for w in pmb lps lj; do
  if [[ $w == lj ]]; then
    kind=lj whole=("$ljfull" "$ljsteps") part=("$ljhalf" "$ljsteps")
  else
    kind=pd whole=("$full" "$w" "$pdsteps") part=("$half" "$w" "$pdsteps")
  fi
  : >"$work/$w.rows"
  for r in $(seq "$rounds"); do
    d=$work/$w.$r
    read -r t1 c1 w1 < <(run "$d/one" 1 "$kind" "${whole[@]}")
    read -r t2 c2 w2 < <(run "$d/two" 2 "$kind" "${whole[@]}")
    read -r ta ca wa < <(run "$d/alone" 1 "$kind" "${part[@]}")
    run "$d/pa" 1 "$kind" core 0 "${part[@]}" >"$d.pa" &
    run "$d/pb" 1 "$kind" core 1 "${part[@]}" >"$d.pb"
    wait
    read -r tpa cpa wpa <"$d.pa"
    read -r tpb cpb wpb <"$d.pb"
    # pair: CPU time of both runs over their work, each run's wall time over its work
    awk -v w="$w" -v r="$r" -v t1="$t1" -v c1="$c1" -v t2="$t2" -v c2="$c2" -v ta="$ta" \
      -v ca="$ca" -v wa="$wa" -v tpa="$tpa" -v cpa="$cpa" -v tpb="$tpb" -v cpb="$cpb" 'BEGIN {
        cc = (ca / wa) / ((cpa + cpb) / (2 * wa)); wc = (ta / wa) / (((tpa + tpb) / 2) / wa)
        printf "%-4s %5d | %7.1f%% %7.2fx | %7.1f%% %7.1f%% | %7.2fs %7.2fs\n", w, r,
          100 * c1 / c2, t1 / t2, 100 * cc, 100 * wc, cpa + cpb, (tpa + tpb) / 2 }' |
      tee -a "$work/$w.rows"
  done
  col() { awk -v k="$1" '{ gsub(/[%x]/, "", $k); print $k }' "$work/$w.rows" | median; }
  summary[$w]=$(printf '%-4s median | %7.1f%% %7.2fx | %7.1f%% %7.1f%%' "$w" "$(col 4)" "$(col 5)" \
    "$(col 7)" "$(col 8)")
done
echo "medians over $rounds rounds (goal: efficiency >= 90 %):"
for w in pmb lps lj; do echo "${summary[$w]}"; done
echo "(eff: 1-rank CPU time over both ranks' on 2; speedup: wall time, 1 over 2 ranks; cpu_ceil,"
echo " wall_ceil: one half-size 1-rank run alone over two of them at once, per unit of work;"
echo " pair_cpu: both runs' CPU seconds, pair_wall: their mean wall seconds;"
echo " load average now $(cut -d' ' -f1-3 /proc/loadavg))"
