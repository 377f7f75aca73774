#!/usr/bin/env bash
# Lennard-Jones throughput of pdq beside LAMMPS (lj/cut, and lj/cut with -sf opt) on the
# same problem, in the same run: fcc at reduced density 0.8442 melting from T* = 1.44,
# rc = 2.5 (energy-shifted), skin 0.3, dt = 0.005, at 1 and 2 MPI ranks (one thread each)
# for 32,000 and 256,000 atoms. Rates are particle-steps per second of wall-clock time
# over the time loop alone (LAMMPS's "Loop time"); ratio = pdq / LAMMPS.
#
#   bench/lj/run.sh BUILD_DIR [RANKS...]        (default ranks: 1 2)
# Environment: LMP (default /usr/bin/lmp), LJ_STEPS_SMALL (200), LJ_STEPS_LARGE (100),
# LJ_ROUNDS (3: pdq and lj/cut/opt run alternately this many times, medians kept; lj/cut once).
set -euo pipefail

build=$(cd "${1:?usage: run.sh BUILD_DIR [RANKS...]}" && pwd)
shift
ranks=("$@")
rounds=${LJ_ROUNDS:-3}
[ ${#ranks[@]} -eq 0 ] && ranks=(1 2)
bench=$build/bench/lj/lj_bench
lmp=${LMP:-/usr/bin/lmp}
[ -x "$bench" ] || { echo "run.sh: $bench not built" >&2; exit 1; }
[ -x "$lmp" ] || { echo "run.sh: LAMMPS not found at $lmp (Debian package lammps)" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# A rank waiting for a message gives its core away (the machine is shared), so a rank's CPU
# time is its own work.
mpirun=(mpirun --oversubscribe --allow-run-as-root --mca mpi_yield_when_idle 1 -x OMP_NUM_THREADS=1)
export OMP_NUM_THREADS=1

# LAMMPS input for CELLS^3 fcc unit cells and STEPS steps, the same problem as lj_bench.
lammps_input() {
  cat <<IN
units lj
atom_style atomic
lattice fcc 0.8442
region box block 0 $1 0 $1 0 $1
create_box 1 box
create_atoms 1 box
mass 1 1.0
velocity all create 1.44 87287 loop geom
pair_style lj/cut 2.5
pair_coeff 1 1 1.0 1.0 2.5
pair_modify shift yes
neighbor 0.3 bin
neigh_modify delay 0 every 1 check yes
fix 1 all nve
timestep 0.005
thermo $2
run $2
IN
}

# The median of its arguments (numbers).
median() {
  printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}

# particle-steps per second from a LAMMPS log ("Loop time of T on P procs for N steps with M atoms")
lammps_rate() {
  awk '/^Loop time of/ { printf "%.4e\n", $12 * $9 / $4 }' "$1"
}

# LAMMPS's CPU rate: its rate over the share of the loop its ranks spent on a core
# ("P% CPU use with ..."), the counterpart of pdq's CPU time.
lammps_cpu_rate() {
  awk '/^Loop time of/ { r = $12 * $9 / $4 } /% CPU use/ { c = $1 + 0 } END { printf "%.4e\n", r * 100 / c }' "$1"
}

# CPU seconds of LAMMPS's loop, all ranks: loop time x CPU use x ranks.
lammps_cpu_sum() {
  awk -v p="$2" '/^Loop time of/ { t = $4 } /% CPU use/ { c = $1 + 0 } END { printf "%.4f\n", t * c / 100 * p }' "$1"
}

out=$build/bench/lj/throughput.txt
{
  echo "# LJ throughput, particle-steps/s (wall clock, time loop only); $(date -u +%Y-%m-%dT%H:%MZ) on $(nproc --all) cores, load average $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "# pdq and lj/cut/opt: medians of $rounds rounds run alternately (each round in the lines below); lj/cut: one run"
  echo "# cpu: the same over the busiest pdq rank's CPU time, and over LAMMPS's CPU use of lj/cut/opt"
  printf "%-8s %-5s %-6s %12s %12s %12s %10s %10s %12s %12s %8s\n" atoms ranks steps pdq lammps \
    lammps-opt pdq/lmp pdq/opt pdq_cpu opt_cpu cpu/opt
} | tee "$out.tmp"
for cells in 20 40; do
  atoms=$((4 * cells * cells * cells))
  steps=$([ "$cells" -eq 20 ] && echo "${LJ_STEPS_SMALL:-200}" || echo "${LJ_STEPS_LARGE:-100}")
  lammps_input "$cells" "$steps" > "$work/in.lj"
  for np in "${ranks[@]}"; do
    # pdq and lj/cut/opt alternately, ROUNDS times: the host moves a core's speed by tens
    # of per cent from minute to minute, so each code's median over the rounds is kept.
    pdq_r=() cpu_r=() sum_r=() opt_r=() optc_r=() opts_r=()
    for ((round = 0; round < rounds; ++round)); do
      line=$("${mpirun[@]}" -np "$np" "$bench" "$cells" "$steps")
      pdq_r+=("$(sed -n 's/.*particle_steps_per_s=\([^ ]*\).*/\1/p' <<<"$line")")
      cpu_r+=("$(sed -n 's/.*cpu_seconds=\([^ ]*\).*/\1/p' <<<"$line")")
      sum_r+=("$(sed -n 's/.*cpu_sum=\([^ ]*\).*/\1/p' <<<"$line")")
      grep '^  rank=' <<<"$line" | sed "s/^/# $atoms atoms, round $((round + 1)): /" >>"$work/ranks.txt"
      "${mpirun[@]}" -np "$np" "$lmp" -sf opt -in "$work/in.lj" -log "$work/opt.log" -screen none
      opt_r+=("$(lammps_rate "$work/opt.log")")
      optc_r+=("$(lammps_cpu_rate "$work/opt.log")")
      opts_r+=("$(lammps_cpu_sum "$work/opt.log" "$np")")
    done
    pdq=$(median "${pdq_r[@]}") pdq_cpu=$(median "${cpu_r[@]}") pdq_sum=$(median "${sum_r[@]}")
    opt=$(median "${opt_r[@]}") opt_cpu=$(median "${optc_r[@]}")
    echo "# $atoms atoms, $np rank(s), each round: pdq ${pdq_r[*]}, lj/cut/opt ${opt_r[*]}" >>"$work/rounds.txt"
    "${mpirun[@]}" -np "$np" "$lmp" -in "$work/in.lj" -log "$work/plain.log" -screen none
    plain=$(lammps_rate "$work/plain.log")
    echo "$atoms $np $pdq_sum $(median "${opts_r[@]}")" >>"$work/sums.txt"
    awk -v a="$atoms" -v n="$np" -v s="$steps" -v p="$pdq" -v l="$plain" -v o="$opt" -v c="$pdq_cpu" \
      -v oc="$opt_cpu" 'BEGIN { pc = a * s / c; printf "%-8s %-5s %-6s %12.4e %12.4e %12.4e %10.3f %10.3f %12.4e %12.4e %8.3f\n", a, n, s, p, l, o, p / l, p / o, pc, oc, pc / oc }' |
      tee -a "$out.tmp"
  done
done
# 1 -> 2 ranks speed-up of each code, from the rows above.
awk '!/^#/ && NF == 11 { key = $1; if ($2 == 1) { p1[key] = $4; o1[key] = $6; c1[key] = $9; q1[key] = $10 }
       if ($2 == 2) { p2[key] = $4; o2[key] = $6; c2[key] = $9; q2[key] = $10 } }
     END { for (k in p1) if (k in p2)
       printf "# %s atoms, 1 -> 2 ranks: pdq %.2fx (cpu %.2fx), lj/cut/opt %.2fx (cpu %.2fx)\n", k,
         p2[k] / p1[k], c2[k] / c1[k], o2[k] / o1[k], q2[k] / q1[k] }' "$out.tmp" | sort -n -k2 | tee -a "$out.tmp"
# 1 -> 2 ranks efficiency: CPU time of the loop on 1 rank over the sum of both ranks' on 2.
awk '{ k = $1; if ($2 == 1) { p1[k] = $3; o1[k] = $4 } if ($2 == 2) { p2[k] = $3; o2[k] = $4 } }
     END { for (k in p1) if (k in p2)
       printf "# %s atoms, 1 -> 2 ranks efficiency (CPU time, all ranks): pdq %.0f %% (goal >= 90 %%), lj/cut/opt %.0f %%\n",
         k, 100 * p1[k] / p2[k], 100 * o1[k] / o2[k] }' "$work/sums.txt" | sort -n -k2 | tee -a "$out.tmp"
cat "$work/rounds.txt" "$work/ranks.txt" | tee -a "$out.tmp"
echo "# load average $(cut -d' ' -f1-3 /proc/loadavg)" | tee -a "$out.tmp"
mv "$out.tmp" "$out"
echo "# written to $out"
