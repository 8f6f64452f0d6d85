// What MPI costs on this machine, for the performance model of a domain
// decomposition (docs/DISTRIBUTED.md), measured between ranks 0 and 1:
//   1. ping-pong: half the round trip of one message, 8 B to 64 MiB; the
//      latency is the 8 B time, the bandwidth the highest bytes over time
//      of any size (each the fastest of many round trips);
//   2. MPI_Allreduce (max) of 2 doubles: the per-step reduction of the
//      re-sort and failure flags and the fastest particle;
//   3. the halo of the particle-to-grid sum across one face of a rank's box
//      of L^3 nodes of the engine's grid (Grid<3>, one array per field
//      component): W node planes of the 7 summed fields (mass, momentum,
//      force) packed by rank 0, sent, and added into rank 1's planes; then
//      the 6 fields of the grid update (velocity and its change) packed by
//      rank 1, sent back and copied into rank 0's planes. For faces normal
//      to x (W doubles contiguous), y (W L) and z (W L^2). It reports the
//      measured exchange, the packing alone, and the model's prediction:
//      the two messages of these sizes timed alone (ping-pong) plus the
//      packing.
// The fastest of --repeats timings. Built only with MPI (FLOWMPM_MPI).
//
//   mpirun -n 2 build/bench/bench_mpi_halo [--nodes L] [--width W] [--repeats R]
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "discretisation/grid/grid.hpp"

using namespace flowmpm;
using Clock = std::chrono::steady_clock;

namespace {

// The fastest of the repeats: the machine is shared, and the fastest run is
// the one least disturbed by the rest of its load.
double fastest(const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); }

// Half the round trip of a `bytes` message between ranks 0 and 1 (s): the
// fastest of many round trips, each timed alone.
double ping_pong(int rank, std::size_t bytes, int repeats) {
  std::vector<char> buffer(std::max<std::size_t>(bytes, 1));
  const int count = static_cast<int>(bytes);
  // About 0.2 s per size, at least `repeats` round trips.
  const int trips = std::max(repeats, static_cast<int>(0.2 / (2e-6 + static_cast<double>(bytes) / 2e9)));
  std::vector<double> times;
  for (int t = 0; t < trips; ++t) {
    MPI_Barrier(MPI_COMM_WORLD);
    const auto start = Clock::now();
    if (rank == 0) {
      MPI_Send(buffer.data(), count, MPI_CHAR, 1, 0, MPI_COMM_WORLD);
      MPI_Recv(buffer.data(), count, MPI_CHAR, 1, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    } else if (rank == 1) {
      MPI_Recv(buffer.data(), count, MPI_CHAR, 0, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      MPI_Send(buffer.data(), count, MPI_CHAR, 0, 0, MPI_COMM_WORLD);
    }
    times.push_back(std::chrono::duration<double>(Clock::now() - start).count() / 2.0);
  }
  return fastest(times);
}

double allreduce_time(int repeats) {
  std::vector<double> times;
  const int calls = 2000;
  for (int r = 0; r < repeats; ++r) {
    double in[2] = {1.0, 2.0}, out[2];
    MPI_Barrier(MPI_COMM_WORLD);
    const auto start = Clock::now();
    for (int c = 0; c < calls; ++c) MPI_Allreduce(in, out, 2, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    times.push_back(std::chrono::duration<double>(Clock::now() - start).count() / calls);
  }
  return fastest(times);
}

// W node planes at one side of the box, normal to `axis`: the lower ones
// [0, W) or the upper ones [L - W, L).
struct Planes {
  Index<3> lo, hi;  // inclusive
  Planes(const Grid<3>& grid, int axis, int width, bool upper) {
    for (int d = 0; d < 3; ++d) {
      lo[d] = 0;
      hi[d] = grid.nodes[d] - 1;
    }
    if (upper) {
      lo[axis] = grid.nodes[axis] - width;
    } else {
      hi[axis] = width - 1;
    }
  }
  std::size_t nodes() const {
    std::size_t n = 1;
    for (int d = 0; d < 3; ++d) n *= static_cast<std::size_t>(hi[d] - lo[d] + 1);
    return n;
  }
  // f(first node, run length): the x-runs of the planes, in buffer order.
  template <class F>
  void for_each_run(const Grid<3>& grid, F&& f) const {
    const std::size_t run = static_cast<std::size_t>(hi[0] - lo[0] + 1);
    for (int k = lo[2]; k <= hi[2]; ++k)
      for (int j = lo[1]; j <= hi[1]; ++j) f(grid.node_index({lo[0], j, k}), run);
  }
};

void pack(const Grid<3>& grid, const Planes& planes, const std::vector<const double*>& fields, double* out) {
  for (const double* field : fields) {
    planes.for_each_run(grid, [&](std::size_t first, std::size_t run) {
      std::memcpy(out, field + first, run * sizeof(double));
      out += run;
    });
  }
}

void unpack_add(const Grid<3>& grid, const Planes& planes, const std::vector<double*>& fields, const double* in) {
  for (double* field : fields) {
    planes.for_each_run(grid, [&](std::size_t first, std::size_t run) {
      for (std::size_t i = 0; i < run; ++i) field[first + i] += in[i];
      in += run;
    });
  }
}

void unpack_copy(const Grid<3>& grid, const Planes& planes, const std::vector<double*>& fields, const double* in) {
  for (double* field : fields) {
    planes.for_each_run(grid, [&](std::size_t first, std::size_t run) {
      std::memcpy(field + first, in, run * sizeof(double));
      in += run;
    });
  }
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  int L = 128, W = 5, repeats = 7;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--nodes" && i + 1 < argc) L = std::stoi(argv[++i]);
    else if (a == "--width" && i + 1 < argc) W = std::stoi(argv[++i]);
    else if (a == "--repeats" && i + 1 < argc) repeats = std::stoi(argv[++i]);
    else {
      if (rank == 0) std::fprintf(stderr, "usage: mpirun -n 2 bench_mpi_halo [--nodes 128] [--width 5] [--repeats 7]\n");
      MPI_Finalize();
      return 1;
    }
  }
  if (size != 2) {
    if (rank == 0) std::fprintf(stderr, "bench_mpi_halo: run it on 2 ranks (mpirun -n 2), not %d\n", size);
    MPI_Finalize();
    return 1;
  }
  char host[MPI_MAX_PROCESSOR_NAME];
  int length = 0;
  MPI_Get_processor_name(host, &length);

  // 1. Ping-pong.
  const std::vector<std::size_t> sizes{8, 64, 512, 4096, 32768, 262144, 2097152, 16777216, 67108864};
  std::vector<double> one_way;
  for (std::size_t bytes : sizes) one_way.push_back(ping_pong(rank, bytes, repeats));
  const double latency = one_way.front();
  std::size_t best = 0;  // the size with the highest bandwidth
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    if (static_cast<double>(sizes[i]) / one_way[i] > static_cast<double>(sizes[best]) / one_way[best]) best = i;
  }
  const double bandwidth = static_cast<double>(sizes[best]) / one_way[best];
  // 2. Allreduce.
  const double reduce = allreduce_time(repeats);
  if (rank == 0) {
    std::printf("MPI between 2 ranks on %s, fastest of %d\n\n", host, repeats);
    std::printf("| message (bytes) | one way (us) | bandwidth (GB/s) |\n|---|---|---|\n");
    for (std::size_t i = 0; i < sizes.size(); ++i) {
      std::printf("| %zu | %.2f | %.2f |\n", sizes[i], one_way[i] * 1e6, static_cast<double>(sizes[i]) / one_way[i] / 1e9);
    }
    std::printf("\nlatency alpha = %.2f us, bandwidth beta = %.2f GB/s (at %zu bytes); MPI_Allreduce of 2 doubles: "
                "%.2f us\n\n",
                latency * 1e6, bandwidth / 1e9, sizes[best], reduce * 1e6);
  }

  // 3. The P2G halo across one face.
  Grid<3> grid(Vec<3>::Zero(), Vec<3>::Ones(), Index<3>{L - 1, L - 1, L - 1});
  for (std::size_t n = 0; n < grid.node_count(); ++n) {
    grid.mass[n] = 1.0 + static_cast<double>(n % 7);
    for (int d = 0; d < 3; ++d) {
      grid.momentum[d][n] = grid.force[d][n] = grid.velocity[d][n] = grid.velocity_change[d][n] = 0.5 * d;
    }
  }
  const std::vector<const double*> sums{grid.mass.data(),        grid.momentum[0].data(), grid.momentum[1].data(),
                                        grid.momentum[2].data(), grid.force[0].data(),    grid.force[1].data(),
                                        grid.force[2].data()};
  const std::vector<double*> sums_out{grid.mass.data(),        grid.momentum[0].data(), grid.momentum[1].data(),
                                      grid.momentum[2].data(), grid.force[0].data(),    grid.force[1].data(),
                                      grid.force[2].data()};
  const std::vector<const double*> update{grid.velocity[0].data(),        grid.velocity[1].data(),
                                          grid.velocity[2].data(),        grid.velocity_change[0].data(),
                                          grid.velocity_change[1].data(), grid.velocity_change[2].data()};
  const std::vector<double*> update_out{grid.velocity[0].data(),        grid.velocity[1].data(),
                                        grid.velocity[2].data(),        grid.velocity_change[0].data(),
                                        grid.velocity_change[1].data(), grid.velocity_change[2].data()};
  if (rank == 0) {
    std::printf("P2G halo across one face of a box of %d^3 nodes, %d node planes: 7 fields there, 6 back\n\n", L, W);
    std::printf("| face normal to | nodes | bytes there + back | packing, both ways (ms) | exchange measured (ms) | "
                "model: the two messages alone + packing (ms) |\n|---|---|---|---|---|---|\n");
  }
  const char* axis_names = "xyz";
  for (int axis = 0; axis < 3; ++axis) {
    const Planes upper(grid, axis, W, true), lower(grid, axis, W, false);
    const std::size_t nodes = upper.nodes();
    std::vector<double> there(7 * nodes), back(6 * nodes);
    // Packing alone, on this rank: what each side does per exchange.
    std::vector<double> pack_times, exchange_times;
    for (int r = 0; r < repeats; ++r) {
      const auto start = Clock::now();
      pack(grid, upper, sums, there.data());
      unpack_add(grid, lower, sums_out, there.data());
      pack(grid, lower, update, back.data());
      unpack_copy(grid, upper, update_out, back.data());
      pack_times.push_back(std::chrono::duration<double>(Clock::now() - start).count());
    }
    for (int r = 0; r < repeats; ++r) {
      MPI_Barrier(MPI_COMM_WORLD);
      const auto start = Clock::now();
      if (rank == 0) {
        pack(grid, upper, sums, there.data());
        MPI_Send(there.data(), static_cast<int>(there.size()), MPI_DOUBLE, 1, 1, MPI_COMM_WORLD);
        MPI_Recv(back.data(), static_cast<int>(back.size()), MPI_DOUBLE, 1, 2, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        unpack_copy(grid, upper, update_out, back.data());
      } else {
        MPI_Recv(there.data(), static_cast<int>(there.size()), MPI_DOUBLE, 0, 1, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        unpack_add(grid, lower, sums_out, there.data());
        pack(grid, lower, update, back.data());
        MPI_Send(back.data(), static_cast<int>(back.size()), MPI_DOUBLE, 0, 2, MPI_COMM_WORLD);
      }
      exchange_times.push_back(std::chrono::duration<double>(Clock::now() - start).count());
    }
    const double bytes = 13.0 * 8.0 * static_cast<double>(nodes);
    const double packing = fastest(pack_times);
    // The model: two messages of these sizes, timed alone, and the packing.
    const double model = ping_pong(rank, there.size() * sizeof(double), repeats) +
                         ping_pong(rank, back.size() * sizeof(double), repeats) + packing;
    if (rank == 0) {
      std::printf("| %c | %zu | %.0f | %.3f | %.3f | %.3f |\n", axis_names[axis], nodes, bytes, packing * 1e3,
                  fastest(exchange_times) * 1e3, model * 1e3);
    }
  }
  MPI_Finalize();
  return 0;
}
