#!/usr/bin/env python3
"""Writes configs/verification/spun_prestressed_bar.csv: the particles of a
bar 1 m x 0.1 m (x along its axis, centred at the origin), 2 x 2 per cell
of 0.025 m, each with the stress of the bar spinning steadily about its
centre at omega (rad/s):

    sigma_xx = rho omega^2 (L^2 / 4 - x^2) / 2,
    sigma_yy = rho omega^2 (W^2 / 4 - y^2) / 2,   the rest 0,

which balances the centripetal acceleration -omega^2 r
(d sigma_xx / dx = -rho omega^2 x, d sigma_yy / dy = -rho omega^2 y) and
leaves every face free. With nu = 0 its strain is compatible: an exact
steady state of linear elasticity, so the bar spins without vibrating
and its stress should keep its place in the bar.

    python3 scripts/spun_bar_particles.py   # rho = 1000 kg/m^3, omega = sqrt(8) rad/s
"""
import math
import pathlib

L, W, spacing = 1.0, 0.1, 0.0125        # m
rho, omega = 1000.0, math.sqrt(8.0)     # kg/m^3, rad/s: sigma_xx = 1000 Pa at the centre
k = rho * omega**2 / 2.0

out = pathlib.Path(__file__).resolve().parent.parent / "configs" / "verification" / "spun_prestressed_bar.csv"
with open(out, "w") as f:
    f.write("# Written by scripts/spun_bar_particles.py: the bar of spun_prestressed_bar.toml,\n")
    f.write(f"# its steady stress at omega = {omega:.10g} rad/s and rho = {rho:g} kg/m^3 (Pa).\n")
    f.write("x,y,volume,stress_xx,stress_yy,stress_zz,stress_yz,stress_xz,stress_xy\n")
    for i in range(round(L / spacing)):
        x = -L / 2 + (i + 0.5) * spacing
        for j in range(round(W / spacing)):
            y = -W / 2 + (j + 0.5) * spacing
            sxx = k * (L * L / 4 - x * x)
            syy = k * (W * W / 4 - y * y)
            f.write(f"{x:.6g},{y:.6g},{spacing * spacing:.6g},{sxx:.10g},{syy:.10g},0,0,0,0\n")
