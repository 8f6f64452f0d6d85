#!/bin/bash
# Runs the soil scenes of configs/soils/ (docs/validation/soil_scenes.md)
# and draws their figures:
#   scripts/plot_soil_scenes.sh FLOWMPM RUNS_DIR [PNG_DIR]
# FLOWMPM is the engine binary (e.g. build/flowmpm), RUNS_DIR where the runs
# go (one folder per run, made afresh), PNG_DIR where the figures go
# (default: the repository's docs/). The runs take about 8 minutes on 2
# cores, most of it the footing at 10 mm cells and the tall column on
# cells of L0 / 40.
#
# Figures (900 x 500 px):
#   soil_footing.png  the footing's pressure against its travel at 40, 20
#                     and 10 mm cells, against Prandtl's c N_c
#   soil_slope.png    the infinite slope's displacement along the slope
#                     against the height above the base, in the middle of
#                     the layer, at beta = 25 and 35 degrees after 0.5 s
#   soil_column.png   the granular columns' deposits (the top of the
#                     particles along x) at a = 0.5, 1 and 2 on cells of
#                     L0 / 20 and L0 / 40, with Lube et al.'s run-out
# Needs gnuplot (scripts/setup.sh --tests installs it) and python3-h5py.
set -euo pipefail
bin=${1:?usage: plot_soil_scenes.sh FLOWMPM RUNS_DIR [PNG_DIR]}
runs=${2:?usage: plot_soil_scenes.sh FLOWMPM RUNS_DIR [PNG_DIR]}
root=$(cd "$(dirname "$0")/.." && pwd)
png=${3:-$root/docs}
mkdir -p "$runs" "$png"
data=$(mktemp -d)
trap 'rm -rf "$data"' EXIT
python=/usr/bin/python3  # Debian's, with numpy and h5py

for size in "0.04 [54,20]" "0.02 [108,40]" "0.01 [216,80]"; do
  set -- $size
  out=$runs/footing_$1
  rm -rf "$out"
  echo "plot_soil_scenes: running the footing at $1 m cells" >&2
  "$bin" run "$root/configs/soils/strip_footing_mohr_coulomb.toml" --quiet --output "$out" \
    --set grid.cell_size=$1 --set "grid.cells=$2" --set output.every=20
  # Travel: the footing's speed ramps to 0.05 m/s over 0.02 s.
  "$python" - "$out/timeseries.csv" >"$data/footing_$1.dat" <<'PY'
import csv, sys
for r in csv.DictReader(open(sys.argv[1])):
    t = float(r["time"])
    travel = 0.05 * t * t / 0.04 if t < 0.02 else 0.05 * (t - 0.01)
    print(1000 * travel, 1e-3 * float(r["reaction.footing.y"]) / 0.2)
PY
done
limit=$("$python" -c "
import math
phi = math.radians(20.0); t = math.tan(math.pi / 4 + phi / 2)
print(10.0 * (math.exp(math.pi * math.tan(phi)) * t * t - 1) / math.tan(phi))")

for beta in 25 35; do
  out=$runs/slope_$beta
  rm -rf "$out"
  echo "plot_soil_scenes: running the infinite slope at beta = $beta degrees" >&2
  g=$("$python" -c "import math; b = math.radians($beta); print(f'[{9.81 * math.sin(b):.4f}, {-9.81 * math.cos(b):.4f}]')")
  "$bin" run "$root/configs/soils/infinite_slope.toml" --quiet --output "$out" --set "analysis.gravity=$g"
  PYTHONPATH="$root/python" "$python" - "$out" >"$data/slope_$beta.dat" <<'PY'
import sys
import flowmpm
with flowmpm.Results(sys.argv[1]) as r:
    x0, u = r.field("position", 0), r.field("displacement", -1)
middle = (x0[:, 0] > 2.5) & (x0[:, 0] < 7.5)
for y, ux in sorted(zip(x0[middle, 1], u[middle, 0])):
    print(y, 1000 * ux)
PY
done

for a in 0.5 1 2; do
  height=$("$python" -c "print(0.1 * $a)")
  for size in "0.005 [208,58] 5e-5" "0.0025 [416,116] 2.5e-5"; do
    set -- $size
    out=$runs/column_${a}_$1
    rm -rf "$out"
    echo "plot_soil_scenes: running the column a = $a on $1 m cells" >&2
    "$bin" run "$root/configs/soils/column_collapse.toml" --quiet --output "$out" --set grid.cell_size=$1 \
      --set "grid.cells=$2" --set analysis.dt=$3 --set "bodies[0].max=[0.1, $height]" --set reference.height=$height
    # The deposit's surface: the highest particle top in each column of 2.5 mm.
    PYTHONPATH="$root/python" "$python" - "$out" $1 >"$data/column_${a}_$1.dat" <<'PY'
import sys
import numpy as np
import flowmpm
with flowmpm.Results(sys.argv[1]) as r:
    x = r.field("position", -1)
half = 0.25 * float(sys.argv[2])  # half a particle (2 x 2 per cell)
bins = np.floor((x[:, 0] + half) / 0.0025).astype(int)
for b in range(bins.max() + 1):
    inside = bins == b
    if inside.any():
        print(1000 * 0.0025 * (b + 1), 1000 * (x[inside, 1].max() + half))
PY
  done
done

gnuplot <<GP
set terminal pngcairo size 900,500 font ",11" noenhanced
set output "$png/soil_footing.png"
set xlabel "travel (mm)"
set ylabel "pressure under the footing (kPa)"
set title "Smooth strip footing, B = 0.2 m, phi = 20 deg, c = 10 kPa, associated Mohr-Coulomb"
set key bottom right
set xrange [0:18.5]
set yrange [0:230]
plot $limit w l lc rgb "black" dt 2 t sprintf("c N_c = %.1f kPa", $limit), \
     "$data/footing_0.04.dat" u 1:2 w l lw 2 lc rgb "#2ca02c" t "40 mm cells", \
     "$data/footing_0.02.dat" u 1:2 w l lw 2 lc rgb "#1f77b4" t "20 mm cells", \
     "$data/footing_0.01.dat" u 1:2 w l lw 2 lc rgb "#d62728" t "10 mm cells"
set output "$png/soil_slope.png"
set xlabel "displacement along the slope after 0.5 s (mm)"
set ylabel "height above the base (m)"
set title "Infinite slope, phi = 30 deg, H = 0.5 m: the middle half of the layer's particles"
set key top center
set autoscale
set logscale x
set xrange [1e-4:1000]
set yrange [0:0.5]
plot "$data/slope_25.dat" u (abs(\$2)):1 w p pt 7 ps 0.4 lc rgb "#1f77b4" t "beta = 25 deg (stands)", \
     "$data/slope_35.dat" u 2:1 w p pt 7 ps 0.4 lc rgb "#d62728" t "beta = 35 deg (flows)"
set output "$png/soil_column.png"
unset logscale x
set xlabel "distance from the wall (mm)"
set ylabel "height (mm)"
set title "Granular columns, L0 = 100 mm, phi = 30 deg: deposits; arrows: Lube et al. (2005) run-out 1.2 a L0 + L0"
set key top right
set xrange [0:700]
set yrange [0:210]
set arrow from 160,40 to 160,0 lc rgb "#2ca02c"
set arrow from 220,40 to 220,0 lc rgb "#1f77b4"
set arrow from 340,40 to 340,0 lc rgb "#d62728"
plot "$data/column_0.5_0.005.dat" u 1:2 w l lw 2 lc rgb "#2ca02c" t "a = 0.5, L0 / 20", \
     "$data/column_0.5_0.0025.dat" u 1:2 w l lw 2 dt 2 lc rgb "#2ca02c" t "a = 0.5, L0 / 40", \
     "$data/column_1_0.005.dat" u 1:2 w l lw 2 lc rgb "#1f77b4" t "a = 1, L0 / 20", \
     "$data/column_1_0.0025.dat" u 1:2 w l lw 2 dt 2 lc rgb "#1f77b4" t "a = 1, L0 / 40", \
     "$data/column_2_0.005.dat" u 1:2 w l lw 2 lc rgb "#d62728" t "a = 2, L0 / 20", \
     "$data/column_2_0.0025.dat" u 1:2 w l lw 2 dt 2 lc rgb "#d62728" t "a = 2, L0 / 40"
GP
echo "plot_soil_scenes: wrote $png/soil_footing.png, $png/soil_slope.png and $png/soil_column.png" >&2
