#!/usr/bin/env python3
"""The performance model of docs/DISTRIBUTED.md: expected parallel efficiency
of one explicit MPM step split over R machines (pencil decomposition, cuts
normal to z and y), for N particles. Prints the table the document quotes.

Every input is below, marked MEASURED (on the project's machine, with the
command that measured it) or ASSUMED (for a cluster; change them to your
machine's figures). Standard library only:

    python3 bench/distributed_model.py
"""
import math

# --- the engine (MEASURED) -------------------------------------------------
# Particle-steps per second per core, 3D elastic block of 10^6 particles, USL,
# 1 thread, native build: bench/README.md "Current engine (second session),
# default build" (build/bench/bench_throughput --sizes 1e6 --repeats 5
# [--shape bspline2]), taken on an idle machine.
RATE_PER_CORE = {"linear": 14.30e6, "bspline2": 6.01e6}
# Bytes moved per particle-step (bench/README.md "What limits the step rate").
BYTES_PER_PARTICLE_STEP = 420.0
# Shape functions: nodes reached below and above a particle's cell, and the
# block edge B (discretisation/shape_*.hpp, discretisation/grid/blocks.hpp).
REACH = {"linear": (0, 1), "bspline2": (1, 2)}
BLOCK = {"linear": 5, "bspline2": 7}
PARTICLES_PER_CELL = 8  # 2 per axis, as in bench_throughput
# Halo bytes per shared node and hand-over (USL): the P2G sum travels as
# mass, momentum, force (7 doubles); the grid update returns velocity and its
# change (6 doubles). Grid<3> fields, discretisation/grid/grid.hpp.
SUM_BYTES, RETURN_BYTES = 7 * 8, 6 * 8
# Hand-overs of a shared node's running sum per P2G pass with today's colour
# order (colour = px + 2 py + 4 pz): across a z face 1, across a y face 3.
HANDOVERS = {"z": 1, "y": 3}
# Halo bytes packed on one side and unpacked on the other per second, one
# core (MEASURED: mpirun -n 2 build/bench/bench_mpi_halo --nodes 128
# --width 5 and --width 7: the bytes over the "packing" column; faces normal
# to y gave 4.3-7.7 GB/s, to z 6.2-11.8 GB/s; the slowest is taken).
PACK_UNPACK_RATE_PER_CORE = 4.3e9

# --- a cluster (ASSUMED) -----------------------------------------------------
CORES_PER_NODE = 64           # two 32-core sockets, one MPI rank per node
MEMORY_BANDWIDTH = 300e9      # B/s per node (STREAM-like, DDR5, 2 sockets)
PACKING_THREADS = 8           # threads packing the halo in parallel
MESSAGE_OVERHEAD = 1e-6       # s of CPU per message sent or received
NETWORKS = {
    # name: (latency alpha in s, bandwidth beta in B/s per direction)
    "InfiniBand HDR100": (1.5e-6, 12e9),
    "25 Gb Ethernet": (25e-6, 2.8e9),
}


def node_rate(shape):
    """Particle-steps per second of one node: its cores, or its memory."""
    return min(CORES_PER_NODE * RATE_PER_CORE[shape], MEMORY_BANDWIDTH / BYTES_PER_PARTICLE_STEP)


def pencils(ranks):
    """P_y x P_z = ranks, as square as possible, P_z >= P_y."""
    p_y = int(math.sqrt(ranks))
    while ranks % p_y:
        p_y -= 1
    return p_y, ranks // p_y


def step_times(particles, ranks, shape, network, width):
    """Seconds per step of an interior rank: compute, and each communication term."""
    alpha, beta = network
    side = (particles / PARTICLES_PER_CELL) ** (1.0 / 3.0)  # cells per side of a cube of material
    p_y, p_z = pencils(ranks)
    compute = particles / ranks / node_rate(shape)
    # Shared nodes: each face is `width` node planes of the face's area.
    area_z = side * side / p_y  # a face normal to z: x by the rank's y extent
    area_y = side * side / p_z  # a face normal to y: x by the rank's z extent
    faces = {"z": area_z if p_z > 1 else 0.0, "y": area_y if p_y > 1 else 0.0}
    # Bytes a rank sends per step (it has two faces of each kind and sends
    # about half of each face's traffic).
    sent = sum(width * area * (HANDOVERS[axis] * SUM_BYTES + RETURN_BYTES) for axis, area in faces.items())
    transfer = sent / beta
    # Rounds: after colours 1, 3, 5 (y hand-overs; z after 3) and the return;
    # each to at most 8 neighbours (4 faces, 4 edges) in each direction.
    rounds = (3 if p_y > 1 else 1) + 1
    messages = rounds * 2 * 8
    latency = rounds * alpha + messages * MESSAGE_OVERHEAD
    packing = sent / (PACKING_THREADS * PACK_UNPACK_RATE_PER_CORE)  # pack what goes, unpack as much
    reduction = math.ceil(math.log2(ranks)) * alpha  # re-sort and failure flags, fastest particle
    return compute, transfer, latency, packing, reduction


def efficiency(particles, ranks, shape, network, width):
    compute, *communication = step_times(particles, ranks, shape, network, width)
    return compute / (compute + sum(communication))


def main():
    print(f"A machine: {CORES_PER_NODE} cores, {MEMORY_BANDWIDTH / 1e9:.0f} GB/s; its step rate linear "
          f"{node_rate('linear') / 1e6:.0f} M, bspline2 {node_rate('bspline2') / 1e6:.0f} M particle-steps/s.\n")
    for name, network in NETWORKS.items():
        print(f"**{name}**: alpha = {network[0] * 1e6:g} us, beta = {network[1] / 1e9:g} GB/s\n")
        print("| particles | nodes (P_y x P_z) | shape | step compute (ms) | halo sent per rank, W = B (MB) | "
              "communication, W = B (ms) | efficiency, W = reach | efficiency, W = B |")
        print("|---|---|---|---|---|---|---|---|")
        for particles in (1e8, 1e9):
            for ranks in (8, 16, 32, 64):
                for shape in ("linear", "bspline2"):
                    below, above = REACH[shape]
                    thin, wide = below + above, BLOCK[shape]
                    compute, transfer, latency, packing, reduction = step_times(particles, ranks, shape, network, wide)
                    sent = transfer * network[1]
                    p_y, p_z = pencils(ranks)
                    print(f"| {particles:.0e} | {ranks} ({p_y} x {p_z}) | {shape} | {compute * 1e3:.1f} | "
                          f"{sent / 1e6:.1f} | {(transfer + latency + packing + reduction) * 1e3:.2f} | "
                          f"{efficiency(particles, ranks, shape, network, thin):.0%} | "
                          f"{efficiency(particles, ranks, shape, network, wide):.0%} |")
        print()


if __name__ == "__main__":
    main()
