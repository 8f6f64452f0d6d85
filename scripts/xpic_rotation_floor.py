#!/usr/bin/env python3
"""How much angular momentum XPIC(m)'s filter alone takes from the rotating
square of configs/verification/rotating_square.toml (0.4 m, 2 x 2 particles
per cell, linear shape functions, omega = 5 rad/s) in one step, and what
that compounds to over the quarter turn at dt = 0.5 h / (c + |v|max).

The particles carry the exactly rigid field v = omega x (x - x_c); XPIC(m)
hands them [I - (I - S+ S)^m] v [Hammerquist 2017], S = N^T m_p / m_I the
particle-to-grid map and S+ = N the grid-to-particle one, written here in
the grid form sum_k (-1)^(k+1) C(m, k) (S S+)^(k-1) S v that
tasks/xpic.hpp evaluates. The loss is a floor under XPIC(m)'s angle error
on this case (docs/validation/transfers.md): the filter also damps the
square's vibration, which this leaves out.

    python3 scripts/xpic_rotation_floor.py [m]   # m = 5 by default
"""
import math
import sys

import numpy as np


def filter_loss(cells, order, ppc=2, width=0.4, centre=1.0, omega=5.0):
    h = width / cells
    xs = centre - width / 2 + (np.arange(cells * ppc) + 0.5) * h / ppc
    X, Y = (a.ravel() for a in np.meshgrid(xs, xs, indexing="ij"))
    nodes = {}
    weights = []  # (node index, particle, N_Ip)
    for p, (x, y) in enumerate(zip(X, Y)):
        i0, j0 = math.floor(x / h), math.floor(y / h)
        for i in (i0, i0 + 1):
            for j in (j0, j0 + 1):
                w = (1 - abs(x / h - i)) * (1 - abs(y / h - j))
                if w > 0:
                    weights.append((nodes.setdefault((i, j), len(nodes)), p, w))
    N = np.zeros((len(nodes), len(X)))
    for a, p, w in weights:
        N[a, p] = w
    S = N / N.sum(axis=1, keepdims=True)  # equal particle masses
    vx, vy = -omega * (Y - centre), omega * (X - centre)

    def xpic(v):
        term, star = S @ v, np.zeros(len(nodes))
        for k in range(1, order + 1):
            star += (-1) ** (k + 1) * math.comb(order, k) * term
            term = S @ (N.T @ term)
        return N.T @ star

    def momentum(ux, uy):
        return np.sum((X - centre) * uy - (Y - centre) * ux)

    return 1.0 - momentum(xpic(vx), xpic(vy)) / momentum(vx, vy)


if __name__ == "__main__":
    order = int(sys.argv[1]) if len(sys.argv) > 1 else 5
    c = 116.0  # m/s, the P-wave speed of the square's material
    print(f"XPIC({order}), rotating square: angular momentum the filter takes")
    for cells in (8, 16, 32):
        h = 0.4 / cells
        steps = round(0.1 * math.pi / (0.5 * h / (c + 5.0 * 0.2 * math.sqrt(2.0))))
        loss = filter_loss(cells, order)
        total = 1.0 - (1.0 - loss) ** steps
        print(f"  {cells:2d} cells: {loss:.3e} per step, {steps} steps, {total:.3f} over the quarter turn")
