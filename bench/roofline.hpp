// The machine's limits for bench_throughput --roofline, measured on the
// spot, and what one particle-step asks of them.
//
// Bandwidth: the read-modify-write loop a[i] += s b[i] over two arrays of
// 2^24 doubles (128 MiB each, far beyond any cache), the pattern of the
// particle updates, counted as 24 B per element (a read, b read, a
// written; as STREAM counts, without the write-allocate read). Each thread
// sweeps its own contiguous share; the best of 5 sweeps.
// FMA rate: 8 independent chains of acc = acc x + y on vectors of 8
// doubles (GCC vector extensions, so the build's widest vectors: AVX-512
// where -march=native finds it, SSE2 in the portable build), 2 flops per
// lane and FMA; every thread runs its own chains; the best of 5 runs.
//
// One particle-step's flops are counted from the source, per stencil node
// and per particle (3D, USL, FLIP, linear_elastic, the bench's block):
//   per node, both transfers: the node's weight N and gradient from the
//     1D factors, 2 + 6 flops, twice (p2g and g2p build their own stencil);
//   p2g per node: mass 2, momentum 2 D, force D (2 D + 2), and with
//     linear shape functions the nodal stiffness 2 D + 1: 39 (32 without);
//   g2p per node: velocity 2 D, FLIP's increment 2 D, velocity gradient
//     2 D^2: 30;
//   per particle: the 1D factors 24 per stencil (48), p2g's m v, m g and
//     V sigma (15), motion and energy sums (35), the stress update with
//     its objective rotation (about 200: the rotation from the spin and
//     R sigma R^T about 140, the strain increment and Hooke's law 40,
//     the stored energy 20).
// Linear: 8 nodes, 8 (16 + 39 + 30) + 298 = 978; quadratic B-spline: 27
// nodes, 27 (16 + 32 + 30) + 298 = 2404; cubic: 64 nodes, 5290. A count of
// the arithmetic the code asks for, not of what the compiler emits (no
// hardware counters here); a model within perhaps 20 %.
// One particle-step's bytes: everything the model holds (its resident
// memory above the process's before it, particles, grid and buffers) read
// and written once per step, 2 x its bytes per particle: an upper bound
// of the traffic when nothing stays in cache from one stage to the next.
#pragma once
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <string>
#include <vector>

namespace flowmpm::bench {

struct MachineLimits {
  double bandwidth = 0.0;  // B/s
  double flops = 0.0;      // flop/s
};

// The bandwidth and FMA rate of `threads` threads (above).
inline MachineLimits measure_machine(int threads) {
  using Clock = std::chrono::steady_clock;
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
  MachineLimits m;
  const std::size_t n = std::size_t{1} << 24;
  std::vector<double> a(n, 1.0), b(n, 0.5);
  const double s = 1e-9;
  const auto sweep = [&] {
    tbb::parallel_for(0, threads, [&](int t) {
      const std::size_t first = n * static_cast<std::size_t>(t) / static_cast<std::size_t>(threads);
      const std::size_t last = n * static_cast<std::size_t>(t + 1) / static_cast<std::size_t>(threads);
      double* const pa = a.data();
      const double* const pb = b.data();
      for (std::size_t i = first; i < last; ++i) pa[i] += s * pb[i];
    }, tbb::static_partitioner());
  };
  sweep();  // pages touched, threads started
  for (int r = 0; r < 5; ++r) {
    const auto t0 = Clock::now();
    sweep();
    const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    m.bandwidth = std::max(m.bandwidth, 24.0 * static_cast<double>(n) / seconds);
  }

  using Lanes = double __attribute__((vector_size(64)));
  constexpr int chains = 8, lanes = 8;
  const long iterations = 20'000'000;
  std::vector<double> sink(static_cast<std::size_t>(threads), 0.0);
  const auto run = [&] {
    tbb::parallel_for(0, threads, [&](int t) {
      volatile double x_in = 0.999999, y_in = 1e-7;  // not known to the compiler
      const double x = x_in, y = y_in;
      Lanes acc[chains];
      for (int c = 0; c < chains; ++c)
        for (int l = 0; l < lanes; ++l) acc[c][l] = 1.0 + 0.1 * c + 0.01 * l;
      for (long i = 0; i < iterations; ++i)
        for (int c = 0; c < chains; ++c) acc[c] = acc[c] * x + y;
      double total = 0.0;
      for (int c = 0; c < chains; ++c)
        for (int l = 0; l < lanes; ++l) total += acc[c][l];
      sink[static_cast<std::size_t>(t)] = total;
    }, tbb::static_partitioner());
  };
  for (int r = 0; r < 5; ++r) {
    const auto t0 = Clock::now();
    run();
    const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    m.flops = std::max(m.flops, 2.0 * chains * lanes * static_cast<double>(iterations) * threads / seconds);
  }
  return m;
}

// The width of the vectors the FMA loop runs on in this build (GCC lowers
// its 8-double vectors to what the target has).
inline int vector_bits() {
#if defined(__AVX512F__)
  return 512;
#elif defined(__AVX__)
  return 256;
#else
  return 128;
#endif
}

// One particle-step's flops (above), 3D, by the shape function's stencil.
inline double flops_per_particle_step(const std::string& shape) {
  const int nodes = shape == "linear" ? 8 : shape == "bspline3" ? 64 : 27;  // gimp and bspline2: 3 per axis
  const int p2g = shape == "linear" ? 39 : 32;
  return nodes * (16 + p2g + 30) + 298.0;
}

}  // namespace flowmpm::bench
