#!/bin/bash
# Runs the axisymmetric validation cases (configs/axisymmetric/,
# docs/validation/axisymmetric.md) and draws a figure for each:
#   scripts/plot_axisymmetric.sh FLOWMPM RUNS_DIR [PNG_DIR]
# FLOWMPM is the engine binary (e.g. build/flowmpm), RUNS_DIR where the runs
# go (one folder per run; a run whose summary.json says "completed" is not
# run again, so delete RUNS_DIR to start afresh), PNG_DIR where the figures
# go (default: the repository's docs/). THREADS (default 1) sets the
# engine's worker threads. The runs take about 10 s on one thread, most of
# it the 3D Taylor bar (configs/benchmarks/taylor_bar.toml).
#
# Figures (1100 x 450 px, two panels):
#   axisymmetric_heated_cylinder.png  the heated cylinder: mean stresses
#                  over time, free and held on r = b (free along z),
#                  against the quasi-static closed form of the ramp
#   axisymmetric_conduction.png  radial conduction: T(r) at four times
#                  (16 cells over the radius) against the Bessel series,
#                  and the error against the cell size (8 to 64 cells)
#   axisymmetric_strand.png  the poplar strand: the free strand's mean
#                  strains over time against beta c(t); the hoop-wound
#                  strand's stresses across the radius (16 cells) against
#                  the cylindrically anisotropic closed form
#   axisymmetric_taylor_bar.png  (650 x 800 px) the Taylor bar's final
#                  shape: the axisymmetric section's particles over the 3D
#                  quarter bar's (r = sqrt(x^2 + z^2))
# It also prints the numbers quoted in docs/validation/axisymmetric.md.
# Needs Debian's python3 with h5py and numpy, and gnuplot (scripts/setup.sh).
set -euo pipefail
# shellcheck source=scripts/plot_runs.sh
source "$(dirname "$0")/plot_runs.sh"

run heated_free "$configs/axisymmetric/heated_cylinder.toml" --set output.every=200
run heated_held "$configs/axisymmetric/heated_cylinder_held.toml" --set output.every=20
for n in 8 16 32 64; do
  h=$(python3 -c "print(0.1 / $n)")
  dt=$(python3 -c "print(0.2 * (0.1 / $n) ** 2 / 1e-3)")
  run conduction_$n "$configs/axisymmetric/cylinder_conduction.toml" --set grid.cell_size=$h \
    --set "grid.cells=[$n, $((n / 8))]" --set analysis.dt=$dt --set output.every=$((3 * n * n / 32))
done
run strand_free "$configs/axisymmetric/strand_swelling.toml" --set output.every=40
run strand_hoop_16 "$configs/axisymmetric/strand_swelling_hoop.toml" --set grid.cell_size=6.25e-5 \
  --set "grid.origin=[-6.25e-5, -6.25e-5]" --set "grid.cells=[19, 4]" --set "bodies[0].max=[1e-3, 1.25e-4]" \
  --set node_sets[1].at=1.25e-4 --set analysis.dt=5e-9
run taylor_axisymmetric "$configs/axisymmetric/taylor_bar.toml" --set output.every=40
run taylor_3d "$configs/benchmarks/taylor_bar.toml" --set output.every=40

/usr/bin/python3 - "$runs" "$data" <<'PY'
import csv
import json
import sys

import h5py
import numpy as np

runs, out = sys.argv[1], sys.argv[2]


def series(name):
    with open(f"{runs}/{name}/timeseries.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def summary(name):
    return json.load(open(f"{runs}/{name}/summary.json"))


def steps(name):
    f = h5py.File(f"{runs}/{name}/results.h5", "r")
    return [f["steps"][s] for s in sorted(f["steps"])]


def ramp(t, top, duration):  # the configs' smoothstep ramps, piecewise linear through 11 points
    knots = np.linspace(0.0, duration, 11)
    return np.interp(t, knots, top * (3 * (knots / duration) ** 2 - 2 * (knots / duration) ** 3))


# (1) The heated cylinder: E = 1 MPa, nu = 0.3, alpha dT = 1e-5 x 100 K,
# free ramped over 10 s, held over 0.5 s.
E, nu = 1e6, 0.3
for name in ("heated_free", "heated_held"):
    s = series(name)
    t = s["time"]
    a = 1e-5 * ramp(t, 100.0, 10.0 if name == "heated_free" else 0.5)
    np.savetxt(out + "/" + name + ".dat", np.column_stack([t, s["cylinder.stress_rr"], s["cylinder.stress_zz"],
                                                          s["cylinder.stress_tt"], -E * a / (1 - nu)]))

# (2) Radial conduction: the Bessel series, J0 and J1 by their integrals.
tau = np.linspace(0.0, np.pi, 2001)


def J(n, x):
    x = np.atleast_1d(x)
    return np.trapz(np.cos(n * tau[None, :] - x[:, None] * np.sin(tau[None, :])), tau, axis=1) / np.pi


zeros = []
for n in range(1, 61):
    x = (n - 0.25) * np.pi
    for _ in range(20):
        x += J(0, x)[0] / J(1, x)[0]
    zeros.append(x)
zeros = np.array(zeros)
weights = 2 / (zeros * J(1, zeros))
b, kappa = 0.1, 1e-3


def T(r, t):
    modes = J(0, np.outer(r / b, zeros).ravel()).reshape(len(r), len(zeros))
    return 400 - 100 * modes @ (weights * np.exp(-zeros**2 * kappa * t / b**2))


r = np.linspace(0.0, b, 101)
with open(out + "/conduction_exact.dat", "w") as f, open(out + "/conduction_particles.dat", "w") as g:
    for step in steps("conduction_16")[1:]:
        time = step.attrs["time"]
        if not any(abs(time - v) < 1e-9 for v in (0.375, 0.75, 1.5, 3.0)):
            continue
        np.savetxt(f, np.column_stack([r * 1e3, T(r, time)]))
        f.write("\n\n")
        x = step["position"][:]
        np.savetxt(g, np.column_stack([x[:, 0] * 1e3, step["temperature"][:]]))
        g.write("\n\n")
errors = [(0.1 / n * 1e3, summary(f"conduction_{n}")["errors"]["temperature"]) for n in (8, 16, 32, 64)]
np.savetxt(out + "/conduction_errors.dat", errors)
print("conduction: errors at 8, 16, 32, 64 cells", ["%.4g" % e for _, e in errors],
      "rates", ["%.3f" % np.log2(errors[i][1] / errors[i + 1][1]) for i in range(3)])

# (3) The strand: free (beta_T c, beta_L c) over time; the hoop-wound strand's stresses.
s = series("strand_free")
c = ramp(s["time"], 0.04, 2e-5)
np.savetxt(out + "/strand_free.dat", np.column_stack([s["time"] * 1e6, s["strand.strain_rr"] * 1e3,
                                                      s["strand.strain_tt"] * 1e3, s["strand.strain_zz"] * 1e3,
                                                      0.215 * c * 1e3, 0.005 * c * 1e3]))
EA, ET, nuAT, nuT, bL, bT = 9936e6, 670e6, 0.35, 0.70, 0.005, 0.215
S = np.array([[1 / ET, -nuT / ET, -nuAT / EA], [-nuT / ET, 1 / ET, -nuAT / EA], [-nuAT / EA, -nuAT / EA, 1 / EA]])
C = np.linalg.inv(S)
th = np.array([bT, bT, bL]) * 0.004
k = np.sqrt(C[2, 2] / C[0, 0])
D = (C[0] - C[2]) @ th / (C[0, 0] - C[2, 2])
A = -(C[0] @ (np.array([D, 0, D]) - th)) / (1e-3 ** (k - 1) * (C[0, 0] * k + C[0, 2]))
rr = np.linspace(0.0, 1e-3, 101)
q = A * rr ** (k - 1)
exact = C @ (np.vstack([q * k + D, 0 * rr, q + D]) - th[:, None])
np.savetxt(out + "/hoop_exact.dat", np.column_stack([rr * 1e3, exact.T / 1e6]))
last = steps("strand_hoop_16")[-1]
x0 = last["position"][:] - last["displacement"][:]
np.savetxt(out + "/hoop_particles.dat", np.column_stack([x0[:, 0] * 1e3, last["stress"][:, :3] / 1e6]))
print("hoop-wound strand: k = %.4f, sigma_tt from %.4g MPa (axis) to %.4g MPa (r = b)" % (k, exact[2, 0] / 1e6,
                                                                                         exact[2, -1] / 1e6))

# (4) The Taylor bar: final shapes and the measures over time.
a = steps("taylor_axisymmetric")[-1]
np.savetxt(out + "/taylor_axisymmetric.dat", a["position"][:, :2] * 1e3)
q = steps("taylor_3d")[-1]["position"][:]
np.savetxt(out + "/taylor_3d.dat", np.column_stack([np.hypot(q[:, 0], q[:, 2]) * 1e3, q[:, 1] * 1e3]))
for name in ("taylor_axisymmetric", "taylor_3d"):
    m = summary(name)
    print("%s: final length %.6g mm, foot radius %.6g mm, plastic work %.5g, energy %.4g, step loop %.3g s, "
          "%d particles" % (name, m["measures"]["final_length"] * 1e3, m["measures"]["foot_radius"] * 1e3,
                            m["measures"]["plastic_work"], m["errors"]["energy"], m["step_loop_seconds"],
                            m["particles"]))
PY

gnuplot <<GP
set terminal pngcairo size 1100,450 font ",10" noenhanced
set output "$png/axisymmetric_heated_cylinder.png"
set multiplot layout 1,2
set title "Heated cylinder, free: mean stress"
set xlabel "time (s)"
set ylabel "stress (Pa)"
set key bottom right
plot "$data/heated_free.dat" using 1:2 with lines lw 2 title "sigma_rr", \
     "" using 1:3 with lines lw 2 title "sigma_zz", \
     "" using 1:4 with lines lw 2 dt 2 title "sigma_tt", \
     0 with lines lc "black" title "closed form: 0"
set title "Held on r = b, free along z: mean stress"
set key bottom left
plot "$data/heated_held.dat" using 1:2 with lines lw 2 title "sigma_rr", \
     "" using 1:3 with lines lw 2 title "sigma_zz", \
     "" using 1:4 with lines lw 2 dt 2 title "sigma_tt", \
     "" using 1:5 with lines lc "black" dt 3 title "-E alpha dT(t) / (1 - nu)"
unset multiplot

set output "$png/axisymmetric_conduction.png"
set multiplot layout 1,2
set title "Radial conduction, 16 cells over the radius"
set xlabel "r (mm)"
set ylabel "T (K)"
set key bottom right
plot for [i=0:3] "$data/conduction_exact.dat" index i using 1:2 with lines lc i+1 lw 2 \
       title sprintf("Bessel series, t = %s s", word("0.375 0.75 1.5 3", i+1)), \
     for [i=0:3] "$data/conduction_particles.dat" index i using 1:2 with points pt 7 ps 0.5 lc i+1 notitle
set title "RMS error (16 samples) against the cell size"
set xlabel "h (mm)"
set ylabel "error / 100 K"
set logscale xy
set key bottom right
plot "$data/conduction_errors.dat" using 1:2 with linespoints pt 7 lw 2 title "flowmpm, dt = 0.2 h^2 / kappa", \
     "" using 1:(\$2 * 0 + 1.534e-3 * (\$1 / 6.25)**2) with lines dt 2 lc "black" title "slope 2"
unset logscale
unset multiplot

set output "$png/axisymmetric_strand.png"
set multiplot layout 1,2
set title "Poplar strand, grain along z, free: mean strain"
set xlabel "time (us)"
set ylabel "strain (x 1e-3)"
set key top left
plot "$data/strand_free.dat" using 1:2 with lines lw 2 title "eps_rr", \
     "" using 1:3 with lines lw 2 dt 2 title "eps_tt", \
     "" using 1:4 with lines lw 2 title "eps_zz", \
     "" using 1:5 with lines lc "black" dt 3 title "beta_T c(t)", \
     "" using 1:6 with lines lc "black" dt 4 title "beta_L c(t)"
set title "Grain along theta, held along z, c = 0.004: stress, 16 cells"
set xlabel "r (mm)"
set ylabel "stress (MPa)"
set key top left
plot "$data/hoop_exact.dat" using 1:2 with lines lw 2 lc 1 title "sigma_rr", \
     "" using 1:3 with lines lw 2 lc 2 title "sigma_zz", \
     "" using 1:4 with lines lw 2 lc 3 title "sigma_tt (closed form: lines)", \
     "$data/hoop_particles.dat" using 1:2 with points pt 7 ps 0.5 lc 1 notitle, \
     "" using 1:3 with points pt 7 ps 0.5 lc 2 notitle, \
     "" using 1:4 with points pt 7 ps 0.5 lc 3 notitle
unset multiplot

set terminal pngcairo size 650,800 font ",10" noenhanced
set output "$png/axisymmetric_taylor_bar.png"
set title "Taylor bar at 80 us, 0.8 mm cells: (r, z) of every particle"
set xlabel "r (mm)"
set ylabel "z (mm)"
set size ratio -1
set xrange [0:14]
set yrange [0:25]
set key top right
plot "$data/taylor_3d.dat" using 1:2 with points pt 7 ps 0.4 lc rgb "#b0b0b0" title "3D quarter bar, r = sqrt(x^2 + z^2)", \
     "$data/taylor_axisymmetric.dat" using 1:2 with points pt 7 ps 0.5 lc rgb "#c03030" title "axisymmetric"
GP
echo "plot_axisymmetric: figures in $png" >&2
