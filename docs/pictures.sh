#!/usr/bin/env bash
# make pictures: a picture of every example under examples/, run as it is and drawn by
# `pdq post`, into docs/images/. (The MPLM examples' damage at failure comes from
# `make validate`, into docs/mplm/.)
# Usage: docs/pictures.sh [build-dir]      (about 2 minutes on 2 cores)
set -euo pipefail
build=$(cd "${1:-build}" && pwd)
pdq=$build/pdq
src=$(cd "$(dirname "$0")/.." && pwd)
img=$src/docs/images
work=$(mktemp -d)
cd "$work"
mpi=(mpirun --oversubscribe --allow-run-as-root -np 2 env OMP_NUM_THREADS=1)

# Breaking springs torn open (examples/spring/tear.toml).
cp "$src"/examples/spring/* . 2>/dev/null || true
"${mpi[@]}" "$pdq" run tear.toml --quiet
"$pdq" post picture tear.toml -o "$img/spring_tear.png" --set "title=spring lattice torn open, step 600"
"$pdq" post plot tear_out/history.csv -x step -y broken_bonds -o "$img/spring_tear_broken.png" \
  --title "broken springs" --ylabel "broken springs"

# The Lennard-Jones melt (examples/lj/melt.toml): atoms coloured by potential energy, energies.
"${mpi[@]}" "$pdq" run "$src/examples/lj/melt.toml" --quiet --out melt_out
"$pdq" post picture "$src/examples/lj/melt.toml" --restart melt_out/ParticleAlterAttrs.1000.rst \
  -o "$img/lj_melt.png" --set colour_by=potential_energy --set view=1,0.6,0.4 --set width=900 \
  --set "title=LJ melt, 4000 atoms at step 1000, coloured by potential energy"
"$pdq" post plot melt_out/history.csv -x step -y potential -y kinetic -y total \
  -o "$img/lj_melt_energy.png" --title "LJ melt: energies" --ylabel "energy (reduced units)"

# Peridynamics: the PMB notched plate cracking, the LPS cantilever of thesis Table 3.1.
"${mpi[@]}" "$pdq" run "$src/examples/pmb/notched_plate.toml" --quiet --out notched_out
"$pdq" post picture "$src/examples/pmb/notched_plate.toml" \
  --restart notched_out/ParticleAlterAttrs.1400.rst -o "$img/pmb_notched_plate.png"
"${mpi[@]}" "$pdq" run "$src/examples/lps/cantilever.toml" --quiet --out cantilever_out
"$pdq" post picture "$src/examples/lps/cantilever.toml" \
  --restart cantilever_out/ParticleAlterAttrs.200.rst -o "$img/lps_cantilever.png"

# The RC beam of thesis §4.4.4 at the file's load (examples/mplm/rc_beam.toml).
"${mpi[@]}" "$pdq" run "$src/examples/mplm/rc_beam.toml" --quiet --out rc_beam_out
"$pdq" post picture "$src/examples/mplm/rc_beam.toml" --restart rc_beam_out/ParticleAlterAttrs.80000.rst \
  -o "$img/rc_beam_damage.png"
"$pdq" post plot rc_beam_out/history.csv --x uy --y load_factor --x-scale -1000 \
  -o "$img/rc_beam_load_deflection.png" --title "RC beam, thesis §4.4.4" \
  --xlabel "midspan deflection (mm)" --ylabel "line load (kN/m)" \
  --label "load ramped to 60 kN/m, then held"

# The out-of-tree Morse plugin (examples/plugin): installed pdq, plugin built against it.
cmake --install "$build" --prefix "$work/prefix" >/dev/null
cmake -S "$src/examples/plugin" -B plugin -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
cmake --build plugin -j2 >/dev/null
"$work/prefix/bin/pdq" run "$src/examples/plugin/cluster.toml" --plugin plugin/libmorse.so \
  --quiet --out cluster_out
"$work/prefix/bin/pdq" post picture "$src/examples/plugin/cluster.toml" --plugin plugin/libmorse.so \
  --restart cluster_out/ParticleAlterAttrs.2000.rst -o "$img/plugin_cluster.png" \
  --set colour_by=vx --set view=1,0.7,0.5 --set width=700 --set "title=Morse cluster (plugin), step 2000"
"$pdq" post plot cluster_out/history.csv -x step -y kinetic -y potential \
  -o "$img/plugin_cluster_history.png" --ylabel "energy" \
  --title "Morse cluster (plugin)"
echo "pictures in $img"
