#!/bin/bash
# Runs the symmetric strain-softening bar (configs/materials/
# strain_softening_symmetric_bar.toml; docs/theory/softening.md) at 45, 93
# and 279 cells and draws two figures:
#   scripts/plot_softening.sh FLOWMPM RUNS_DIR [PNG_DIR]
# FLOWMPM is the engine binary (e.g. build/flowmpm), RUNS_DIR where the runs
# go (one folder per run, made afresh), PNG_DIR where the figures go
# (default: the repository's docs/). The runs take a few seconds.
#
# Figures (900 x 500 px):
#   softening_counts.png   energy dissipated per unit cross-section against
#                          the cells along the bar: the model's count
#                          (dissipated_energy) and the energy balance's
#                          (boundary work less kinetic and stored energy),
#                          with the default band (1 and 2 x 2 particles per
#                          cell) and with nonlocal_length = 0, against G_c
#   softening_history.png  the shipped bar (93 cells): both counts over time,
#                          as shipped (MUSL, dt = 0.2 h / c) and with USL at
#                          dt = 0.45 h / c, where the two part
# Needs gnuplot (scripts/setup.sh --tests installs it).
set -euo pipefail
bin=${1:?usage: plot_softening.sh FLOWMPM RUNS_DIR [PNG_DIR]}
runs=${2:?usage: plot_softening.sh FLOWMPM RUNS_DIR [PNG_DIR]}
root=$(cd "$(dirname "$0")/.." && pwd)
png=${3:-$root/docs}
mkdir -p "$runs" "$png"
data=$(mktemp -d)
trap 'rm -rf "$data"' EXIT

# bar N PPC SCHEME COURANT L: writes the bar at N cells (the test's
# symmetric_bar_case, tests/test_strain_softening.cpp) to RUNS_DIR and
# prints its path. L: the nonlocal length, "default" for none.
bar() {
  python3 - "$@" "$runs" <<'EOF'
import math, sys
N, ppc, scheme, courant, l, runs = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3], float(sys.argv[4]), sys.argv[5], sys.argv[6]
E, nu, eps_i = 30e9, 0.2, 1e-4
M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu))
L, h, c = 0.1, 0.2 / N, math.sqrt(M / 2400.0)
v0 = 0.6 * eps_i * math.sqrt(E / M) * c
name = f"bar_{N}_{ppc}_{scheme}_{courant}_{l}"
lines = [
    "[analysis]", "dimension = 2", f'scheme = "{scheme}"', f"dt = {courant * h / c!r}",
    f"steps = {round(1.9 * N / 2 / courant)}",
    "[grid]", f"origin = [{-L - h!r}, 0.0]", f"cell_size = {h!r}", f"cells = [{N + 2}, 1]",
    "[materials.concrete]", 'type = "strain_softening"', "density = 2400.0", "youngs_modulus = 30e9",
    "poisson_ratio = 0.2", "initiation_strain = 1e-4", "fracture_energy = 5.0",
]
if l != "default":
    lines.append(f"nonlocal_length = {l}")
lines += ["[[bodies]]", 'material = "concrete"', f"min = [{-L!r}, 0.0]", f"max = [{L!r}, {h!r}]",
          f"particles_per_cell = {ppc}",
          "[[node_sets]]", 'name = "lateral"', f"min = [{-L - h!r}, 0.0]", f"max = [{L + h!r}, {h!r}]",
          "velocity = { y = 0.0 }"]
for side, set_name in ((-1, "left"), (1, "right")):
    lines += ["[[node_sets]]", f'name = "{set_name}"', 'plane = "x"', f"at = {side * L!r}",
              f"velocity = {{ x = {side * v0!r} }}"]
lines += ["[output]", "every = 1000000"]
path = f"{runs}/{name}.toml"
open(path, "w").write("\n".join(lines) + "\n")
print(path)
EOF
}

# counts DIR H: "model balance" per unit cross-section (J/m^2) from summary.json.
counts() {
  python3 -c "
import json, sys
d = json.load(open('$1/summary.json'))
h = $2
print(d['dissipated_energy'] / h, (d['boundary_work'] - d['kinetic_energy'] - d['stored_energy']) / h)"
}

# run CASE: runs CASE (a .toml) into the folder of its name; prints the folder.
run() {
  local case=$1 out=${1%.toml}
  rm -rf "$out"
  echo "plot_softening: running $(basename "$out")" >&2
  "$bin" run "$case" --threads 1 --quiet --output "$out" >&2
  echo "$out"
}

: >"$data/counts.dat"
for N in 45 93 279; do
  h=$(python3 -c "print(0.2 / $N)")
  row="$N"
  for ppc in 1 2; do
    out=$(run "$(bar $N $ppc musl 0.2 default)")
    row="$row $(counts "$out" "$h")"
  done
  out=$(run "$(bar $N 1 musl 0.2 0)")
  row="$row $(counts "$out" "$h")"
  echo "$row" >>"$data/counts.dat"
done
echo "plot_softening: N, then model and balance (J/m^2) for 1 ppc, 2 x 2 ppc, nonlocal_length = 0:" >&2
cat "$data/counts.dat" >&2

# The shipped bar's history, and the same with USL at 0.45 h / c.
shipped=$runs/shipped
rm -rf "$shipped"
"$bin" run "$root/configs/materials/strain_softening_symmetric_bar.toml" --threads 1 --quiet --output "$shipped" \
  --set output.every=2
usl=$runs/usl_045
rm -rf "$usl"
"$bin" run "$(bar 93 1 usl 0.45 default)" --threads 1 --quiet --output "$usl" --set output.every=1
for run_dir in "$shipped" "$usl"; do
  python3 - "$run_dir/timeseries.csv" "$(python3 -c 'print(0.2 / 93)')" >"$data/$(basename "$run_dir").dat" <<'EOF'
import csv, sys
h = float(sys.argv[2])
for r in csv.DictReader(open(sys.argv[1])):
    w, k, u, d = (float(r[c]) for c in ("boundary_work", "kinetic_energy", "stored_energy", "dissipated_energy"))
    print(float(r["time"]) * 1e6, d / h, (w - k - u) / h)
EOF
done

cell_band=$(awk '{printf "%s%.1f", (NR > 1 ? ", " : ""), $6}' "$data/counts.dat")
gnuplot <<EOF
set terminal pngcairo size 900,500 font ",11"
set output "$png/softening_counts.png"
set logscale x
set xrange [38:330]
set xtics (45, 93, 279)
set yrange [4.6:5.6]
set xlabel "cells along the bar"
set ylabel "dissipated per unit cross-section (J/m^2)"
set title "Symmetric softening bar: G_c = 5 J/m^2 by the model's count and the energy balance's"
set key top right
set object 1 rect from 38,4.75 to 330,5.25 fc rgb "#e0e0e0" fs solid noborder behind
set label 1 "with nonlocal length 0 (the crack band of one cell), model: $cell_band J/m^2 (off the scale)" at graph 0.03, 0.06
plot 5 w l lc rgb "black" dt 2 t "G_c (band: 5 %)", \
     "$data/counts.dat" u 1:2 w lp pt 7 lc rgb "#1f77b4" t "default band, 1 ppc: model", \
     "" u 1:3 w lp pt 6 lc rgb "#1f77b4" dt 3 t "default band, 1 ppc: balance", \
     "" u 1:4 w lp pt 5 lc rgb "#2ca02c" t "default band, 2 x 2 ppc: model", \
     "" u 1:5 w lp pt 4 lc rgb "#2ca02c" dt 3 t "default band, 2 x 2 ppc: balance"
set output "$png/softening_history.png"
unset logscale x
unset object 1
unset label 1
set xtics auto
set xrange [0:52]
set yrange [-0.5:8]
set xlabel "time (us)"
set title "Symmetric bar, 93 cells: dissipation over time, the model's count and the balance's"
set key top left
plot 5 w l lc rgb "black" dt 2 t "G_c", \
     "$data/shipped.dat" u 1:2 w l lw 2 lc rgb "#1f77b4" t "MUSL, dt = 0.2 h/c (shipped): model", \
     "" u 1:3 w l lw 2 lc rgb "#1f77b4" dt 3 t "MUSL, dt = 0.2 h/c: balance", \
     "$data/usl_045.dat" u 1:2 w l lw 2 lc rgb "#d62728" t "USL, dt = 0.45 h/c: model", \
     "" u 1:3 w l lw 2 lc rgb "#d62728" dt 3 t "USL, dt = 0.45 h/c: balance"
EOF
echo "plot_softening: wrote $png/softening_counts.png and $png/softening_history.png" >&2
