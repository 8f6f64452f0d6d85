#!/bin/bash
# Runs the plane-strain biaxial compression of a confined block
# (configs/materials/mohr_coulomb_biaxial.toml and drucker_prager_biaxial.toml;
# docs/validation/soil_element_tests.md) and draws its figure:
#   scripts/plot_soil_element_tests.sh FLOWMPM RUNS_DIR [PNG_DIR]
# FLOWMPM is the engine binary (e.g. build/flowmpm), RUNS_DIR where the runs
# go (one folder per run, made afresh), PNG_DIR where the figure goes
# (default: the repository's docs/). The runs take a few seconds.
#
# Figure (900 x 500 px):
#   soil_biaxial.png  the block's mean sigma_1 = -sigma_yy against its mean
#                     axial strain -eps_yy, Mohr-Coulomb and Drucker-Prager's
#                     plane-strain fit, against sigma_3 N_phi + 2 c sqrt(N_phi)
# Needs gnuplot (scripts/setup.sh --tests installs it).
set -euo pipefail
bin=${1:?usage: plot_soil_element_tests.sh FLOWMPM RUNS_DIR [PNG_DIR]}
runs=${2:?usage: plot_soil_element_tests.sh FLOWMPM RUNS_DIR [PNG_DIR]}
root=$(cd "$(dirname "$0")/.." && pwd)
png=${3:-$root/docs}
mkdir -p "$runs" "$png"
data=$(mktemp -d)
trap 'rm -rf "$data"' EXIT

for model in mohr_coulomb drucker_prager; do
  out=$runs/${model}_biaxial
  rm -rf "$out"
  echo "plot_soil_element_tests: running ${model}_biaxial" >&2
  "$bin" run "$root/configs/materials/${model}_biaxial.toml" --threads 1 --quiet --output "$out" --set output.every=20
  python3 - "$out/timeseries.csv" >"$data/$model.dat" <<'EOF'
import csv, sys
for r in csv.DictReader(open(sys.argv[1])):
    print(-100 * float(r["block.strain_yy"]), -1e-3 * float(r["block.stress_yy"]), -1e-3 * float(r["block.stress_zz"]))
EOF
done
strength=$(python3 -c "
import math
s = math.sin(math.radians(30.0)); N = (1 + s) / (1 - s)
print(100 * N + 2 * 10 * math.sqrt(N))")

gnuplot <<EOF
set terminal pngcairo size 900,500 font ",11" noenhanced
set output "$png/soil_biaxial.png"
set xlabel "mean axial strain -eps_yy (%)"
set ylabel "mean stress (kPa, compression positive)"
set title "Plane-strain biaxial compression, sigma_3 = 100 kPa, phi = 30 deg, c = 10 kPa, psi = 10 deg"
set key center right
set xrange [0:3.2]
set yrange [0:380]
plot $strength w l lc rgb "black" dt 2 t sprintf("sigma_3 N_phi + 2 c sqrt(N_phi) = %.2f kPa", $strength), \
     "$data/mohr_coulomb.dat" u 1:2 w l lw 2 lc rgb "#1f77b4" t "mohr_coulomb: sigma_1", \
     "" u 1:3 w l lc rgb "#1f77b4" dt 3 t "mohr_coulomb: sigma_zz", \
     "$data/drucker_prager.dat" u 1:2 w l lw 2 lc rgb "#d62728" t "drucker_prager, plane-strain fit: sigma_1", \
     "" u 1:3 w l lc rgb "#d62728" dt 3 t "drucker_prager: sigma_zz"
EOF
echo "plot_soil_element_tests: wrote $png/soil_biaxial.png" >&2
