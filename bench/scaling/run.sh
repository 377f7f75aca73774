#!/usr/bin/env bash
# Cluster scale, measured and modelled (docs/scaling.md):
#  1. the network: one exchange (MPI_Sendrecv of B bytes both ways, as each halo direction)
#     on 2 ranks for B = 8 bytes .. 2 MiB, through shared memory (Open MPI's default on one
#     machine) and through TCP on loopback; latency alpha, bandwidth 1/beta, and the step's
#     reduction lambda;
#  2. per model (the example scenarios): compute c, CPU seconds of the model's force and
#     integration per particle-step on one rank, and on 2 ranks the messages and bytes each
#     rank sends per step (the engine's counters) beside the halo the geometry predicts
#     (particles per cell, Plimpton's steps);
#  3. the check on 1-4 ranks (mplm3d, the §4.4.7 cantilever): the busiest rank's compute
#     CPU time, the wall time per step and the halo beside the model's;
#  4. the model's predictions for the §4.4.7 cantilever and a 10-million-particle 3D beam
#     on 16, 64 and 256 ranks (strong scaling), and weak scaling at the cantilever's
#     particles per rank, for the network measured here and an assumed InfiniBand;
#  5. 1 -> 2 ranks on this machine (two_cores.sh): the efficiency of PMB, LPS and LJ
#     256,000 atoms (median of three) beside the ceiling two cores allow (two independent
#     1-rank runs at once against one alone).
# Model per step on the busiest rank: T = c N_max + k_m M alpha + k_b W r beta + lambda log2 P
# (N_max owned particles, M messages and W wall particles of one halo, r bytes per wall
# particle, k_m and k_b all traffic over the halo's, measured on 2 ranks).
# Usage: bench/scaling/run.sh BUILD_DIR [quick]   (a few minutes on a quiet machine)
set -euo pipefail
build=$(cd "${1:?usage: run.sh BUILD_DIR [quick]}" && pwd)
quick=${2:-}
src=$(cd "$(dirname "$0")/../.." && pwd)
bench=$build/bench/scaling/scaling_bench
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
# A rank waiting for a message gives its core away (the machine is shared), so a rank's CPU
# time is its own work.
mpirun=(mpirun --oversubscribe --allow-run-as-root --mca mpi_yield_when_idle 1
  -x OMP_NUM_THREADS=1)
export OMP_NUM_THREADS=1
cores=$(nproc --all)
# An assumed cluster network (docs/scaling.md says where the figures come from).
ib_alpha_us=1.0 ib_gbs=12.0

field() { sed -nE "s/(^|.* )$1=([^ ]*).*/\2/p" | head -1; }  # key=value from stdin

echo "# $(date -u +%Y-%m-%dT%H:%MZ), $cores cores, load average $(cut -d' ' -f1-3 /proc/loadavg)," \
  "commit $(git -C "$src" rev-parse --short HEAD 2>/dev/null || echo unknown)"

echo
echo "== 1. Network: one exchange of B bytes each way between 2 ranks (fastest, median of 30 rounds) =="
# Waiting ranks poll here, as ranks with a core each do on a cluster.
net=(mpirun --allow-run-as-root -np 2)
"${net[@]}" "$bench" network >shm.txt
"${net[@]}" --mca pml ob1 --mca btl tcp,self "$bench" network >tcp.txt
printf '%10s %12s %12s %12s %12s\n' bytes shm_us shm_median tcp_us tcp_median
paste <(grep ^exchange shm.txt) <(grep ^exchange tcp.txt) |
  awk '{ for (k = 2; k <= 8; ++k) { split($k, f, "="); v[k] = f[2] }
         printf "%10d %12.2f %12.2f %12.2f %12.2f\n", v[2], v[3], v[4], v[7], v[8] }'
# From the fastest rounds: alpha, the smallest message; beta, the slope between the two
# largest.
fit() {
  awk '/^exchange/ { split($2, b, "="); split($3, t, "="); n++; B[n] = b[2]; T[n] = t[2] }
       /^reduction/ { split($3, r, "="); red = r[2] }
       END { printf "%.4f %.6g %.4f\n", T[1], (T[n] - T[n-1]) / (B[n] - B[n-1]), red }' "$1"
}
read -r shm_alpha shm_beta shm_red < <(fit shm.txt)
read -r tcp_alpha tcp_beta tcp_red < <(fit tcp.txt)
ib_beta=$(awk -v g="$ib_gbs" 'BEGIN { print 1e6 / (g * 1e9) }')  # us per byte
awk -v a="$shm_alpha" -v b="$shm_beta" -v r="$shm_red" -v A="$tcp_alpha" -v B="$tcp_beta" \
  -v R="$tcp_red" -v ia="$ib_alpha_us" -v ig="$ib_gbs" 'BEGIN {
  printf "shared memory: alpha %.2f us, bandwidth %.2f GB/s, reduction (2 ranks) %.2f us\n", a, 1e-3 / b, r
  printf "TCP loopback:  alpha %.2f us, bandwidth %.2f GB/s, reduction (2 ranks) %.2f us\n", A, 1e-3 / B, R
  printf "InfiniBand (assumed, EDR): alpha %.2f us, bandwidth %.1f GB/s, reduction alpha per tree level\n", ia, ig }'

echo
echo "== 2. Per model: compute on 1 rank (CPU time), traffic per rank per step on 2 ranks =="
if [[ $quick == quick ]]; then scale=10; else scale=1; fi
models=(spring lj pmb lps mplm2d mplm3d)
declare -A file=([spring]=spring/tear [lj]=lj/melt [pmb]=pmb/notched_plate [lps]=lps/cantilever
  [mplm2d]=mplm/deep_beam [mplm3d]=mplm/cantilever3d)
declare -A steps=([spring]=4000 [lj]=400 [pmb]=1000 [lps]=1000 [mplm2d]=300 [mplm3d]=40)
declare -A c km kb
printf '%-7s %9s %8s %12s | %9s %9s %10s %10s %10s %7s %6s %6s\n' model particles steps \
  c_ns/p-step msgs halo_msgs bytes halo_bytes geom_bytes error k_m k_b
for m in "${models[@]}"; do
  s=$((${steps[$m]} / scale))
  scen=$src/examples/${file[$m]}.toml
  one=$("$bench" run "$scen" "$s")
  two=$("${mpirun[@]}" -np 2 "$bench" run "$scen" "$s")
  geo=$("$bench" geometry "$scen" 0 2)
  n=$(field particles <<<"$one")
  c[$m]=$(awk -v t="$(field compute_cpu_s <<<"$one")" -v n="$n" -v s="$s" 'BEGIN { print 1e9 * t / (n * s) }')
  row=$(awk -v m="$m" -v n="$n" -v s="$s" -v c="${c[$m]}" -v msg="$(field messages <<<"$two")" \
    -v hm="$(field halo_messages <<<"$two")" -v by="$(field bytes <<<"$two")" \
    -v hb="$(field halo_bytes <<<"$two")" -v w="$(grep ^ranks=2 <<<"$geo" | field wall_max)" \
    -v r="$(field halo_record <<<"$two")" 'BEGIN {
      g = w * r; km = hm > 0 ? msg / hm : 1; kb = hb > 0 ? by / hb : 1
      printf "%-7s %9d %8d %12.1f | %9.2f %9.2f %10.0f %10.0f %10.0f %6.1f%% %6.3f %6.3f\n",
        m, n, s, c, msg, hm, by, hb, g, (g > 0 ? 100 * (g - hb) / hb : 0), km, kb }')
  echo "$row"
  km[$m]=$(awk '{ print $(NF-1) }' <<<"$row")
  kb[$m]=$(awk '{ print $NF }' <<<"$row")
done

# T per step (s) on the busiest rank: c N_max + k_m M alpha + k_b W r beta + lambda ceil(log2 P)
# args: c_ns N_max M W r k_m k_b alpha_us beta_us_per_byte lambda_us P
step_time() {
  awk -v c="$1" -v n="$2" -v M="$3" -v W="$4" -v r="$5" -v km="$6" -v kb="$7" -v a="$8" \
    -v b="$9" -v l="${10}" -v P="${11}" 'BEGIN { lv = 0; for (q = 1; q < P; q *= 2) ++lv
      printf "%.6g\n", 1e-9 * c * n + 1e-6 * (km * M * a + kb * W * r * b + l * lv) }'
}

echo
echo "== 3. Check on 1-4 ranks: mplm3d, the §4.4.7 cantilever ($cores cores: 3 and 4 ranks share them) =="
m=mplm3d
scen=$src/examples/${file[$m]}.toml
s=$((${steps[$m]} / scale))
geo=$("$bench" geometry "$scen" 0 1 2 3 4)
printf '%5s %7s %7s %7s %9s | %10s %10s %7s | %8s | %9s %10s %7s\n' ranks grid N_max \
  wall msgs compute_ms c_N_max err loop_cpu wall_ms wall_model err
for p in 1 2 3 4; do
  out=$("${mpirun[@]}" -np "$p" "$bench" run "$scen" "$s")
  g=$(grep "^ranks=$p " <<<"$geo")
  nmax=$(field owned_max <<<"$g")
  pred=$(step_time "${c[$m]}" "$nmax" "$(field messages_max <<<"$g")" "$(field wall_max <<<"$g")" \
    "$(field halo_record <<<"$out")" "${km[$m]}" "${kb[$m]}" "$shm_alpha" "$shm_beta" "$shm_red" "$p")
  awk -v p="$p" -v grid="$(field grid <<<"$out")" -v n="$nmax" -v w="$(field halo_wall <<<"$out")" \
    -v gw="$(field wall_max <<<"$g")" -v comp="$(field compute_cpu_s <<<"$out")" -v s="$s" \
    -v cpu="$(field cpu_s <<<"$out")" -v c="${c[$m]}" \
    -v wall="$(field step_median_s <<<"$out")" -v t="$pred" -v cores="$cores" \
    -v msg="$(field halo_messages <<<"$out")" -v gm="$(field messages_max <<<"$g")" 'BEGIN {
      cm = 1e3 * comp / s; model = 1e-6 * c * n; wm = 1e3 * wall
      share = p > cores ? p / cores : 1   # ranks per core when oversubscribed
      printf "%5d %7s %7d %7s %9s | %10.2f %10.2f %6.1f%% | %8.2f | %9.2f %10.2f %6.1f%%\n",
        p, grid, n, w "/" gw, sprintf("%.2f/%d", msg, gm), cm, model, 100 * (cm - model) / model,
        1e3 * cpu / s, wm, 1e3 * t * share, 100 * (wm - 1e3 * t * share) / (1e3 * t * share) }'
done
echo "(busiest rank per step; wall, msgs: the halo's wall particles and messages measured/geometric;"
echo " compute_ms: CPU of force + integration beside c N_max; loop_cpu: CPU of the whole step;"
echo " wall_ms: the median step beside the model with the shared-memory alpha, beta, beyond"
echo " $cores ranks the ranks sharing the cores evenly; load average now $(cut -d' ' -f1 /proc/loadavg))"

echo
echo "== 4. Predictions: mplm3d, seconds per step on the busiest rank (c = ${c[$m]} ns, measured above) =="
printf '%-26s %6s %9s %9s %9s | %11s %5s %5s | %11s %5s %5s\n' problem ranks grid N_max \
  wall_ptcl loopback_s comm eff infiniband_s comm eff
predict() {  # label geometry-output steps-for-total
  local label=$1 geo=$2 total=$3 n t1 line
  n=$(sed -n 1p <<<"$geo" | field particles)
  t1=$(awk -v c="${c[$m]}" -v n="$n" 'BEGIN { print 1e-9 * c * n }')
  while read -r line; do
    [[ $line == ranks=* ]] || continue
    local p nmax msgs wall r tl ti
    p=$(field ranks <<<"$line"); nmax=$(field owned_max <<<"$line")
    msgs=$(field messages_max <<<"$line"); wall=$(field wall_max <<<"$line")
    r=$(sed -n 1p <<<"$geo" | field halo_record)
    tl=$(step_time "${c[$m]}" "$nmax" "$msgs" "$wall" "$r" "${km[$m]}" "${kb[$m]}" "$shm_alpha" \
      "$shm_beta" "$shm_red" "$p")
    ti=$(step_time "${c[$m]}" "$nmax" "$msgs" "$wall" "$r" "${km[$m]}" "${kb[$m]}" "$ib_alpha_us" \
      "$ib_beta" "$ib_alpha_us" "$p")
    awk -v l="$label" -v p="$p" -v g="$(field grid <<<"$line")" -v n="$nmax" -v w="$wall" \
      -v tl="$tl" -v ti="$ti" -v t1="$t1" -v total="$total" -v c="${c[$m]}" 'BEGIN {
        tc = 1e-9 * c * n   # compute of the busiest rank; the rest is communication
        printf "%-26s %6d %9s %9d %9d | %11.4g %4.0f%% %4.0f%% | %11.4g %4.0f%% %4.0f%%", l, p, g,
          n, w, tl, (tl > tc ? 100 * (tl - tc) / tl : 0), 100 * t1 / (p * tl), ti,
          (ti > tc ? 100 * (ti - tc) / ti : 0),
          100 * t1 / (p * ti)
        if (total > 0) printf "   %d steps: %.3g h loopback, %.3g h InfiniBand", total,
          total * tl / 3600, total * ti / 3600
        printf "\n" }'
  done <<<"$geo"
}
geo=$("$bench" geometry "$scen" 0 1 16 64 256)
n0=$(sed -n 1p <<<"$geo" | field particles)
predict "cantilever §4.4.7 (strong)" "$geo" 100000
# The 10M beam: the same member at a finer spacing, k = (1e7/n0)^(1/3); its time step is k
# times smaller, so the thesis's 18 ms take k x 100 000 steps.
fine_steps=$(awk -v n="$n0" 'BEGIN { printf "%d\n", 1e5 * (1e7 / n) ^ (1 / 3) }')
predict "10M-particle beam (strong)" "$("$bench" geometry "$scen" 1e7 1 16 64 256)" "$fine_steps"
for p in 16 64 256; do
  predict "weak, $n0 per rank" "$("$bench" geometry "$scen" $((n0 * p)) "$p")" 0
done
echo "(comm: the share of the step that is communication; eff: strong rows against c N on one"
echo " rank, weak rows against one rank's $n0 particles;"
echo " the 10M beam is the cantilever's member at a finer spacing, the same particles per cell)"

echo
echo "== 5. 1 -> 2 ranks on this machine: efficiency and the two cores' ceiling =="
bash "$src/bench/scaling/two_cores.sh" "$build" "$quick"
