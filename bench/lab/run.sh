#!/usr/bin/env bash
# The laboratory tests of docs/lab-tests.md (the scenarios of examples/lab/) on two ranks,
# each run under displacement control by the quasi-static solver past its peak; each curve
# drawn over the measured one into docs/lab/<test>.png with `pdq post plot` (pdq's curve as
# numbers in docs/lab/<test>_pdq.csv), the damage at the peak (and, for the reinforced
# beams, at the end of the run) into docs/lab/<test>_peak.png (_end.png) with `pdq post
# picture`, and the README's table of laboratory tests printed: measured peak, pdq's peak,
# their ratio. Runs and logs stay in the work folder printed at the end.
# Usage: bench/lab/run.sh [build-dir] [ranks] [test ...]   (tests: the scenarios' names; all by default)
set -euo pipefail
build=$(cd "${1:-build}" && pwd)
ranks=${2:-2}
shift $(($# < 2 ? $# : 2))
tests=${*:-gregoire_notched vecchio_shim_oa1 janney_flexure}
wanted() { [[ " $tests " == *" $1 "* ]]; }
src=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
cd "$work"
run() {  # run <test>: the scenario examples/lab/<test>.toml into <test>_out
  OMP_NUM_THREADS=1 mpirun --oversubscribe --allow-run-as-root -np "$ranks" "$build/pdq" \
    run "$src/examples/lab/$1.toml" --out "$1_out" -q >"$1.log" 2>&1
}
# The peak row of quasi_static.csv: load step, load (N), displacement (m).
peak() { awk -F, 'NR > 1 && (n == 0 || $7 > p) { n = $1; p = $7; d = $8 } END { print n, p, d }' \
  "$1_out/quasi_static.csv"; }

echo "| test | measured peak | pdq peak | pdq / measured | what explains the difference |"
echo "| --- | --- | --- | --- | --- |"

# Grégoire et al. 2013, notched beam: the load against the CMOD, the opening between the
# bottom particles 20 mm apart either side of the notch (history_ids of the scenario).
t=gregoire_notched
if ! wanted $t; then
  :
elif run $t; then
  # timehist.dat: per load step a row for each gauge particle, in ID order (left, right).
  awk '!/^#/ { if (!n || $1 != s) { n = 1; s = $1; a = $4 }
               else { d = $4 - a; if (s == 0) d0 = d; print s, (d - d0) * 1e3 } }' \
    $t"_out/timehist.dat" >cmod.txt
  { echo "# pdq's curve of examples/lab/$t.toml (bench/lab/run.sh): per load step the CMOD"
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
  "$build/pdq" post picture "$src/examples/lab/$t.toml" \
    --restart $t"_out/ParticleAlterAttrs.$step.rst" -o "$src/docs/lab/${t}_peak.png" \
    --set "title=Gregoire notched beam: tensile damage at the peak (load step $step, $(printf %.0f "$load") N)" >>$t.log
  awk -v p="$load" -v c="$cmod" 'BEGIN { printf "| Grégoire et al. 2013, notched beam D = 50 mm | 0.933–1.114 kN | %.3f kN at CMOD %s mm | %.2f–%.2f | docs/lab-tests.md §5 |\n", p / 1000, c, p / 1114, p / 933 }'
else
  echo "| Grégoire et al. 2013, notched beam | 0.933–1.114 kN | pdq run failed: see $work/$t.log |"
fi

# The reinforced beams: the load (quasi_static.csv: the reaction of the pushed plate
# particles, N) × <scale> against the midspan deflection (history.csv's uy, the bottom
# particles at midspan), per load step.
beam() {  # beam <test> <measured csv> <its load column> <scale> <measured peak> <unit> <title>
  local t=$1
  wanted "$t" || return 0
  if ! run "$t"; then
    echo "| $7 | $5 $6 | pdq run failed: see $work/$t.log |"
    return
  fi
  { echo "# pdq's curve of examples/lab/$t.toml (bench/lab/run.sh): per load step the midspan"
    echo "# deflection (mm, the bottom particles at midspan) and the load ($6, the reaction"
    echo "# of the pushed particles x $4); the first row is the unloaded state."
    echo "deflection_mm,$3"
    # history.csv's rows of the unloaded state and of the converged load steps (a run stopped
    # at a snap-back also writes the step it stopped at, which has no load).
    awk -F, -v k="$4" 'FNR == NR { if (FNR > 1) load[$1] = $7; next }
      FNR > 1 && !seen[$1]++ && ($1 == 0 || $1 in load) { printf "%.6g,%.6g\n", 0 - $7 * 1e3, k * load[$1] }' \
      "${t}_out/quasi_static.csv" "${t}_out/history.csv"; } >"$src/docs/lab/${t}_pdq.csv"
  read -r step load disp < <(peak "$t")
  local last defl
  last=$(awk -F, 'NR > 1 { n = $1 } END { print n }' "${t}_out/quasi_static.csv")
  defl=$(awk -F, -v s="$step" 'NR > 1 && $1 == s { printf "%.2f", -$7 * 1e3; exit }' "${t}_out/history.csv")
  "$build/pdq" post plot "$src/docs/lab/$2" "$src/docs/lab/${t}_pdq.csv" --x deflection_mm \
    --label "measured" --label "pdq mplm2d, displacement control" \
    --xlabel "midspan deflection (mm)" --ylabel "$3" --title "$7: measured and pdq" \
    -o "$src/docs/lab/$t.png" >>"$t.log"
  local n
  for n in "$step" "$last"; do
    "$build/pdq" post picture "$src/examples/lab/$t.toml" --restart "${t}_out/ParticleAlterAttrs.$n.rst" \
      -o "$src/docs/lab/${t}_$([ "$n" = "$step" ] && echo peak || echo end).png" \
      --set "title=$7: tensile damage at load step $n$([ "$n" = "$step" ] && echo ", the peak")" >>"$t.log"
  done
  awk -v p="$load" -v k="$4" -v d="$defl" -v m="$5" -v u="$6" -v name="$7" \
    'BEGIN { printf "| %s | %s %s | %.1f %s at %s mm | %.2f | docs/lab-tests.md §5 |\n", name, m, u, k * p, u, d, k * p / m }'
}
beam vecchio_shim_oa1 vecchio_shim2004_oa1_load_deflection.csv load_kN 1e-3 332 kN \
  "Vecchio & Shim 2004, beam OA1 (shear, no stirrups)"
# Janney: the two plates' reactions, each times the shear span 0.9144 m: the moment.
beam janney_flexure janney1956_moment_deflection.csv moment_kNm 4.572e-4 41.5 "kN m" \
  "Janney et al. 1956 (flexure, four-point bending)"
echo
echo "runs: $work/*_out; curves and pictures: $src/docs/lab/"
