#!/usr/bin/env bash
# MPLM speed, timed through `pdq run` on the example scenario files as they are (no peer
# code runs these models):
#  1. the speed goals: the §4.4.4 beam (80 000 steps) on one core in under 10 s, and the
#     4.06 m beam of §4.4.6 (45 000 steps) on 2 ranks in under a minute (wall clock of the
#     whole command: start-up, power iteration, outputs included);
#  2. throughput of mplm2d (the 4.06 m beam) and mplm3d (the §4.4.7 cantilever) at 1 and 2
#     ranks over a few thousand steps: particle-steps/s and core-ns per interaction-step of
#     the time loop (force + integrate + communication from timing.out, outputs left out),
#     the 1 -> 2 rank efficiency over the wall clock, and for mplm2d over CPU time as in 3;
#  3. the §4.4.7 cantilever's CPU time (user + sys of all ranks, which other users of the
#     machine change far less than the wall clock): per step from runs of 10 + S and 10
#     steps, per interaction-step, the 1 -> 2 rank CPU efficiency (work added by the second
#     rank: halo, interactions evaluated by both ranks), and the thesis's 100 000 steps
#     (Δt = 1.808e-7 s) projected on 2 ranks from wall and from CPU time (CPU / 2: the
#     two cores to ourselves), and (not `quick`) run: the example at that step, 100 000
#     steps on 2 ranks, the wall clock of the whole command;
#  4. peak memory (VmHWM, /usr/bin/time) of an mplm3d block of about a million particles
#     over 3 steps, per particle.
# Usage: bench/mplm/run.sh [build-dir] [quick]     (`quick`: shorter runs, no 1M block)
set -euo pipefail
build=$(cd "${1:-build}" && pwd)
quick=${2:-}
src=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
# A rank waiting for a message gives its core away (the machine is shared), so a rank's CPU
# time is its own work.
mpirun=(mpirun --oversubscribe --allow-run-as-root --mca mpi_yield_when_idle 1 -x OMP_NUM_THREADS=1)
export OMP_NUM_THREADS=1

timed() {  # name ranks goal-seconds
  local t0 t1
  t0=$(date +%s.%N)
  "${mpirun[@]}" -np "$2" "$build/pdq" run "$src/examples/mplm/$1.toml" --quiet --out "$1"
  t1=$(date +%s.%N)
  local steps particles force
  steps=$(sed -nE 's/.* over [0-9]+ rank\(s\), ([0-9]+) steps.*/\1/p' "$1/timing.out")
  force=$(awk '$1 == "force" {print $4}' "$1/timing.out")
  particles=$("$build/pdq" info "$src/examples/mplm/$1.toml" | awk '$1 == "particles" {print $2}')
  awk -v n="$1" -v r="$2" -v g="$3" -v s="$steps" -v p="$particles" -v f="$force" \
    -v t0="$t0" -v t1="$t1" 'BEGIN { w = t1 - t0
      printf "%s: %d particles, %d steps on %d rank(s): %.2f s wall (goal < %d s: %s), force %.2f s = %.0f ns per particle-step\n",
        n, p, s, r, w, g, (w < g ? "met" : "NOT met"), f, 1e9 * f * r / (p * s) }'
}

# Time loop (force + integrate + communication + shuffle, max over ranks) of `steps` steps
# of example $1 on $2 ranks, in seconds.
loop_seconds() {  # name ranks steps
  local out=$1.np$2
  "${mpirun[@]}" -np "$2" "$build/pdq" run "$src/examples/mplm/$1.toml" --steps "$3" --quiet \
    --out "$out"
  awk '$1 == "force" || $1 == "integrate" || $1 == "communication" || $1 == "shuffle" {
         t += $4 } END { printf "%.4f\n", t }' "$out/timing.out"
}

# Throughput at 1 and 2 ranks; sets `per_step2` (seconds per step on 2 ranks) and
# `per_step1` for the projection.
throughput() {  # model name steps
  local info particles inter t1 t2
  info=$("$build/pdq" info "$src/examples/mplm/$2.toml")
  particles=$(awk '$1 == "particles" {print $2}' <<<"$info")
  inter=$(awk '$1 == "bonds" {print $2}' <<<"$info")
  t1=$(loop_seconds "$2" 1 "$3")
  t2=$(loop_seconds "$2" 2 "$3")
  per_step1=$(awk -v t="$t1" -v s="$3" 'BEGIN { print t / s }')
  per_step2=$(awk -v t="$t2" -v s="$3" 'BEGIN { print t / s }')
  awk -v m="$1" -v n="$2" -v p="$particles" -v k="$inter" -v s="$3" -v t1="$t1" -v t2="$t2" 'BEGIN {
    for (r = 1; r <= 2; ++r) { t = (r == 1 ? t1 : t2)
      printf "%-7s %-12s %8d %8d %6d %5d %9.2f %12.4e %10.1f\n", m, n, p, k, s, r, t,
        p * s / t, 1e9 * t * r / (k * s) }
    printf "%-7s %-12s 1 -> 2 ranks: speed-up %.2fx, efficiency %.0f %% (goal >= 90 %%)\n",
      m, n, t1 / t2, 50 * t1 / t2 }'
}

# CPU seconds (user + sys, every rank) of example $1 on $2 ranks over $3 steps.
cpu_seconds() {  # name ranks steps
  /usr/bin/time -f "%U %S" -o "$1.cpu" "${mpirun[@]}" -np "$2" "$build/pdq" run \
    "$src/examples/mplm/$1.toml" --steps "$3" --quiet --out "$1.cpu.np$2"
  awk '{ print $1 + $2 }' "$1.cpu"
}

# An example's time loop in CPU time at 1 and 2 ranks; sets cpu1, cpu2 (s per step).
cpu_rows() {  # model name steps
  local model=$1 info inter a b
  shift
  info=$("$build/pdq" info "$src/examples/mplm/$1.toml")
  inter=$(awk '$1 == "bonds" {print $2}' <<<"$info")
  for r in 1 2; do
    a=$(cpu_seconds "$1" "$r" 10)
    b=$(cpu_seconds "$1" "$r" $((10 + $2)))
    printf -v "cpu$r" '%s' "$(awk -v a="$a" -v b="$b" -v s="$2" 'BEGIN { print (b - a) / s }')"
  done
  awk -v m="$model" -v n="$1" -v k="$inter" -v s="$2" -v c1="$cpu1" -v c2="$cpu2" 'BEGIN {
    for (r = 1; r <= 2; ++r) { c = (r == 1 ? c1 : c2)
      printf "%-7s %-12s CPU time, %d rank(s): %.2f ms per step (all ranks), %.0f ns per interaction-step\n",
        m, n, r, 1e3 * c, 1e9 * c / k }
    printf "%-7s %-12s 1 -> 2 ranks in CPU time: efficiency %.0f %% (goal >= 90 %%)\n", m, n, 100 * c1 / c2 }'
}

echo "# $(date -u +%Y-%m-%dT%H:%MZ), $(nproc --all) cores, load average $(cut -d" " -f1-3 /proc/loadavg)"
if [[ $quick == quick ]]; then steps2d=500 steps3d=50; else steps2d=5000 steps3d=500; fi

echo "== Speed goals (whole runs of the example files) =="
if [[ $quick != quick ]]; then
  timed rc_beam 1 10
  timed deep_beam 2 60
fi

echo
echo "== Throughput: time loop of the example files (outputs left out) =="
printf '%-7s %-12s %8s %8s %6s %5s %9s %12s %10s\n' model example particles interact steps \
  ranks loop_s ptcl-steps/s core-ns/int
throughput mplm2d deep_beam "$steps2d"
throughput mplm3d cantilever3d "$steps3d"
echo "1 -> 2 ranks in CPU time (user + sys of every rank, runs of 10 + S steps less 10):"
cpu_rows mplm2d deep_beam "$steps2d"

echo
echo "== §4.4.7 cantilever: the thesis's 100 000 steps of 1.808e-7 s, projected =="
dt=$("$build/pdq" info "$src/examples/mplm/cantilever3d.toml" | awk '$1 == "time" {print $3}')
own=$("$build/pdq" info "$src/examples/mplm/cantilever3d.toml" | awk '$1 == "steps" {print $4}')
cpu_rows mplm3d cantilever3d "$steps3d"
awk -v a="$per_step1" -v b="$per_step2" -v c="$cpu2" -v dt="$dt" -v own="$own" -v s="$steps3d" 'BEGIN {
  printf "measured over %d steps: %.1f ms per step on 1 rank, %.1f ms on 2 ranks (wall)\n", s, 1e3 * a, 1e3 * b
  printf "100000 steps (thesis): %.1f min on 2 ranks, %.1f min on 1 (wall, at this load; goal < 10 min, stretch 5; thesis: 30 min on 16 processors)\n",
    1e5 * b / 60, 1e5 * a / 60
  printf "100000 steps (thesis) from CPU time on 2 ranks, two free cores: %.1f min (goal < 10 min, stretch 5)\n",
    1e5 * c / 2 / 60
  printf "pdq'"'"'s own run of the file (%d steps of its stable %.3g s, same 18 ms): %.1f min on 2 ranks\n",
    own, dt, own * b / 60 }'

if [[ $quick != quick ]]; then
  # The goal itself, not projected: the example at the thesis's time step, 100 000 steps, on
  # 2 ranks, the whole command (set-up, outputs and the end's checkpoint included).
  sed 's/^name = "mplm3d".*/&\ndt = 1.808e-7/' "$src/examples/mplm/cantilever3d.toml" >thesis_dt.toml
  t0=$(date +%s.%N)
  "${mpirun[@]}" -np 2 "$build/pdq" run thesis_dt.toml --steps 100000 --quiet --out thesis_dt
  t1=$(date +%s.%N)
  awk -v t0="$t0" -v t1="$t1" 'BEGIN { m = (t1 - t0) / 60
    printf "100000 steps (thesis), run: %.2f min on 2 ranks, wall clock of the whole run (goal < 10 min: %s, stretch 5: %s)\n",
      m, (m < 10 ? "met" : "NOT met"), (m < 5 ? "met" : "not met") }'
  grep -E '^(force|integrate|communication|output)' thesis_dt/timing.out

  echo
  echo "== Peak memory: mplm3d block 8.0 x 0.84 x 0.84 m at s = 2 cm, 1 rank, 3 steps =="
  cat >block1m.toml <<'IN'
description = "mplm3d block of about a million particles (peak memory)"
steps = 3
[model]
name = "mplm3d"
[loading]
load_scale = 1000
ramp_time = 0.01
[particles]
generator = "mplm3d_beam"
length = 8.0
depth = 0.84
width = 0.84
IN
  info=$("$build/pdq" info block1m.toml)
  particles=$(awk '$1 == "particles" {print $2}' <<<"$info")
  grep -E '^(bonds|memory)' <<<"$info"
  /usr/bin/time -v "$build/pdq" run block1m.toml --quiet --out block1m 2>time.log
  awk -v p="$particles" '/Maximum resident set size/ { k = $NF }
    END { printf "%d particles: peak %.0f MiB = %.0f bytes per particle (goal <= 1024)\n",
          p, k / 1024, 1024 * k / p }' time.log
  grep -E '^(setup|force|output)' block1m/timing.out
fi
echo "# done $(date -u +%H:%MZ), load average $(cut -d" " -f1-3 /proc/loadavg)"
