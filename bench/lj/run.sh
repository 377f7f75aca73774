#!/usr/bin/env bash
# Lennard-Jones throughput of pdq beside LAMMPS (lj/cut, and lj/cut with -sf opt) on the
# same problem, in the same run: fcc at reduced density 0.8442 melting from T* = 1.44,
# rc = 2.5 (energy-shifted), skin 0.3, dt = 0.005, at 1 and 2 MPI ranks (one thread each)
# for 32,000 and 256,000 atoms. Rates are particle-steps per second of wall-clock time
# over the time loop alone (LAMMPS's "Loop time"); ratio = pdq / LAMMPS.
#
#   bench/lj/run.sh BUILD_DIR [RANKS...]        (default ranks: 1 2)
# Environment: LMP (default /usr/bin/lmp), LJ_STEPS_SMALL (200), LJ_STEPS_LARGE (100).
set -euo pipefail

build=$(cd "${1:?usage: run.sh BUILD_DIR [RANKS...]}" && pwd)
shift
ranks=("$@")
[ ${#ranks[@]} -eq 0 ] && ranks=(1 2)
bench=$build/bench/lj/lj_bench
lmp=${LMP:-/usr/bin/lmp}
[ -x "$bench" ] || { echo "run.sh: $bench not built" >&2; exit 1; }
[ -x "$lmp" ] || { echo "run.sh: LAMMPS not found at $lmp (Debian package lammps)" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mpirun=(mpirun --oversubscribe --allow-run-as-root -x OMP_NUM_THREADS=1)
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

# particle-steps per second from a LAMMPS log ("Loop time of T on P procs for N steps with M atoms")
lammps_rate() {
  awk '/^Loop time of/ { printf "%.4e\n", $12 * $9 / $4 }' "$1"
}

out=$build/bench/lj/throughput.txt
{
  echo "# LJ throughput, particle-steps/s (wall clock, time loop only); $(date -u +%Y-%m-%dT%H:%MZ) on $(nproc --all) cores"
  printf "%-8s %-5s %-6s %12s %12s %12s %10s %10s\n" atoms ranks steps pdq lammps lammps-opt pdq/lmp pdq/opt
} | tee "$out.tmp"
for cells in 20 40; do
  atoms=$((4 * cells * cells * cells))
  steps=$([ "$cells" -eq 20 ] && echo "${LJ_STEPS_SMALL:-200}" || echo "${LJ_STEPS_LARGE:-100}")
  lammps_input "$cells" "$steps" > "$work/in.lj"
  for np in "${ranks[@]}"; do
    pdq=$("${mpirun[@]}" -np "$np" "$bench" "$cells" "$steps" |
      sed -n 's/.*particle_steps_per_s=\([^ ]*\).*/\1/p')
    "${mpirun[@]}" -np "$np" "$lmp" -in "$work/in.lj" -log "$work/plain.log" -screen none
    "${mpirun[@]}" -np "$np" "$lmp" -sf opt -in "$work/in.lj" -log "$work/opt.log" -screen none
    plain=$(lammps_rate "$work/plain.log")
    opt=$(lammps_rate "$work/opt.log")
    awk -v a="$atoms" -v n="$np" -v s="$steps" -v p="$pdq" -v l="$plain" -v o="$opt" \
      'BEGIN { printf "%-8s %-5s %-6s %12.4e %12.4e %12.4e %10.3f %10.3f\n", a, n, s, p, l, o, p / l, p / o }' |
      tee -a "$out.tmp"
  done
done
mv "$out.tmp" "$out"
echo "# written to $out"
