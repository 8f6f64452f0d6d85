// Throughput of the explicit step: a 3D linear-elastic block resting on a
// fixed base under gravity (USL, FLIP; linear shape functions unless
// --shape names another), at several
// sizes, with 1 and 2 threads. Reports, per size, the median over repeats of
//   - particle-steps per second through the flow graph, 1 and 2 threads,
//     and the 2-thread speedup;
//   - the serial reference step (stages called in order, no graph) on one
//     thread, and the graph's rate relative to it (noisy: two timings);
//   - the flow graph's own cost per step, measured alone (the USL wiring
//     with stages that do nothing, 2 threads), as a share of the 2-thread
//     step;
//   - set-up time (particles generated and sorted) per million particles;
//   - peak resident memory per particle (whole process, and above the
//     resident memory before the model was built);
//   - the share of each node of the step graph in the 1-thread step (the
//     rest: sorting and
//     the time loop);
//   - the cost of one output step (the default fields to a step file), in bytes and
//     microseconds per particle, apart from the step rate.
// Output steps are not part of this program (docs/performance.md, output cost).
// With --transport heat (or both: heat and solvent) the block conducts heat
// (and diffuses solvent) from its base, held at 400 K (and c = 0.1), and
// expands with it; the program then reports instead, per size, the rates
// without transport, with the transport branch beside the momentum stages
// (the engine's wiring) and with it run before them (one after the other),
// the cost of transport per particle-step, and what running the branches
// side by side gains.
// With --transfers the program reports per size the rates with the FLIP,
// APIC and XPIC(5) velocity updates, 1 and 2 threads, and APIC's and
// XPIC's over FLIP's.
// With --contact the block is two half-blocks (y below and above 0.5 m),
// the upper resting on the lower, in Coulomb contact (mu = 0.3): the
// program reports per size the rates of the one-body block and of the two
// bodies in contact, 1 and 2 threads, their ratio, and the peak bytes per
// particle of each.
// With --material mohr_coulomb (or drucker_prager) the program reports per
// size the rates of the elastic block and of the same block of that soil
// (the same elasticity, phi = 30 degrees, c = 10 kPa, psi = 0; Drucker-
// Prager's plane-strain fit), 1 and 2 threads, and the soil step's cost
// over the elastic one's (their rates' inverse ratio). The block's
// self-weight (10 kPa at its base) stays inside the surface: every particle
// takes the trial, its principal stresses (Mohr-Coulomb) or invariants
// and the yield check, the elastic path of a soil at rest.
// With --axisymmetric the block is a 2D section, 1 m x 1 m, of cells of
// 2 x 2 particles on a held base under gravity, run in plane strain and
// axisymmetric (x the radius from the axis): the program reports per size
// the rates of both, 1 and 2 threads, and the axisymmetric step's cost
// over the plane-strain step's (their rates' inverse ratio).
// With --roofline the program first measures this machine's bandwidth and
// FMA rate on 1 and 2 threads (bench/roofline.hpp, which says how), and
// prints under every row of the main table the flops and bytes of one
// particle-step, the rate each limit allows, and the fraction of the
// lower one the step reaches on 1 and 2 threads.
//
//   build/bench/bench_throughput [--sizes 1e4,1e5,1e6] [--particle-steps N]
//                                [--repeats R] [--shape linear|gimp|bspline2|bspline3]
//                                [--transport heat|both] [--contact] [--transfers] [--axisymmetric]
//                                [--material mohr_coulomb|drucker_prager] [--roofline] [--csv FILE]
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <tbb/global_control.h>

#include "discretisation/shapes/shape_functions.hpp"
#include "engine/stable_time_step.hpp"
#include "engine/schemes.hpp"
#include "engine/simulation.hpp"
#include "io/results/results_h5.hpp"
#include "roofline.hpp"

using namespace flowmpm;
using Clock = std::chrono::steady_clock;

namespace {

// The benches' material: a soft elastic solid.
LinearElastic::Parameters bench_elastic() {
  LinearElastic::Parameters elastic;
  elastic.density = 1000.0;       // kg/m^3
  elastic.youngs_modulus = 1e7;   // Pa
  elastic.poisson_ratio = 0.3;
  return elastic;
}

// The node plane y = 0 held still on every axis.
NodeSetSpec held_base(int dimension) {
  NodeSetSpec base;
  base.name = "base";
  base.axis = 1;
  base.at = 0.0;
  for (int d = 0; d < dimension; ++d) base.velocity[d] = TimeFunction{{{0.0, 0.0}}};
  return base;
}

// The block: k x k x k cells of 8 particles each (2 per axis), resting on
// the plane of nodes two cells above the grid's bottom, which is held fixed
// (two cells of grid around the block leave room for every shape function).
SystemSpec block_case(std::size_t target_particles, const std::string& shape, const std::string& transport = "",
                      bool contact = false) {
  const int k = std::max(2, static_cast<int>(std::lround(std::cbrt(target_particles / 8.0))));
  const double h = 1.0 / k;  // a 1 m cube
  SystemSpec c;
  c.source = "bench_block";
  c.dimension = 3;
  c.shape_function = shape_function_named(shape);
  c.grid.origin = {-2 * h, -2 * h, -2 * h};
  c.grid.cell_size = {h, h, h};
  c.grid.cells = {k + 4, k + 5, k + 4};
  c.gravity = {0.0, -9.81, 0.0};
  LinearElastic::Parameters elastic = bench_elastic();
  if (!transport.empty()) {
    // kappa = k / (rho C) = 1e-3 m^2/s: the wave limit governs dt at every size.
    elastic.transport.heat_capacity = 1000.0;             // J/(kg K)
    elastic.transport.conductivity.setConstant(1000.0);   // W/(m K)
    elastic.transport.reference_temperature = 300.0;      // K
    elastic.expansion.alpha.fill(1e-5);                   // 1/K
    elastic.expansion.thermal = true;
    if (transport == "both") {
      elastic.transport.diffusivity.setConstant(1e-3);   // m^2/s
      elastic.expansion.beta.fill(0.01);
      elastic.expansion.solvent = true;
    }
  }
  c.materials.push_back({"elastic", LinearElastic(elastic)});
  BodySpec body;
  body.name = "block";
  body.shape = BodyShape{BoxShape{{0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}}};
  body.spacing = {h / 2, h / 2, h / 2};
  body.temperature = 300.0;  // K, used with transport only
  c.bodies.push_back(body);
  NodeSetSpec base = held_base(3);
  if (!transport.empty()) base.temperature = TimeFunction{{{0.0, 400.0}}};
  if (transport == "both") base.concentration = TimeFunction{{{0.0, 0.1}}};
  c.node_sets.push_back(base);
  if (contact) {
    // The same particles as two bodies: the lattice's layers split at y = 0.5 m.
    c.bodies[0].name = "lower";
    c.bodies[0].shape = BodyShape{BoxShape{{0.0, 0.0, 0.0}, {1.0, 0.5, 1.0}}};
    BodySpec upper = c.bodies[0];
    upper.name = "upper";
    upper.shape = BodyShape{BoxShape{{0.0, 0.5, 0.0}, {1.0, 1.0, 1.0}}};
    c.bodies.push_back(upper);
    ContactSpec pair;
    pair.first = 0;
    pair.second = 1;
    pair.names = {"lower", "upper"};
    pair.law = CoulombLaw{0.3};
    c.contacts.push_back(pair);
  }
  const StableStep stable = stable_time_step(c, scheme_named("usl"));
  c.dt = std::min(0.5 * stable.crossing, stable.dt());
  return c;
}

std::size_t resident_kib(const char* field) {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);) {
    if (line.rfind(field, 0) == 0) return std::stoul(line.substr(std::string(field).size()));
  }
  return 0;
}

// Lets VmHWM (peak resident memory) restart from the current resident size.
void reset_peak_resident() { std::ofstream("/proc/self/clear_refs") << "5"; }

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

// Cost of one output step: the particle snapshot written to its step file
// (the default fields; flushed to disk and renamed into place), in bytes
// and seconds per particle.
template <class Shape>
std::pair<double, double> output_cost(SystemSpec c) {
  c.keep_initial_positions = true;  // for the displacement field
  Simulation<3, Shape> sim(c, scheme_named("usl").wiring, c.dt);
  const auto dir = std::filesystem::temp_directory_path() / "flowmpm-bench-output";
  std::filesystem::create_directories(dir);
  ResultsMetadata metadata;  // the materials' names: HDF5 writes no empty attribute
  for (const auto& m : c.materials) metadata.materials.push_back(m.name);
  ResultsH5 h5(dir / "results.h5", metadata);
  const auto start = Clock::now();
  h5.write(sim.snapshot(default_output_fields()));
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  const double bytes = static_cast<double>(std::filesystem::file_size(dir / ResultsH5::step_file(0)));
  std::filesystem::remove_all(dir);
  const double n = static_cast<double>(sim.system().particle_count());
  return {bytes / n, seconds / n};
}

struct Timing {
  double rate = 0.0;  // particle-steps per second
  std::vector<double> node_share;  // per node of the wiring
  double setup = 0.0;  // s
  std::size_t particles = 0;
  std::int64_t sorts = 0;
};

template <class Shape, int D = 3>
Timing time_steps(const SystemSpec& c, int threads, bool serial, int steps, TransportBranch branch) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
  const auto t0 = Clock::now();
  Simulation<D, Shape> sim(c, scheme_named("usl").wiring, c.dt, {}, branch);
  Timing t;
  t.setup = std::chrono::duration<double>(Clock::now() - t0).count();
  t.particles = sim.system().particle_count();
  for (int s = 0; s < 2; ++s) serial ? sim.advance_serial() : sim.advance();  // warm-up
  const auto before = sim.graph().node_seconds();
  const auto start = Clock::now();
  for (int s = 0; s < steps; ++s) serial ? sim.advance_serial() : sim.advance();
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  t.rate = static_cast<double>(t.particles) * steps / seconds;
  for (std::size_t i = 0; i < before.size(); ++i)
    t.node_share.push_back((sim.graph().node_seconds()[i] - before[i]) / seconds);
  t.sorts = sim.system().sorts;
  return t;
}

// Seconds per step of the flow graph alone: the USL wiring with empty
// stages, triggered many times on 2 threads.
double empty_graph_seconds_per_step() {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
  StepGraph graph(scheme_named("usl").wiring, [](int) {});
  for (int i = 0; i < 1000; ++i) graph.run();  // warm-up
  const int runs = 100000;
  const auto start = Clock::now();
  for (int i = 0; i < runs; ++i) graph.run();
  return std::chrono::duration<double>(Clock::now() - start).count() / runs;
}

// The bench's two measurements, compiled for one shape function.
struct ShapeRunner {
  Timing (*time_steps)(const SystemSpec&, int threads, bool serial, int steps, TransportBranch branch);
  std::pair<double, double> (*output_cost)(SystemSpec);
  Timing (*time_steps_2d)(const SystemSpec&, int threads, bool serial, int steps, TransportBranch branch);
};

ShapeRunner runner_named(const std::string& shape) {
  const std::vector<std::string> known = shape_function_names();
  if (std::ranges::find(known, shape) == known.end()) {
    std::cerr << "--shape: expected one of " << quoted_list(known) << ", got '" << shape << "'\n";
    std::exit(1);
  }
  return with_shape_function(shape_function_named(shape),
                             []<class Shape>() {
                               return ShapeRunner{&time_steps<Shape>, &output_cost<Shape>, &time_steps<Shape, 2>};
                             });
}

// Two models timed in turn, `repeats` times: the median rates of a and b
// on 1 thread and on 2, and a's particle count.
struct PairRates {
  double a1 = 0.0, b1 = 0.0, a2 = 0.0, b2 = 0.0;  // particle-steps per second
  std::size_t particles = 0;
};

PairRates pair_rates(decltype(ShapeRunner::time_steps) time_steps, const SystemSpec& a, const SystemSpec& b,
                     int steps, int repeats) {
  std::vector<double> a1, b1, a2, b2;
  PairRates r;
  for (int k = 0; k < repeats; ++k) {
    const Timing t = time_steps(a, 1, false, steps, TransportBranch::beside);
    r.particles = t.particles;
    a1.push_back(t.rate);
    b1.push_back(time_steps(b, 1, false, steps, TransportBranch::beside).rate);
    a2.push_back(time_steps(a, 2, false, steps, TransportBranch::beside).rate);
    b2.push_back(time_steps(b, 2, false, steps, TransportBranch::beside).rate);
  }
  r.a1 = median(a1);
  r.b1 = median(b1);
  r.a2 = median(a2);
  r.b2 = median(b2);
  return r;
}

// The transport table: per size, the median rates (2 threads unless
// stated) without transport, with the branch beside the momentum stages
// and run before them; transport's cost per particle-step; the gain of the
// branches side by side.
void transport_table(const ShapeRunner& runner, const std::vector<double>& sizes, double particle_steps, int repeats,
                     const std::string& shape, const std::string& transport, std::ofstream& csv) {
  std::printf("3D elastic block on a fixed base under gravity, USL, %s shape functions, %s transport from the base;"
              " medians of %d runs\n", shape.c_str(), transport == "both" ? "heat and solvent" : "heat", repeats);
  std::printf("%10s %6s %10s %10s %10s %10s %10s %12s %12s %8s  %s\n", "particles", "steps", "plain 1t", "transp 1t",
              "plain 2t", "beside 2t", "before 2t", "cost 1t", "cost 2t", "gain", "shares of the nodes (beside, 1 thread)");
  std::printf("%10s %6s %10s %10s %10s %10s %10s %12s %12s %8s\n", "", "", "Mp-st/s", "Mp-st/s", "Mp-st/s", "Mp-st/s",
              "Mp-st/s", "ns/p-step", "ns/p-step", "");
  if (csv) {
    csv << "particles,steps,rate_plain_1t,rate_transport_1t,rate_plain_2t,rate_beside_2t,rate_before_2t,"
           "cost_ns_1t,cost_ns_2t,gain_beside_vs_before\n";
  }
  for (double size : sizes) {
    const SystemSpec plain = block_case(static_cast<std::size_t>(size), shape);
    const SystemSpec coupled = block_case(static_cast<std::size_t>(size), shape, transport);
    const int steps = std::max(5, static_cast<int>(particle_steps / size));
    std::vector<double> p1, t1, p2, beside, before;
    std::vector<std::vector<double>> shares;
    std::size_t n = 0;
    std::vector<StageGroup> nodes;
    for (int r = 0; r < repeats; ++r) {
      p1.push_back(runner.time_steps(plain, 1, false, steps, TransportBranch::beside).rate);
      const Timing one = runner.time_steps(coupled, 1, false, steps, TransportBranch::beside);
      t1.push_back(one.rate);
      p2.push_back(runner.time_steps(plain, 2, false, steps, TransportBranch::beside).rate);
      beside.push_back(runner.time_steps(coupled, 2, false, steps, TransportBranch::beside).rate);
      before.push_back(runner.time_steps(coupled, 2, false, steps, TransportBranch::before).rate);
      n = one.particles;
      shares.resize(one.node_share.size());
      for (std::size_t i = 0; i < shares.size(); ++i) shares[i].push_back(one.node_share[i]);
    }
    nodes = step_wiring(scheme_named("usl").wiring, coupled).nodes;
    const double mp1 = median(p1), mt1 = median(t1), mp2 = median(p2), mb = median(beside), ma = median(before);
    const double cost1 = 1e9 * (1.0 / mt1 - 1.0 / mp1), cost2 = 1e9 * (1.0 / mb - 1.0 / mp2);
    std::ostringstream stage_text;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      stage_text << "[" << group_name(nodes[i]) << "] " << std::lround(100 * median(shares[i])) << "% ";
    }
    std::printf("%10zu %6d %10.2f %10.2f %10.2f %10.2f %10.2f %12.1f %12.1f %7.1f%%  %s\n", n, steps, mp1 / 1e6,
                mt1 / 1e6, mp2 / 1e6, mb / 1e6, ma / 1e6, cost1, cost2, 100.0 * (mb / ma - 1.0),
                stage_text.str().c_str());
    std::fflush(stdout);
    if (csv) {
      csv << n << "," << steps << "," << mp1 << "," << mt1 << "," << mp2 << "," << mb << "," << ma << "," << cost1
          << "," << cost2 << "," << (mb / ma - 1.0) << "\n";
    }
  }
}

// The bench's soil (header): the elastic constants of bench_elastic.
Material bench_soil(const std::string& type) {
  const LinearElastic::Parameters e = bench_elastic();
  FrictionalParameters p;
  p.density = e.density;
  p.youngs_modulus = e.youngs_modulus;
  p.poisson_ratio = e.poisson_ratio;
  p.friction_angle = 30.0 * std::numbers::pi / 180.0;
  p.cohesion = 10e3;
  p.tension_cutoff = p.apex();
  if (type == "mohr_coulomb") {
    MohrCoulomb::Parameters m;
    static_cast<FrictionalParameters&>(m) = p;
    return MohrCoulomb(m);
  }
  DruckerPrager::Parameters d;
  static_cast<FrictionalParameters&>(d) = p;
  return DruckerPrager(d);
}

// The material table: per size, the median rates of the elastic block and
// of the soil block, 1 and 2 threads, and the soil step's relative cost.
void material_table(const ShapeRunner& runner, const std::vector<double>& sizes, double particle_steps, int repeats,
                    const std::string& shape, const std::string& material, std::ofstream& csv) {
  std::printf("3D block on a fixed base under gravity, USL, %s shape functions: linear_elastic and %s"
              " (phi = 30 deg, c = 10 kPa, inside the surface); medians of %d runs\n", shape.c_str(), material.c_str(),
              repeats);
  std::printf("%10s %6s %10s %10s %10s %10s %8s %8s\n", "particles", "steps", "elast 1t", "soil 1t", "elast 2t",
              "soil 2t", "cost 1t", "cost 2t");
  std::printf("%10s %6s %10s %10s %10s %10s\n", "", "", "Mp-st/s", "Mp-st/s", "Mp-st/s", "Mp-st/s");
  if (csv) csv << "particles,steps,rate_elastic_1t,rate_soil_1t,rate_elastic_2t,rate_soil_2t\n";
  for (double size : sizes) {
    const SystemSpec elastic = block_case(static_cast<std::size_t>(size), shape);
    SystemSpec soil = elastic;
    soil.materials[0] = {material, bench_soil(material)};
    const int steps = std::max(5, static_cast<int>(particle_steps / size));
    const PairRates r = pair_rates(runner.time_steps, elastic, soil, steps, repeats);
    std::printf("%10zu %6d %10.2f %10.2f %10.2f %10.2f %8.3f %8.3f\n", r.particles, steps, r.a1 / 1e6, r.b1 / 1e6,
                r.a2 / 1e6, r.b2 / 1e6, r.a1 / r.b1, r.a2 / r.b2);
    std::fflush(stdout);
    if (csv) csv << r.particles << "," << steps << "," << r.a1 << "," << r.b1 << "," << r.a2 << "," << r.b2 << "\n";
  }
}

// The contact table: per size, the median rates of the one-body block and
// of the two half-blocks in contact, 1 and 2 threads, their ratios, and
// the peak resident bytes per particle of each.
void contact_table(const ShapeRunner& runner, const std::vector<double>& sizes, double particle_steps, int repeats,
                   const std::string& shape, std::ofstream& csv) {
  std::printf("3D elastic block on a fixed base under gravity, USL, %s shape functions: one body, and two half-blocks"
              " in Coulomb contact; medians of %d runs\n", shape.c_str(), repeats);
  std::printf("%10s %6s %10s %10s %10s %10s %8s %8s %9s %9s\n", "particles", "steps", "one 1t", "contact 1t", "one 2t",
              "contact 2t", "ratio 1t", "ratio 2t", "B/p one", "B/p cont");
  std::printf("%10s %6s %10s %10s %10s %10s %8s %8s %9s %9s\n", "", "", "Mp-st/s", "Mp-st/s", "Mp-st/s", "Mp-st/s", "",
              "", "peak", "peak");
  if (csv) csv << "particles,steps,rate_one_1t,rate_contact_1t,rate_one_2t,rate_contact_2t,bytes_one,bytes_contact\n";
  for (double size : sizes) {
    const SystemSpec one = block_case(static_cast<std::size_t>(size), shape);
    const SystemSpec two = block_case(static_cast<std::size_t>(size), shape, "", true);
    const int steps = std::max(5, static_cast<int>(particle_steps / size));
    // Peak resident memory of each model, above what the process held before it.
    auto peak_bytes = [&](const SystemSpec& c) {
      const std::size_t before = resident_kib("VmRSS:");
      reset_peak_resident();
      const Timing t = runner.time_steps(c, 2, false, 5, TransportBranch::beside);
      return 1024.0 * static_cast<double>(resident_kib("VmHWM:") - before) / static_cast<double>(t.particles);
    };
    const double bytes_one = peak_bytes(one), bytes_two = peak_bytes(two);
    const PairRates r = pair_rates(runner.time_steps, one, two, steps, repeats);
    const std::size_t n = r.particles;
    const double mo1 = r.a1, mc1 = r.b1, mo2 = r.a2, mc2 = r.b2;
    std::printf("%10zu %6d %10.2f %10.2f %10.2f %10.2f %8.2f %8.2f %9.0f %9.0f\n", n, steps, mo1 / 1e6, mc1 / 1e6,
                mo2 / 1e6, mc2 / 1e6, mc1 / mo1, mc2 / mo2, bytes_one, bytes_two);
    std::fflush(stdout);
    if (csv) csv << n << "," << steps << "," << mo1 << "," << mc1 << "," << mo2 << "," << mc2 << "," << bytes_one << ","
                 << bytes_two << "\n";
  }
}

// The transfers table: per size, the median rates with the FLIP, APIC and
// XPIC(5) velocity updates (docs/theory/transfers.md), 1 and 2 threads, and
// APIC's and XPIC's rates over FLIP's.
void transfers_table(const ShapeRunner& runner, const std::vector<double>& sizes, double particle_steps, int repeats,
                     const std::string& shape, std::ofstream& csv) {
  std::printf("3D elastic block on a fixed base under gravity, USL, %s shape functions: FLIP, APIC and XPIC(5);"
              " medians of %d runs\n", shape.c_str(), repeats);
  std::printf("%10s %6s %9s %9s %9s %9s %9s %9s %7s %7s %7s %7s\n", "particles", "steps", "FLIP 1t", "APIC 1t", "XPIC 1t",
              "FLIP 2t", "APIC 2t", "XPIC 2t", "A/F 1t", "A/F 2t", "X/F 1t", "X/F 2t");
  std::printf("%10s %6s %9s %9s %9s %9s %9s %9s\n", "", "", "Mp-st/s", "Mp-st/s", "Mp-st/s", "Mp-st/s", "Mp-st/s",
              "Mp-st/s");
  if (csv) csv << "particles,steps,rate_flip_1t,rate_apic_1t,rate_xpic_1t,rate_flip_2t,rate_apic_2t,rate_xpic_2t\n";
  for (double size : sizes) {
    std::array<SystemSpec, 3> cases;
    const VelocityUpdate updates[] = {VelocityUpdate::flip, VelocityUpdate::apic, VelocityUpdate::xpic};
    for (int u = 0; u < 3; ++u) {
      cases[u] = block_case(static_cast<std::size_t>(size), shape);
      cases[u].velocity_update = updates[u];
      cases[u].flip_fraction = u == 0 ? 1.0 : 0.0;
    }
    const int steps = std::max(5, static_cast<int>(particle_steps / size));
    std::array<std::vector<double>, 6> rates;
    std::size_t n = 0;
    for (int r = 0; r < repeats; ++r) {
      for (int threads : {1, 2}) {
        for (int u = 0; u < 3; ++u) {
          const Timing t = runner.time_steps(cases[u], threads, false, steps, TransportBranch::beside);
          n = t.particles;
          rates[3 * (threads - 1) + u].push_back(t.rate);
        }
      }
    }
    std::array<double, 6> m;
    for (int i = 0; i < 6; ++i) m[i] = median(rates[i]);
    std::printf("%10zu %6d %9.2f %9.2f %9.2f %9.2f %9.2f %9.2f %7.2f %7.2f %7.2f %7.2f\n", n, steps, m[0] / 1e6,
                m[1] / 1e6, m[2] / 1e6, m[3] / 1e6, m[4] / 1e6, m[5] / 1e6, m[1] / m[0], m[4] / m[3], m[2] / m[0],
                m[5] / m[3]);
    std::fflush(stdout);
    if (csv) {
      csv << n << "," << steps;
      for (double rate : m) csv << "," << rate;
      csv << "\n";
    }
  }
}

// The section of --axisymmetric: k x k cells of 2 x 2 particles, 1 m x
// 1 m, on the held plane y = 0 under gravity; axisymmetric, x is the
// radius and the grid starts on the axis (its node set "axis" holds
// v_r = 0); plane strain, two cells of grid on each side.
SystemSpec section_case(std::size_t target_particles, const std::string& shape, bool axisymmetric) {
  const int k = std::max(2, static_cast<int>(std::lround(std::sqrt(target_particles / 4.0))));
  const double h = 1.0 / k;
  SystemSpec c;
  c.source = "bench_section";
  c.dimension = 2;
  c.axisymmetric = axisymmetric;
  c.shape_function = shape_function_named(shape);
  c.grid.origin = {axisymmetric ? 0.0 : -2 * h, -2 * h, 0.0};
  c.grid.cell_size = {h, h, h};
  c.grid.cells = {k + (axisymmetric ? 2 : 4), k + 5, 1};
  c.gravity = {0.0, -9.81, 0.0};
  c.materials.push_back({"elastic", LinearElastic(bench_elastic())});
  BodySpec body;
  body.name = "section";
  body.shape = BodyShape{BoxShape{{0.0, 0.0, 0.0}, {1.0, 1.0, 0.0}}};
  body.spacing = {h / 2, h / 2, h / 2};
  c.bodies.push_back(body);
  c.node_sets.push_back(held_base(2));
  const StableStep stable = stable_time_step(c, scheme_named("usl"));
  c.dt = std::min(0.5 * stable.crossing, stable.dt());
  return c;
}

// The axisymmetric table: per size, the median rates of the section in
// plane strain and axisymmetric, 1 and 2 threads, and the axisymmetric
// step's cost over the plane-strain one's.
void axisymmetric_table(const ShapeRunner& runner, const std::vector<double>& sizes, double particle_steps,
                        int repeats, const std::string& shape, std::ofstream& csv) {
  std::printf("2D elastic section on a fixed base under gravity, USL, %s shape functions: plane strain and"
              " axisymmetric; medians of %d runs\n", shape.c_str(), repeats);
  std::printf("%10s %6s %10s %10s %10s %10s %9s %9s\n", "particles", "steps", "plane 1t", "axisym 1t", "plane 2t",
              "axisym 2t", "cost 1t", "cost 2t");
  std::printf("%10s %6s %10s %10s %10s %10s %9s %9s\n", "", "", "Mp-st/s", "Mp-st/s", "Mp-st/s", "Mp-st/s", "ax/pl",
              "ax/pl");
  if (csv) csv << "particles,steps,rate_plane_1t,rate_axisymmetric_1t,rate_plane_2t,rate_axisymmetric_2t\n";
  for (double size : sizes) {
    const SystemSpec plane = section_case(static_cast<std::size_t>(size), shape, false);
    const SystemSpec axisymmetric = section_case(static_cast<std::size_t>(size), shape, true);
    const int steps = std::max(5, static_cast<int>(particle_steps / size));
    const PairRates r = pair_rates(runner.time_steps_2d, plane, axisymmetric, steps, repeats);
    const std::size_t n = r.particles;
    const double mp1 = r.a1, ma1 = r.b1, mp2 = r.a2, ma2 = r.b2;
    std::printf("%10zu %6d %10.2f %10.2f %10.2f %10.2f %9.3f %9.3f\n", n, steps, mp1 / 1e6, ma1 / 1e6, mp2 / 1e6,
                ma2 / 1e6, mp1 / ma1, mp2 / ma2);
    std::fflush(stdout);
    if (csv) csv << n << "," << steps << "," << mp1 << "," << ma1 << "," << mp2 << "," << ma2 << "\n";
  }
}

std::vector<double> parse_sizes(const std::string& text) {
  std::vector<double> sizes;
  std::stringstream ss(text);
  for (std::string item; std::getline(ss, item, ',');) sizes.push_back(std::stod(item));
  return sizes;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<double> sizes{1e4, 1e5, 1e6};
  double particle_steps = 3e7;  // per measurement, so that each lasts ~1 s or more
  int repeats = 3;
  std::string csv_path, shape = "linear", transport, material;
  bool contact = false, transfers = false, axisymmetric = false, roofline = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&] {
      if (i + 1 >= argc) {
        std::cerr << a << " needs a value\n";
        std::exit(1);
      }
      return std::string(argv[++i]);
    };
    if (a == "--sizes") sizes = parse_sizes(next());
    else if (a == "--particle-steps") particle_steps = std::stod(next());
    else if (a == "--repeats") repeats = std::stoi(next());
    else if (a == "--shape") shape = next();
    else if (a == "--csv") csv_path = next();
    else if (a == "--contact") contact = true;
    else if (a == "--transfers") transfers = true;
    else if (a == "--axisymmetric") axisymmetric = true;
    else if (a == "--roofline") roofline = true;
    else if (a == "--material") {
      material = next();
      if (material != "mohr_coulomb" && material != "drucker_prager") {
        std::cerr << "--material: expected \"mohr_coulomb\" or \"drucker_prager\", got '" << material << "'\n";
        return 1;
      }
    }
    else if (a == "--transport") {
      transport = next();
      if (transport != "heat" && transport != "both") {
        std::cerr << "--transport: expected \"heat\" or \"both\", got '" << transport << "'\n";
        return 1;
      }
    }
    else {
      std::cerr << "usage: bench_throughput [--sizes 1e4,1e5,1e6] [--particle-steps 3e7] [--repeats 3] [--shape linear] "
                   "[--transport heat|both] [--contact] [--transfers] [--axisymmetric] [--material mohr_coulomb|drucker_prager] "
                   "[--roofline] [--csv FILE]\n";
      return a == "--help" ? 0 : 1;
    }
  }

  const ShapeRunner runner = runner_named(shape);
  if (contact) {
    std::ofstream csv;
    if (!csv_path.empty()) csv.open(csv_path);
    contact_table(runner, sizes, particle_steps, repeats, shape, csv);
    return 0;
  }
  if (!material.empty()) {
    std::ofstream csv;
    if (!csv_path.empty()) csv.open(csv_path);
    material_table(runner, sizes, particle_steps, repeats, shape, material, csv);
    return 0;
  }
  if (axisymmetric) {
    std::ofstream csv;
    if (!csv_path.empty()) csv.open(csv_path);
    axisymmetric_table(runner, sizes, particle_steps, repeats, shape, csv);
    return 0;
  }
  if (transfers) {
    std::ofstream csv;
    if (!csv_path.empty()) csv.open(csv_path);
    transfers_table(runner, sizes, particle_steps, repeats, shape, csv);
    return 0;
  }
  if (!transport.empty()) {
    std::ofstream csv;
    if (!csv_path.empty()) csv.open(csv_path);
    transport_table(runner, sizes, particle_steps, repeats, shape, transport, csv);
    return 0;
  }
  const std::vector<StageGroup> nodes = scheme_named("usl").wiring.nodes;
  std::printf("3D elastic block on a fixed base under gravity, USL, %s shape functions; medians of %d runs\n",
              shape.c_str(), repeats);
  const double graph_seconds = empty_graph_seconds_per_step();
  std::printf("flow graph alone (USL wiring, empty stages, 2 threads): %.2f us per step\n", 1e6 * graph_seconds);
  bench::MachineLimits limits[2];
  if (roofline) {
    for (int t = 0; t < 2; ++t) {
      limits[t] = bench::measure_machine(t + 1);
      std::printf("this machine, %d thread%s: %.1f GB/s (a[i] += s b[i]), %.1f GF/s (FMA, %d-bit vectors)\n", t + 1,
                  t ? "s" : "", limits[t].bandwidth / 1e9, limits[t].flops / 1e9, bench::vector_bits());
    }
  }
  std::printf("%10s %6s %10s %10s %8s %10s %8s %8s %9s %9s %9s %8s %8s  %s\n", "particles", "steps", "1 thr", "2 thr",
              "speedup", "serial 1t", "graph vs", "graph", "setup", "B/p peak", "B/p model", "output", "output",
              "shares of the graph's nodes at 1 thread");
  std::printf("%10s %6s %10s %10s %8s %10s %8s %8s %9s %9s %9s %8s %8s\n", "", "", "Mp-st/s", "Mp-st/s", "", "Mp-st/s",
              "serial", "cost", "s/Mp", "", "", "B/p", "us/p");
  std::ofstream csv;
  if (!csv_path.empty()) {
    csv.open(csv_path);
    csv << "particles,steps,rate_1t,rate_2t,speedup,rate_serial_1t,graph_vs_serial,graph_cost,setup_s_per_million,"
           "bytes_per_particle_peak,bytes_per_particle_model,output_bytes_per_particle,output_seconds_per_particle";
    for (const StageGroup& node : nodes) csv << ",share_" << group_name(node);
    if (roofline) csv << ",flops_per_particle_step,bytes_per_particle_step,limit_1t,limit_2t,fraction_1t,fraction_2t";
    csv << "\n";
  }
  for (double size : sizes) {
    const SystemSpec c = block_case(static_cast<std::size_t>(size), shape);
    std::size_t n = 0;
    std::vector<double> r1, r2, rs, setup;
    std::vector<std::vector<double>> shares(nodes.size());
    const int steps = std::max(5, static_cast<int>(particle_steps / size));
    const std::size_t rss_before = resident_kib("VmRSS:");
    reset_peak_resident();
    for (int r = 0; r < repeats; ++r) {
      const Timing serial = runner.time_steps(c, 1, true, steps, TransportBranch::beside);
      const Timing one = runner.time_steps(c, 1, false, steps, TransportBranch::beside);
      const Timing two = runner.time_steps(c, 2, false, steps, TransportBranch::beside);
      n = one.particles;
      rs.push_back(serial.rate);
      r1.push_back(one.rate);
      r2.push_back(two.rate);
      setup.push_back(one.setup);
      for (std::size_t i = 0; i < nodes.size(); ++i) shares[i].push_back(one.node_share[i]);
    }
    const double peak = 1024.0 * resident_kib("VmHWM:");
    const auto [out_bytes, out_seconds] = runner.output_cost(c);
    const double bpp_peak = peak / n, bpp_model = (peak - 1024.0 * rss_before) / n;
    const double m1 = median(r1), m2 = median(r2), ms = median(rs);
    std::ostringstream stage_text;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      stage_text << "[" << group_name(nodes[i]) << "] " << std::lround(100 * median(shares[i])) << "% ";
    }
    const double graph_cost = graph_seconds / (n / m2);  // share of a 2-thread step
    std::printf("%10zu %6d %10.2f %10.2f %8.2f %10.2f %7.1f%% %7.3f%% %9.3f %9.0f %9.0f %8.0f %8.3f  %s\n", n, steps,
                m1 / 1e6, m2 / 1e6, m2 / m1, ms / 1e6, 100.0 * (ms / m1 - 1.0), 100.0 * graph_cost,
                median(setup) / (n / 1e6), bpp_peak, bpp_model, out_bytes, 1e6 * out_seconds,
                stage_text.str().c_str());
    std::fflush(stdout);
    if (csv) {
      csv << n << "," << steps << "," << m1 << "," << m2 << "," << m2 / m1 << "," << ms << "," << (ms / m1 - 1.0)
          << "," << graph_cost << "," << median(setup) / (n / 1e6) << "," << bpp_peak << "," << bpp_model << "," << out_bytes << ","
          << out_seconds;
      for (const auto& share : shares) csv << "," << median(share);
    }
    if (roofline) {
      // The rate each limit allows: bandwidth over bytes, FMA rate over flops.
      const double flops = bench::flops_per_particle_step(shape), bytes = 2.0 * bpp_model;
      double limit[2], fraction[2];
      for (int t = 0; t < 2; ++t) {
        limit[t] = std::min(limits[t].bandwidth / bytes, limits[t].flops / flops);
        fraction[t] = (t ? m2 : m1) / limit[t];
      }
      std::printf("%10s roofline: %.0f flop and %.0f B per particle-step; limits 1t %.1f (memory) / %.1f (FMA), "
                  "2t %.1f / %.1f Mp-st/s; the step reaches %.2f (1t) and %.2f (2t) of the lower\n",
                  "", flops, bytes, limits[0].bandwidth / bytes / 1e6, limits[0].flops / flops / 1e6,
                  limits[1].bandwidth / bytes / 1e6, limits[1].flops / flops / 1e6, fraction[0], fraction[1]);
      std::fflush(stdout);
      if (csv) csv << "," << flops << "," << bytes << "," << limit[0] << "," << limit[1] << "," << fraction[0] << ","
                   << fraction[1];
    }
    if (csv) csv << "\n";
  }
  return 0;
}
