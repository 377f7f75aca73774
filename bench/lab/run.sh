#!/usr/bin/env bash
# The laboratory tests of docs/lab-tests.md on two ranks: the notched beam run under
# displacement control past its peak, the reinforced beams through pdq's dynamic strength
# search; each curve drawn over the measured one into docs/lab/<test>.png with `pdq post
# plot` (pdq's curves as numbers in docs/lab/<test>_*.csv), the damage at the peak or at
# failure into docs/lab/<test>_peak.png or _failure.png with `pdq post picture`, and the
# README's table of laboratory tests printed: measured peak, pdq's peak, their ratio. Runs
# and logs stay in the work folder printed at the end.
# Usage: bench/lab/run.sh [build-dir] [ranks]
set -euo pipefail
build=$(cd "${1:-build}" && pwd)
ranks=${2:-2}
src=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
cd "$work"
run() {  # run <test>: the scenario bench/lab/<test>.toml into <test>_out
  OMP_NUM_THREADS=1 mpirun --oversubscribe --allow-run-as-root -np "$ranks" "$build/pdq" \
    run "$src/bench/lab/$1.toml" --out "$1_out" -q >"$1.log" 2>&1
}
# The peak row of quasi_static.csv: load step, load (N), displacement (m).
peak() { awk -F, 'NR > 1 && (n == 0 || $7 > p) { n = $1; p = $7; d = $8 } END { print n, p, d }' \
  "$1_out/quasi_static.csv"; }

echo "| test | measured peak | pdq peak | pdq / measured | what explains the difference |"
echo "| --- | --- | --- | --- | --- |"

# Grégoire et al. 2013, notched beam: the load against the CMOD, the opening between the
# bottom particles 20 mm apart either side of the notch (history_ids of the scenario).
t=gregoire_notched
if run $t; then
  # timehist.dat: per load step a row for each gauge particle, in ID order (left, right).
  awk '!/^#/ { if (!n || $1 != s) { n = 1; s = $1; a = $4 }
               else { d = $4 - a; if (s == 0) d0 = d; print s, (d - d0) * 1e3 } }' \
    $t"_out/timehist.dat" >cmod.txt
  { echo "# pdq's curve of bench/lab/$t.toml (bench/lab/run.sh): per load step the CMOD"
    echo "# (mm, between the bottom particles at x = 77.5 and 97.5 mm) and the load (N, the"
    echo "# reaction of the pushed particles); the first row is the unloaded state."
    echo "cmod_mm,load_N"; echo "0,0"
    awk 'FNR == NR { cmod[$1] = $2; next } FNR > 1 { printf "%.9g,%.9g\n", cmod[$1], $7 }' \
      cmod.txt FS=, $t"_out/quasi_static.csv"; } >"$src/docs/lab/${t}_pdq.csv"
  read -r step load disp < <(peak $t)
  cmod=$(awk -v s="$step" '$1 == s { printf "%.4f", $2 }' cmod.txt)
  "$build/pdq" post plot "$src/docs/lab/gregoire2013_d50_half_notched_load_cmod.csv" \
    "$src/docs/lab/${t}_pdq.csv" \
    --x cmod_mm --label "measured, lower envelope" --label "measured, upper envelope" \
    --label "pdq mplm2d" --y-scale 1e-3 --xlabel "CMOD (mm)" --ylabel "load (kN)" \
    --title "Gregoire et al. 2013, notched beam D = 50 mm: load against CMOD" \
    -o "$src/docs/lab/$t.png" >>$t.log
  "$build/pdq" post picture "$src/bench/lab/$t.toml" \
    --restart $t"_out/ParticleAlterAttrs.$step.rst" -o "$src/docs/lab/${t}_peak.png" \
    --set "title=Gregoire notched beam: tensile damage at the peak (load step $step, $(printf %.0f "$load") N)" >>$t.log
  awk -v p="$load" -v c="$cmod" 'BEGIN { printf "| Grégoire et al. 2013, notched beam D = 50 mm | 0.933–1.114 kN | %.3f kN at CMOD %s mm | %.2f–%.2f | docs/lab-tests.md §5 |\n", p / 1000, c, p / 1114, p / 933 }'
else
  echo "| Grégoire et al. 2013, notched beam | 0.933–1.114 kN | pdq run failed: see $work/$t.log |"
fi

# The reinforced beams: pdq's dynamic strength search (docs/mplm.md), its bracket the row;
# the curve is each trial's ramp, load against midspan deflection, of the highest trial
# that holds and the lowest that fails, drawn over the measured curve; the picture is the
# lowest failing trial at its end.
beam() {  # beam <test> <measured csv> <its load column> <measured peak> <unit> <title>
  local t=$1
  if ! OMP_NUM_THREADS=1 mpirun --oversubscribe --allow-run-as-root -np "$ranks" "$build/pdq" \
    strength "$src/bench/lab/$t.toml" >"$t.log" 2>&1; then
    echo "| $6 | $4 $5 | pdq strength failed: see $work/$t.log |"
    return
  fi
  # trials.csv: trial, load, holds (1 or 0), ...: the highest holding and lowest failing trial.
  local dir=${t}_out/strength held failed
  read -r held failed < <(awk -F, 'NR > 1 { if ($3 == 1 && $2 > h) { h = $2; hn = $1 }
    if ($3 == 0 && (f == "" || $2 < f)) { f = $2; fn = $1 } } END { print hn, fn }' "$dir/trials.csv")
  if [ -z "$failed" ]; then
    echo "| $6 | $4 $5 | no bracket: see $work/$dir/strength.txt |"
    return
  fi
  local n
  for n in "$held" "$failed"; do
    { echo "# pdq's curve of bench/lab/$t.toml (bench/lab/run.sh): trial $n of its strength"
      echo "# search, midspan deflection (mm) against the load ($5) as the ramp raises it"
      echo "deflection_mm,$3"
      awk -F, 'NR > 1 { printf "%.6g,%.6g\n", -$7 * 1e3, $3 }' "$dir/$(printf trial_%02d "$n")/history.csv"
    } >"$src/docs/lab/${t}_trial$n.csv"
  done
  local lo hi
  lo=$(awk -F, -v n="$held" '$1 == n { print $2 }' "$dir/trials.csv")
  hi=$(awk -F, -v n="$failed" '$1 == n { print $2 }' "$dir/trials.csv")
  "$build/pdq" post plot "$src/docs/lab/$2" "$src/docs/lab/${t}_trial$held.csv" \
    "$src/docs/lab/${t}_trial$failed.csv" --x deflection_mm \
    --label "measured" --label "pdq, holds at $(printf %.1f "$lo") $5" \
    --label "pdq, fails at $(printf %.1f "$hi") $5" --xlabel "midspan deflection (mm)" \
    --ylabel "$3" --title "$6: measured and pdq (dynamic strength trials)" \
    -o "$src/docs/lab/$t.png" >>"$t.log"
  local last
  last=$(ls "$dir/$(printf trial_%02d "$failed")"/ParticleAlterAttrs.*.rst)
  "$build/pdq" post picture "$src/bench/lab/$t.toml" --restart "$last" \
    -o "$src/docs/lab/${t}_failure.png" \
    --set "title=$6: tensile damage, the lowest failing trial ($(printf %.1f "$hi") $5)" >>"$t.log"
  awk -v lo="$lo" -v hi="$hi" -v m="$4" -v u="$5" -v name="$6" -v mode="$(sed -n 's/^failure mode: //p' "$dir/strength.txt")" \
    'BEGIN { printf "| %s | %s %s | %.1f–%.1f %s (%s) | %.2f–%.2f | docs/lab-tests.md §5 |\n", name, m, u, lo, hi, u, mode, lo / m, hi / m }'
}
beam vecchio_shim_oa1 vecchio_shim2004_oa1_load_deflection.csv load_kN 332 kN \
  "Vecchio & Shim 2004, beam OA1 (shear, no stirrups)"
beam janney_flexure janney1956_moment_deflection.csv moment_kNm 41.5 "kN m" \
  "Janney et al. 1956 (flexure, four-point bending)"
echo
echo "runs: $work/*_out; curves and pictures: $src/docs/lab/"
