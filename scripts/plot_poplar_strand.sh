#!/bin/bash
# Draws the warping of the wetted poplar strand
# (configs/verification/poplar_strand_wetting_2d.toml) from its results:
#   scripts/plot_poplar_strand.sh RESULTS_DIR [PNG]
# Left: the curvature of the middle half of the strand (a least-squares
# parabola through each row of particles, as verification/swelling_bending.hpp
# measures it) at every output step, against beam theory from the moisture
# profile. Right: the cross-section at the output step nearest the peak,
# displacements magnified 20 times, coloured by the moisture content gained.
# Needs Debian's python3 with h5py and numpy, and gnuplot (scripts/setup.sh).
set -euo pipefail
dir=${1:?usage: plot_poplar_strand.sh RESULTS_DIR [PNG]}
png=${2:-$dir/poplar_strand.png}
data=$(mktemp -d)
trap 'rm -rf "$data"' EXIT
/usr/bin/python3 - "$dir/results.h5" "$data" <<'PY'
import sys
import h5py
import numpy as np

# The case's parameters (poplar_strand_wetting_2d.toml).
D, H, width, beta_x, beta_z, nu_zx = 3.2e-4, 0.0008, 0.008, 0.30, 0.005, 0.39
ramp = [(k * 3.5e-5, 0.04 * (3 * (k / 10) ** 2 - 2 * (k / 10) ** 3)) for k in range(11)]


def concentration(X, t):  # the slab series of a slab 2 H thick with the ramp superposed
    n = np.arange(1, 4002, 2)
    k = n * np.pi / (2 * H)
    lam = D * k * k
    u = 0.0
    for (a, ua), (b, ub) in zip(ramp, ramp[1:]):
        b = min(b, t)
        if b <= a:
            continue
        slope = (ub - ua) / (ramp[1][0] - ramp[0][0])
        u += slope * ((b - a) - np.sum(4 / (n * np.pi) * np.sin(k * X) * (np.exp(-lam * (t - b)) - np.exp(-lam * (t - a))) / lam))
    return u


def beam_curvature(t):
    y = np.linspace(0.0, H, 201)
    eps = (beta_x + nu_zx * beta_z) * np.array([concentration(v + H, t) for v in y])
    return 12 / H**3 * np.trapz(eps * (y - H / 2), y)


f = h5py.File(sys.argv[1], "r")
out = sys.argv[2]
steps = sorted(f["steps"])
rows = []
for name in steps:
    g = f["steps"][name]
    t = g.attrs["time"]
    x, u = g["position"][:], g["displacement"][:]
    x0 = x - u
    mid = np.abs(x0[:, 0] - width / 2) <= width / 4
    kappas = []
    for y in np.unique(np.round(x0[mid, 1], 12)):
        sel = mid & (np.abs(x0[:, 1] - y) < 1e-12)
        q = np.polyfit(x0[sel, 0] - width / 2, u[sel, 1], 2)[0]
        kappas.append(-2 * q)
    rows.append((t, np.mean(kappas), beam_curvature(t)))
np.savetxt(out + "/curvature.dat", [(t * 1e3, k, b) for t, k, b in rows])
peak = max(range(len(rows)), key=lambda i: rows[i][2])
g = f["steps"][steps[peak]]
x, u, c = g["position"][:], g["displacement"][:], g["concentration"][:]
shape = (x - u) + 20 * u
np.savetxt(out + "/shape.dat", np.column_stack([shape[:, 0] * 1e3, shape[:, 1] * 1e3, c * 100]))
open(out + "/peak.txt", "w").write("%.2f" % (rows[peak][0] * 1e3))
PY
peak=$(cat "$data/peak.txt")
gnuplot <<GP
set terminal pngcairo size 1400,500 font ",11"
set output "$png"
set multiplot layout 1,2
set title "Hybrid poplar strand wetted on its top face: curvature"
set xlabel "time of the run (ms; x 3200 s of the strand's time)"
set ylabel "curvature (1/m)"
set key top right
plot "$data/curvature.dat" using 1:3 with lines lw 2 title "beam theory from the moisture profile", \
     "" using 1:2 with points pt 7 ps 0.8 title "flowmpm (middle half, parabola per row)"
set title sprintf("cross-section at t = %s ms, displacement x 20", "$peak")
set xlabel "x (mm)"
set ylabel "y (mm)"
set size ratio -1
set cblabel "moisture gained (% of dry mass)"
set palette defined (0 "#2c7bb6", 1 "#ffffbf", 2 "#d7191c")
unset key
plot "$data/shape.dat" using 1:2:3 with points pt 7 ps 0.6 palette
unset multiplot
GP
echo "$png"
