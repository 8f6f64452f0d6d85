#!/bin/bash
# Runs the contact validation cases (configs/contact/, docs/validation/contact.md)
# and draws a figure for each:
#   scripts/plot_contact.sh FLOWMPM RUNS_DIR [PNG_DIR]
# FLOWMPM is the engine binary (e.g. build/flowmpm), RUNS_DIR where the runs
# go (one folder per run; a run whose summary.json says "completed" is not
# run again, so delete RUNS_DIR to start afresh), PNG_DIR where the figures
# go (default: the repository's docs/). THREADS (default 1) sets the
# engine's worker threads. The runs take about 2 minutes on one thread
# (most of it the punch at 10 mm cells) and 0.3 GB of disk (the Sulsky run
# writes every step, the 10 mm punch 120 steps of 29k particles).
#
# Figures (900 x 500 px, or 1100 x 450 px with two panels):
#   contact_incline.png     block on the rigid 30 degree plane, mu = 0, 0.2,
#                           0.5, 0.7: centre of mass (mass-weighted) moved
#                           along the slope against g (sin 30 - mu cos 30) t^2 / 2,
#                           and mu = 0.2 on a deformable slab and on a wall
#   contact_disk.png        disk on the plane, mu = 0.1 and 0.3: centre moved
#                           against rolling (g sin 30 t^2 / 3) and sliding
#   contact_punch.png       rigid punch in a von Mises block: reaction.punch.y
#                           (N/m, 2D) over B = 0.2 m against the punch's
#                           travel, cells of 40, 20 and 10 mm, and Prandtl's
#                           (2 + pi) sigma_Y / sqrt(3)
#   contact_sulsky_disks.png  Sulsky's disks, frictionless contact: the pair's
#                           normal force (with the 2D Hertz estimate) and the
#                           kinetic energy beside the one-field run
#                           (configs/benchmarks/sulsky_disks.toml)
#   contact_bars.png        two elastic bars meeting end on: the pair's
#                           normal force against the exact 10 N/m from 0.5 to
#                           0.9 s, and the kinetic energy, at 4, 16 and 32
#                           cells per bar
#   contact_lap_shear.png   two strands bonded by an interface: load against
#                           the pulled end's displacement, against Volkersen's
#   contact_drop_3d.png     3D block on a rigid floor: centre height (and on a
#                           wall) and the energy balance's terms
#   contact_drop_2d.png     2D block on a rigid floor at 30 mm cells with the
#                           floor's surface 0, 1/4, 1/2 and 3/4 of a cell
#                           above a node plane: centre height, and near the
#                           impact against long-wave theory's lowest centre
# It also prints the Sulsky contact's measured duration and the Hertz
# estimate (the numbers quoted in docs/validation/contact.md).
# Needs Debian's python3 with h5py and numpy, and gnuplot (scripts/setup.sh).
set -euo pipefail
# shellcheck source=scripts/plot_runs.sh
source "$(dirname "$0")/plot_runs.sh"

fields='output.fields=["mass","material"]'
for mu in 0 0.2 0.5 0.7; do
  run incline_mu$mu "$configs/contact/incline_block_rigid.toml" --set "contacts[0].friction=$mu" \
    --set output.every=200 --set "$fields"
done
# mu = 0.2 on a deformable slab and on a wall (a node plane that only pushes).
run incline_slab_mu0.2 "$configs/contact/incline_block_slab.toml" --set output.every=200 --set "$fields"
run incline_wall_mu0.2 "$configs/contact/incline_block_wall.toml" --set output.every=200 --set "$fields"
for mu in 0.1 0.3; do
  run disk_mu$mu "$configs/contact/incline_disk_rigid.toml" --set "contacts[0].friction=$mu" \
    --set output.every=200 --set "$fields"
done
# About 120 output steps at each resolution (dt follows the cell).
run punch_40mm "$configs/contact/punch_von_mises.toml" --set grid.cell_size=0.04 --set "grid.cells=[34, 20]" \
  --set output.every=20 --set 'output.fields=["material"]'
run punch_20mm "$configs/contact/punch_von_mises.toml" \
  --set output.every=40 --set 'output.fields=["material"]'
run punch_10mm "$configs/contact/punch_von_mises.toml" --set grid.cell_size=0.01 --set "grid.cells=[136, 80]" \
  --set output.every=80 --set 'output.fields=["material"]'
# Every step: the contact's duration is counted in steps.
run sulsky_contact "$configs/contact/sulsky_disks_frictionless.toml" --set output.every=1 --set "$fields"
run sulsky_one_field "$configs/benchmarks/sulsky_disks.toml" --set output.every=10 --set "$fields"
# The bars at 4, 16 (the case file) and 32 cells per bar, dt = 0.02 h / c.
bars="$configs/contact/bars_impact_frictionless.toml"
run bars_4 "$bars" --set grid.cell_size=0.05 --set "grid.cells=[26, 4]" --set analysis.dt=1e-3 \
  --set output.every=1 --set "$fields"
run bars_16 "$bars" --set output.every=4 --set "$fields"
run bars_32 "$bars" --set grid.cell_size=0.00625 --set "grid.cells=[208, 32]" --set analysis.dt=1.25e-4 \
  --set output.every=8 --set "$fields"
run drop_3d "$configs/contact/drop_3d_rigid_floor.toml" --set output.every=10 --set "$fields"
run drop_3d_wall "$configs/contact/drop_3d_wall.toml" --set output.every=10 --set "$fields"
# The 2D drop at 30 mm cells, the floor's surface at four offsets in a cell.
for offset in 0 0.25 0.5 0.75; do
  run "drop_2d_$offset" "$configs/contact/drop_rigid_floor.toml" --set "grid.cells=[30, 29]" \
    --set "grid.origin=[-0.21, $(awk "BEGIN { print -0.24 - $offset * 0.03 }")]" --set output.every=2 --set "$fields"
done
run lap_shear_0.5mm "$configs/contact/lap_shear_interface.toml" --set grid.cell_size=0.0005 --set "grid.cells=[62, 6]" \
  --set output.every=10 --set "$fields"
run lap_shear_0.25mm "$configs/contact/lap_shear_interface.toml" --set output.every=20 --set "$fields"

/usr/bin/python3 - "$runs" "$data" <<'PY'
import csv
import sys

import h5py
import numpy as np

runs, out = sys.argv[1], sys.argv[2]


def series(name):
    with open(f"{runs}/{name}/timeseries.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def centres(name, select):
    """time and the mass-weighted centre of the particles select(material) picks, per output step"""
    f = h5py.File(f"{runs}/{name}/results.h5", "r")
    t, c = [], []
    for s in sorted(f["steps"]):
        g = f["steps"][s]
        sel = select(g["material"][:])
        x = g["position"][:][sel]
        w = g["mass"][:][sel] if "mass" in g else np.ones(len(x))
        t.append(g.attrs["time"])
        c.append((w[:, None] * x).sum(0) / w.sum())
    return np.array(t), np.array(c)


deformable = lambda m: m >= 0   # rigid bodies' particles have material -1
rigid = lambda m: m < 0

# (a), (b): the centre's motion along the slope (the plane is the x axis).
for name in ["incline_mu0", "incline_mu0.2", "incline_mu0.5", "incline_mu0.7", "disk_mu0.1", "disk_mu0.3"]:
    t, c = centres(name, deformable)
    np.savetxt(f"{out}/{name}.dat", np.column_stack([t, c[:, 0] - c[0, 0]]))
# On the slab both bodies are deformable: the block's particles start above y = 0.
for name in ["incline_slab_mu0.2", "incline_wall_mu0.2"]:
    f = h5py.File(f"{runs}/{name}/results.h5", "r")
    steps = sorted(f["steps"])
    block = f["steps"][steps[0]]["position"][:, 1] > 0
    t, c = centres(name, lambda m: block)
    np.savetxt(f"{out}/{name}.dat", np.column_stack([t, c[:, 0] - c[0, 0]]))

# (c): punch pressure (reaction over B = 0.2 m: N/m / m = Pa) against its travel.
for cell in ["40mm", "20mm", "10mm"]:
    name = "punch_" + cell
    ts = series(name)
    t, c = centres(name, rigid)
    assert np.allclose(t, ts["time"])
    np.savetxt(f"{out}/{name}.dat", np.column_stack([-(c[:, 1] - c[0, 1]) * 1e3, ts["reaction.punch.y"] / 0.2 / 1e3]))

# (d): Sulsky's disks.
R, E, nu, rho, v = 0.2, 1000.0, 0.3, 1000.0, 0.1     # sulsky_disks_frictionless.toml
ts = series("sulsky_contact")
normal = ts["contact.lower_left~upper_right.normal"]
on = np.nonzero(normal > 0)[0]
dt = ts["time"][1] - ts["time"][0]
np.savetxt(f"{out}/sulsky_contact.dat", np.column_stack(
    [ts["time"], normal, ts["kinetic_energy"], ts["kinetic_energy"] + ts["stored_energy"]]))
one = series("sulsky_one_field")
np.savetxt(f"{out}/sulsky_one_field.dat", np.column_stack(
    [one["time"], one["kinetic_energy"], one["kinetic_energy"] + one["stored_energy"]]))
# The disks' centres (particles by id: the lower-left disk's first).
f = h5py.File(f"{runs}/sulsky_contact/results.h5", "r")
steps = sorted(f["steps"])
x0 = f["steps"][steps[0]]["position"][:]
lower = x0[:, 0] + x0[:, 1] < 1.0
gap = []
for s in steps:
    x = f["steps"][s]["position"][:]
    gap.append((f["steps"][s].attrs["time"], np.linalg.norm(x[~lower].mean(0) - x[lower].mean(0))))
gap = np.array(gap)
closer = gap[gap[:, 1] < 2 * R, 0]

# The 2D Hertz estimate: two equal plane-strain cylinders, force P per unit
# length, half-width of contact b = sqrt(4 P R* / (pi E*)), approach of the
# axes delta = 2 P (1 - nu^2) / (pi E) (2 ln(4 R / b) - 1) (docs/validation/contact.md).
# Reduced mass m / 2, closing speed V along the line of centres; m* delta'' = -P(delta).
Es, Rs = E / (2 * (1 - nu**2)), R / 2
ms, V = rho * np.pi * R**2 / 2, 2 * v * np.sqrt(2)
P = np.concatenate([[0.0], np.logspace(-10, np.log10(300.0), 200001)])  # delta(P) rises up to b = 4 R / e (P = 373 N/m)
delta = np.zeros_like(P)
b = np.sqrt(4 * P[1:] * Rs / (np.pi * Es))
delta[1:] = 2 * P[1:] * (1 - nu**2) / (np.pi * E) * (2 * np.log(4 * R / b) - 1)
assert np.all(np.diff(delta) > 0)
h, d, u, t, hist = 1e-4, 0.0, V, 0.0, [(0.0, 0.0)]
while True:   # semi-implicit Euler
    u -= np.interp(d, delta, P) / ms * h
    d += u * h
    t += h
    hist.append((t, np.interp(max(d, 0.0), delta, P)))
    if d <= 0:
        break
hist = np.array(hist)
T_hertz, P_hertz = hist[-1, 0], hist[:, 1].max()
touch = (np.sqrt(2) * 0.6 - 2 * R) / V      # the disks' surfaces meet (centres 2 R apart)
np.savetxt(f"{out}/hertz.dat", np.column_stack([hist[:, 0] + touch, hist[:, 1]])[::50])
report = (
    f"Sulsky's disks: normal force > 0 in {len(on)} steps, steps {int(ts['step'][on[0]])} to {int(ts['step'][on[-1]])} "
    f"(t = {ts['time'][on[0]]:.3f} to {ts['time'][on[-1]]:.3f} s: {len(on) * dt:.3f} s), "
    f"{'contiguous' if on[-1] - on[0] + 1 == len(on) else 'NOT contiguous'}, largest {normal.max():.1f} N/m, "
    f"impulse {normal.sum() * dt:.2f} N s/m\n"
    f"  centres closer than 2 R from t = {closer[0]:.3f} to {closer[-1]:.3f} s ({closer[-1] - closer[0] + dt:.3f} s), "
    f"least distance {gap[:, 1].min():.4f} m\n"
    f"  2D Hertz: surfaces meet at t = {touch:.3f} s, contact for {T_hertz:.3f} s, largest force {P_hertz:.1f} N/m, "
    f"largest approach {np.interp(P_hertz, P, delta):.4f} m, half-width {np.sqrt(4 * P_hertz * Rs / (np.pi * Es)):.3f} m; "
    f"measured / Hertz {len(on) * dt / T_hertz:.3f}")
open(f"{out}/report.txt", "w").write(report + "\n")
open(f"{out}/hertz.txt", "w").write(f"{T_hertz:.3f} {touch:.3f}\n")

# (e): the bars: normal force and kinetic energy (J/m) against time.
for per in ["4", "16", "32"]:
    ts = series(f"bars_{per}")
    np.savetxt(f"{out}/bars_{per}.dat", np.column_stack(
        [ts["time"], ts["contact.left~right.normal"], ts["kinetic_energy"]]))

# (f): the 3D drop.
ts = series("drop_3d")
t, c = centres("drop_3d", deformable)
assert np.allclose(t, ts["time"])
np.savetxt(f"{out}/drop_3d.dat", np.column_stack([t, c[:, 1], ts["kinetic_energy"], ts["stored_energy"],
                                                   ts["gravity_work"], ts["contact_work"], ts["energy_balance_error"]]))
t, c = centres("drop_3d_wall", deformable)
np.savetxt(f"{out}/drop_3d_wall.dat", np.column_stack([t, c[:, 1]]))
# (g): the 2D drop at four offsets.
for offset in ["0", "0.25", "0.5", "0.75"]:
    t, c = centres(f"drop_2d_{offset}", deformable)
    np.savetxt(f"{out}/drop_2d_{offset}.dat", np.column_stack([t, c[:, 1]]))


def ramp_displacement(t):
    """the pulled end's displacement (m): its velocity rises linearly to 0.4 m/s at 25 us and falls to 0 at 50 us"""
    t = np.minimum(t, 5e-5)
    rise = 0.4 / 2.5e-5
    up = 0.5 * rise * np.minimum(t, 2.5e-5) ** 2
    late = np.maximum(t - 2.5e-5, 0.0)
    return up + 0.4 * late - 0.5 * rise * late**2


for cell in ["0.5mm", "0.25mm"]:
    ts = series(f"lap_shear_{cell}")
    np.savetxt(f"{out}/lap_shear_{cell}.dat",
               np.column_stack([ramp_displacement(ts["time"]) * 1e6, ts["reaction.pulled.x"], ts["time"] * 1e6]))
PY
cat "$data/report.txt"
read -r hertz touch <"$data/hertz.txt"

gnuplot <<GP
set terminal pngcairo size 900,500 font ",11" noenhanced
set output "$png/contact_incline.png"
set title "Block on a rigid 30° incline (incline_block_rigid.toml), Coulomb friction μ\\nclosed form: g (sin 30° - μ cos 30°) t²/2, and 0 for μ ≥ tan 30° = 0.577"
set xlabel "time t (s)"
set ylabel "centre of mass moved along the slope (m)"
set key top left
g = 9.81
s(mu, t) = mu < tan(pi / 6) ? g * (sin(pi / 6) - mu * cos(pi / 6)) * t**2 / 2 : 0
set xrange [0:1]
set yrange [-0.05:2.6]
set key maxrows 6 top left
plot for [i = 1:4] (mu = word("0 0.2 0.5 0.7", i) + 0, s(mu, x)) with lines lw 2 lc i dt 1 \
       title sprintf("closed form, μ = %s%s", word("0 0.2 0.5 0.7", i), i == 4 ? " (sticks)" : ""), \
     keyentry with points pt -1 title " ", keyentry with points pt -1 title " ", \
     for [i = 1:4] "$data/incline_mu".word("0 0.2 0.5 0.7", i).".dat" using 1:2 with points pt 7 ps 0.8 lc i \
       title sprintf("flowmpm, μ = %s", word("0 0.2 0.5 0.7", i)), \
     "$data/incline_slab_mu0.2.dat" using 1:2 with points pt 4 ps 1.2 lc 2 title "on a slab, μ = 0.2", \
     "$data/incline_wall_mu0.2.dat" using 1:2 with points pt 8 ps 1.2 lc 2 title "on a wall, μ = 0.2"
set key maxrows auto

set output "$png/contact_disk.png"
set title "Disk (R = 0.1 m) on a rigid 30° incline (incline_disk_rigid.toml)"
set ylabel "centre moved along the slope (m)"
set yrange [0:2.2]
plot g * sin(pi / 6) * x**2 / 3 with lines lw 2 lc 2 title "rolling: g sin 30° t²/3 (μ ≥ tan 30°/3 = 0.192)", \
     s(0.1, x) with lines lw 2 lc 1 title "sliding, μ = 0.1: g (sin 30° - 0.1 cos 30°) t²/2", \
     s(0.3, x) with lines lw 1 lc 2 dt 2 title "sliding at μ = 0.3 (the least it could move)", \
     "$data/disk_mu0.1.dat" using 1:2 with points pt 7 ps 0.8 lc 1 title "flowmpm, μ = 0.1 (slips)", \
     "$data/disk_mu0.3.dat" using 1:2 with points pt 5 ps 0.8 lc 2 title "flowmpm, μ = 0.3 (rolls)"

set output "$png/contact_punch.png"
set title "Rigid flat punch (B = 0.2 m) in a von Mises block, σ_Y = 100 kPa (punch_von_mises.toml)"
set xlabel "punch travel (mm)"
set ylabel "punch pressure: reaction / B (kPa)"
set key bottom right
set xrange [0:19]
set yrange [0:400]
plot (2 + pi) * 100 / sqrt(3) with lines lw 2 lc rgb "black" dt 2 title "Prandtl: (2 + π) σ_Y / √3 = 296.85 kPa", \
     "$data/punch_40mm.dat" using 1:2 with linespoints pt 9 ps 0.6 lc 1 title "cells of 40 mm", \
     "$data/punch_20mm.dat" using 1:2 with linespoints pt 5 ps 0.5 lc 2 title "cells of 20 mm", \
     "$data/punch_10mm.dat" using 1:2 with linespoints pt 7 ps 0.5 lc 3 title "cells of 10 mm"

set terminal pngcairo size 1100,450 font ",10" noenhanced
set output "$png/contact_sulsky_disks.png"
set multiplot layout 1,2 title "Sulsky's disks with frictionless contact (sulsky_disks_frictionless.toml)"
set title "the pair's normal contact force"
set xlabel "time t (s)"
set ylabel "normal force (N/m, per unit thickness)"
set key top right
set xrange [1:3]
set yrange [0:*]
plot "$data/sulsky_contact.dat" using 1:2 with lines lw 1 lc 1 title "flowmpm (every step)", \
     "$data/hertz.dat" using 1:2 with lines lw 2 lc rgb "black" dt 2 title sprintf("2D Hertz estimate: %s s from the touch at %s s", "$hertz", "$touch")
set title "kinetic energy (solid) and kinetic + stored (dashed)"
set ylabel "energy (J/m, per unit thickness)"
set key left center
set xrange [0:3.5]
set yrange [0:*]
plot "$data/sulsky_one_field.dat" using 1:2 with lines lw 2 lc 2 title "one shared field", \
     "" using 1:3 with lines lw 1 lc 2 dt 2 notitle, \
     "$data/sulsky_contact.dat" using 1:3 with lines lw 2 lc 1 title "frictionless contact", \
     "" using 1:4 with lines lw 1 lc 1 dt 2 notitle
unset multiplot

set output "$png/contact_bars.png"
set multiplot layout 1,2 title "Two elastic bars meeting end on, frictionless contact (bars_impact_frictionless.toml)"
set title "the pair's normal contact force"
set xlabel "time t (s)"
set ylabel "normal force (N/m, per unit thickness)"
set key top right
set xrange [0.3:1.1]
set yrange [0:14]
set samples 801
plot "+" using 1:((\$1 < 0.5 || \$1 > 0.9) ? 0 : 10) with lines lw 2 lc rgb "black" dt 2 title "exact: ρ c V h = 10 N/m for 2 L / c", \
     "$data/bars_4.dat" using 1:2 with lines lw 1 lc 1 title "4 cells per bar", \
     "$data/bars_16.dat" using 1:2 with lines lw 1 lc 2 title "16 cells per bar", \
     "$data/bars_32.dat" using 1:2 with lines lw 1 lc 3 title "32 cells per bar"
set title "kinetic energy"
set ylabel "kinetic energy (J/m, per unit thickness)"
set key bottom right
set xrange [0:1.5]
set yrange [0:0.21]
plot 0.2 with lines lw 2 lc rgb "black" dt 2 title "exact after the impact: 0.2 J/m", \
     "$data/bars_4.dat" using 1:3 with lines lw 2 lc 1 title "4 cells per bar", \
     "$data/bars_16.dat" using 1:3 with lines lw 2 lc 2 title "16 cells per bar", \
     "$data/bars_32.dat" using 1:3 with lines lw 2 lc 3 title "32 cells per bar"
unset multiplot

set output "$png/contact_drop_3d.png"
set multiplot layout 1,2 title "3D block (0.3 m cube) dropped on a rigid floor, frictionless (drop_3d_rigid_floor.toml)"
set title "the block's centre of mass"
set xlabel "time t (s)"
set ylabel "centre height y (m)"
set key top right
set xrange [0:0.63]
set yrange [0.1:0.3]
plot "$data/drop_3d.dat" using 1:2 with lines lw 2 lc 1 title "on the rigid floor", \
     "$data/drop_3d_wall.dat" using 1:2 with lines lw 2 lc 3 dt 2 title "on a wall (drop_3d_wall.toml)", \
     0.15 with lines lc rgb "gray" dt 2 title "its base on the floor (0.15 m)"
set title "the energy balance's terms"
set ylabel "energy (J)"
set key top left horizontal maxrows 2 width -2
set yrange [-16:32]
plot "$data/drop_3d.dat" using 1:3 with lines lw 2 lc 1 title "kinetic", \
     "" using 1:4 with lines lw 2 lc 2 title "stored", \
     "" using 1:5 with lines lw 2 lc 3 title "gravity work", \
     "" using 1:6 with lines lw 2 lc 4 title "contact work", \
     "" using 1:7 with lines lw 2 lc rgb "black" dt 2 title "balance error"
unset multiplot

set output "$png/contact_drop_2d.png"
set multiplot layout 1,2 title "2D block (0.3 m square, plane strain) dropped on a rigid floor at 30 mm cells (drop_rigid_floor.toml)"
set title "the block's centre of mass, the floor's surface at four offsets"
set xlabel "time t (s)"
set ylabel "centre height y (m)"
set key top right
set xrange [0:0.3]
set yrange [0.13:0.26]
plot "$data/drop_2d_0.dat" using 1:2 with lines lw 2 lc 1 title "on a node plane", \
     "$data/drop_2d_0.25.dat" using 1:2 with lines lw 2 lc 2 dt 2 title "1/4 of a cell above one", \
     "$data/drop_2d_0.5.dat" using 1:2 with lines lw 2 lc 3 dt 3 title "1/2", \
     "$data/drop_2d_0.75.dat" using 1:2 with lines lw 2 lc 4 dt 4 title "3/4", \
     0.15 with lines lc rgb "gray" dt 2 title "its base on the floor (0.15 m)"
set title "near the impact"
set key bottom left opaque box
set xrange [0.135:0.17]
set yrange [0.137:0.152]
plot "$data/drop_2d_0.dat" using 1:2 with linespoints lw 2 pt 7 ps 0.4 lc 1 title "on a node plane", \
     "$data/drop_2d_0.25.dat" using 1:2 with linespoints lw 2 pt 7 ps 0.4 lc 2 title "1/4", \
     "$data/drop_2d_0.5.dat" using 1:2 with linespoints lw 2 pt 7 ps 0.4 lc 3 title "1/2", \
     "$data/drop_2d_0.75.dat" using 1:2 with linespoints lw 2 pt 7 ps 0.4 lc 4 title "3/4", \
     0.14366 with lines lw 2 lc rgb "black" dt 2 title "long-wave theory: lowest at 0.1437 m"
unset multiplot
set key noopaque nobox

set terminal pngcairo size 900,500 font ",11" noenhanced
set output "$png/contact_lap_shear.png"
set title "Two poplar strands bonded by an interface (D_t = 1e11 Pa/m), lap shear (lap_shear_interface.toml)\\nclosed form: Volkersen's shear-lag joint, P = K δ, K = 3.5239e8 N/m²"
set xlabel "pulled end's displacement δ (μm)"
set ylabel "load P on the pulled end (N per m of width)"
set key bottom right
set autoscale
set xrange [0:10.5]
plot 3.5239e8 * x * 1e-6 with lines lw 2 lc rgb "black" title "closed form", \
     "$data/lap_shear_0.5mm.dat" using 1:2 with lines lw 3 lc 1 dt 2 title "cells of 0.5 mm", \
     "$data/lap_shear_0.25mm.dat" using 1:2 with lines lw 1.5 lc 2 title "cells of 0.25 mm"
GP
ls "$png"/contact_*.png
