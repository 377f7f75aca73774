#!/usr/bin/env bash
# Peridynamics benchmarks: bash bench/pd/run.sh BUILD_DIR [quick]   (about 15 minutes)
#  1. pdq against LAMMPS's PERI package on the same 3D simple-cubic block (47^3 = 103,823
#     particles, δ = 3 s, 200 steps, undamped and undamaged): displacement agreement and
#     throughput (particle-steps/s, bond-steps/s) of each code at 1 and 2 ranks, and the
#     ratio, for PMB (peri/pmb) and LPS (peri/lps);
#  2. the thesis's Tables 3.2/3.3 (the preprocessor writes the thesis's input files, each
#     run reads them): the monitored particle's final Y of the 2D cantilever
#     (721 x 309, 223,820 particles, LPS at ν = 0.22 and PMB at its ν = 1/3) for 1-4 ranks,
#     several grids and 1-2 threads, which must all be identical;
#  3. peak memory of the 1,122,892-particle cantilever (1617 x 693) and bytes per bond.
# `quick` shrinks every problem (a smoke test of this script).
set -euo pipefail
BUILD=$(cd "${1:?usage: run.sh BUILD_DIR [quick]}" && pwd)
QUICK=${2:-}
BENCH="$BUILD/bench/pd/pd_bench"
LMP=${LMP:-/usr/bin/lmp}
# A rank waiting for a message gives its core away (the machine is shared), so a rank's CPU
# time is its own work.
MPIRUN=(mpirun --oversubscribe --allow-run-as-root --mca mpi_yield_when_idle 1)
WORK=$(mktemp -d /tmp/pd_bench.XXXXXX)
trap 'rm -rf "$WORK"' EXIT
N=47; M=721; D=309; BIGM=1617; BIGN=693
if [[ $QUICK == quick ]]; then N=14; M=90; D=30; BIGM=160; BIGN=70; fi
export OMP_NUM_THREADS=1

echo "load average $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc --all) cores (the machine is shared: rates are"
echo " wall clock over the time loop; cpu rates are the busiest rank's CPU time, pdq's own work)"
"$BENCH" bandwidth
echo "(bytes per bond-step streamed by pdq: PMB 8 = 4 partner row offset + 4 pair-row offset;"
echo " LPS 16 = two passes of 4 partner index + 4 pair-row offset; partner positions and the"
echo " rows come from cache)"
"$BENCH" divider
"$BENCH" incore
echo
echo "== pdq vs LAMMPS PERI: ${N}^3 simple-cubic block, delta = 3 s, 200 steps =="
printf '%-5s %-5s %12s %12s %12s %12s %12s %7s %10s\n' model ranks pdq_ptcl/s pdq_cpu/s \
  lmp_ptcl/s lmp_cpu/s pdq_bond/s ratio rel_diff
declare -A rate
for model in pmb lps; do
  for np in 1 2; do
    dir="$WORK/$model.np$np"; mkdir -p "$dir"
    out=$("${MPIRUN[@]}" -np "$np" "$BENCH" block "$N" "$model" 200 "$dir")
    pdq_ps=$(sed -n 's/.* particle-steps\/s=\([^ ]*\).*/\1/p' <<<"$out")
    pdq_cpu=$(sed -n 's/.*cpu-particle-steps\/s=\([^ ]*\).*/\1/p' <<<"$out")
    pdq_bs=$(sed -n 's/.*bond-steps\/s=\([^ ]*\).*/\1/p' <<<"$out")
    pdq_sum=$(sed -n 's/.*cpu_sum=\([^ ]*\).*/\1/p' <<<"$out")
    grep '^  rank=' <<<"$out" >>"$WORK/ranks.txt"
    lmp_ps=n/a; lmp_cpu=n/a; lmp_sum=n/a; ratio=n/a; rel=n/a
    if [[ -x $LMP ]]; then
      (cd "$dir" && env -i PATH=/usr/bin:/bin HOME=/tmp OMP_NUM_THREADS=1 \
         "${MPIRUN[@]}" -np "$np" "$LMP" -in lammps.in -log lammps.log >lmp.out 2>&1)
      loop=$(grep '^Loop time' "$dir/lammps.log" | tail -1 | awk '{print $4}')
      natoms=$(grep '^Loop time' "$dir/lammps.log" | tail -1 | awk '{print $(NF-1)}')
      # "P% CPU use with ...": the share of the loop the ranks spent on a core
      cpu_use=$(sed -n 's/^\([0-9.]*\)% CPU use.*/\1/p' "$dir/lammps.log" | tail -1)
      lmp_ps=$(awk -v n="$natoms" -v t="$loop" 'BEGIN{printf "%.4g", n*200/t}')
      lmp_cpu=$(awk -v r="$lmp_ps" -v c="${cpu_use:-100}" 'BEGIN{printf "%.4g", r*100/c}')
      lmp_sum=$(awk -v t="$loop" -v c="${cpu_use:-100}" -v p="$np" 'BEGIN{printf "%.4f", t*c/100*p}')
      ratio=$(awk -v a="$pdq_ps" -v b="$lmp_ps" 'BEGIN{printf "%.2f", a/b}')
      rel=$("$BENCH" compare "$dir/pdq.disp" "$dir/lammps.dump" | sed -n 's/.*relative=//p')
    fi
    rate[$model.$np]="$pdq_ps $pdq_cpu $lmp_ps $lmp_cpu $pdq_sum $lmp_sum"
    printf '%-5s %-5s %12s %12s %12s %12s %12s %7s %10s\n' "$model" "$np" "$pdq_ps" "$pdq_cpu" \
      "$lmp_ps" "$lmp_cpu" "$pdq_bs" "$ratio" "$rel"
  done
done
echo "1 -> 2 ranks speed-up (wall clock; CPU time of the busiest rank) and efficiency (CPU time of"
echo " the time loop on 1 rank over the sum of both ranks' on 2: 100 % = the second rank added no work):"
for model in pmb lps; do
  read -r a1 c1 l1 lc1 s1 ls1 <<<"${rate[$model.1]}"
  read -r a2 c2 l2 lc2 s2 ls2 <<<"${rate[$model.2]}"
  awk -v m="$model" -v a1="$a1" -v a2="$a2" -v c1="$c1" -v c2="$c2" -v l1="$l1" -v l2="$l2" \
    -v lc1="$lc1" -v lc2="$lc2" -v s1="$s1" -v s2="$s2" -v ls1="$ls1" -v ls2="$ls2" \
    'function r(x, y) { return (x + 0 > 0 && y + 0 > 0) ? sprintf("%.2fx", y / x) : "n/a" }
     function e(x, y) { return (x + 0 > 0 && y + 0 > 0) ? sprintf("%.0f %%", 100 * x / y) : "n/a" }
    BEGIN { printf "  %-4s pdq %s (cpu %s), efficiency %s (goal >= 90 %%)   LAMMPS %s (cpu %s), efficiency %s\n",
            m, r(a1, a2), r(c1, c2), e(s1, s2), r(l1, l2), r(lc1, lc2), e(ls1, ls2) }'
done
echo "pdq's CPU seconds of the time loop per rank and phase (pmb 1, 2 ranks, then lps):"
cat "$WORK/ranks.txt"
echo "load average $(cut -d' ' -f1-3 /proc/loadavg)"

echo
echo "== Instability checks (non-finite values, skin, growing motion; every step) on the PMB block, 1 rank =="
(cd "$WORK" && "$BENCH" check_cost "$N" 200)
(cd "$WORK" && "$BENCH" checkpoint_cost "$N" 200 50)

echo
echo "== Thesis Tables 3.2/3.3: cantilever ${M} x ${D}, monitored particle's final Y =="
for model in lps pmb; do
  ys=()
  for cfg in "1 1 1 1" "1 1 1 2" "2 2 1 1" "2 1 2 2" "3 3 1 1" "4 4 1 1" "4 2 2 1"; do
    read -r np px py th <<<"$cfg"
    line=$(cd "$WORK" && OMP_NUM_THREADS=$th "${MPIRUN[@]}" -np "$np" -x OMP_NUM_THREADS="$th" \
             "$BENCH" cantilever "$M" "$D" "$model" "$px" "$py")
    echo "$line"
    ys+=("$(sed -n 's/.*Y=\([^ ]*\).*/\1/p' <<<"$line")")
  done
  if [[ $(printf '%s\n' "${ys[@]}" | sort -u | wc -l) == 1 ]]; then
    echo "$model: all ${#ys[@]} runs give Y = ${ys[0]} (identical)"
  else
    echo "$model: RESULTS DIFFER"; exit 1
  fi
done

echo
echo "== Memory: cantilever ${BIGM} x ${BIGN} ($(( (BIGM + 1) * (BIGN + 1) )) particles), 1 rank, 5 steps =="
for model in pmb lps; do
  line=$(cd "$WORK" && "$BENCH" cantilever "$BIGM" "$BIGN" "$model" 1 1 5)
  echo "$line"
  awk '{for (i = 1; i <= NF; ++i) { split($i, kv, "="); v[kv[1]] = kv[2] } }
       END { printf "%s: peak %.0f MiB = %.1f bytes per bond (all memory over %d bonds); %s\n",
             $1, v["peak_MiB"], v["peak_MiB"] * 1048576 / v["bonds"], v["bonds"],
             v["peak_MiB"] < 4096 ? "fits 4 GiB" : "DOES NOT FIT 4 GiB" }' <<<"$line"
done
