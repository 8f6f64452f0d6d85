// Results do not depend on the thread count, nor on whether the step runs
// through the flow graph or serially: two bodies of different materials,
// one thrown against the other under gravity, fast enough that particles
// cross cells and leave their blocks (so particles are re-sorted during the
// run). 1 thread, 2 threads and the serial reference must agree bit for bit.
// The same for the nonlocal averages of a softening band (the symmetric
// strain-softening bar, nonlocal_length), which run serially in a fixed
// order inside a parallel step, for an imperfect interface (the lap
// shear of configs/contact), and with the APIC and XPIC(5) velocity updates.
#include <doctest/doctest.h>

#include <tbb/global_control.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "discretisation/shapes/shape_bspline.hpp"
#include "discretisation/shapes/shape_gimp.hpp"
#include "discretisation/shapes/shape_functions.hpp"
#include "discretisation/shapes/shape_linear.hpp"
#include "engine/simulation.hpp"
#include "test_helpers.hpp"

using namespace flowmpm;

namespace {

std::string impact_case(int dim) {
  const char* v3[] = {"", "[0.0]", "[0.0, 0.0]", "[0.0, 0.0, 0.0]"};
  const char* vel[] = {"", "[8.0]", "[8.0, -1.0]", "[8.0, -1.0, 0.5]"};
  const char* g[] = {"", "[-9.81]", "[0.0, -9.81]", "[0.0, -9.81, 0.0]"};
  const char* cells[] = {"", "[40]", "[24, 24]", "[19, 16, 16]"};
  const char* a_min[] = {"", "[0.3]", "[0.3, 0.8]", "[0.3, 0.6, 0.5]"};
  const char* a_max[] = {"", "[0.8]", "[0.8, 1.3]", "[0.8, 1.1, 1.0]"};
  const char* b_min[] = {"", "[1.0]", "[1.0, 0.5]", "[0.95, 0.5, 0.4]"};
  const char* b_max[] = {"", "[1.6]", "[1.6, 1.4]", "[1.4, 1.2, 1.1]"};
  return std::string("[analysis]\ndimension = ") + std::to_string(dim) +
         "\nscheme = \"musl\"\nvelocity_update = \"blend\"\nflip_fraction = 0.95\ndt = 5e-4\nsteps = 120\n"
         "gravity = " + g[dim] + "\n[grid]\norigin = " + v3[dim] + "\ncell_size = 0.1\ncells = " + cells[dim] +
         "\n[materials.soft]\ntype = \"linear_elastic\"\ndensity = 1000.0\nyoungs_modulus = 1e6\npoisson_ratio = 0.3\n"
         "[materials.stiff]\ntype = \"linear_elastic\"\ndensity = 2000.0\nyoungs_modulus = 4e6\npoisson_ratio = 0.25\n"
         "[[bodies]]\nname = \"projectile\"\nmaterial = \"soft\"\nmin = " + a_min[dim] + "\nmax = " + a_max[dim] +
         "\nparticles_per_cell = 2\nvelocity = " + vel[dim] +
         "\n[[bodies]]\nname = \"target\"\nmaterial = \"stiff\"\nmin = " + b_min[dim] + "\nmax = " + b_max[dim] +
         "\nspacing = 0.04\n";
}

template <int D, class Shape>
ParticleSnapshot run(const Case& c, int threads, bool serial, std::int64_t* sorts = nullptr,
                     std::vector<std::string> fields = default_output_fields()) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
  auto sim = testing::simulation<D, Shape>(c);
  for (std::int64_t s = 0; s < c.time_control.steps; ++s) serial ? sim.advance_serial() : sim.advance();
  if (sorts) *sorts = sim.system().sorts;
  return sim.snapshot(fields);
}

void check_identical(const ParticleSnapshot& a, const ParticleSnapshot& b,
                     std::vector<const char*> names = {"position", "velocity", "stress", "strain", "volume"}) {
  REQUIRE(a.count == b.count);
  // Bitwise: operator== on doubles, no tolerance.
  for (const char* name : names) {
    CAPTURE(name);
    CHECK(a.find(name)->real == b.find(name)->real);
  }
}

// The impact with Coulomb contact between the bodies (tasks/contact.hpp):
// each body a velocity field of its own, the contact stages in the graph.
const char* const coulomb_contact =
    "[[contacts]]\nbodies = [\"projectile\", \"target\"]\nlaw = \"coulomb\"\nfriction = 0.3\n";

// `update`: the velocity update instead of the blend.
template <int D, class Shape = LinearShape>
void check_dimension(const std::string& extra = "", const std::string& update = "", const std::string& scheme = "") {
  std::string text = impact_case(D) + extra;
  if (!update.empty()) {
    const std::string blend = "velocity_update = \"blend\"\nflip_fraction = 0.95";
    text.replace(text.find(blend), blend.size(), "velocity_update = \"" + update + "\"");
  }
  if (!scheme.empty()) {
    const std::string musl = "scheme = \"musl\"";
    text.replace(text.find(musl), musl.size(), "scheme = \"" + scheme + "\"");
  }
  const Case c = testing::case_from_text("impact" + std::to_string(D) + "d", text,
                                         {std::string("analysis.shape_function=") + Shape::name});
  std::int64_t sorts = 0;
  const ParticleSnapshot one = run<D, Shape>(c, 1, false, &sorts);
  // Particles move up to 8 m/s * 0.06 s = 4.8 cells: re-sorted on the way.
  CHECK(sorts > 1);
  check_identical(one, run<D, Shape>(c, 2, false));
  check_identical(one, run<D, Shape>(c, 2, true));
  // The bodies moved and were stressed: the comparison is not between zeros.
  double max_stress = 0.0;
  for (double s : one.find("stress")->real) max_stress = std::max(max_stress, std::abs(s));
  CHECK(max_stress > 1e3);
}

}  // namespace

TEST_CASE("1D: 1 thread, 2 threads and the serial step agree bit for bit") { check_dimension<1>(); }
TEST_CASE("2D: 1 thread, 2 threads and the serial step agree bit for bit") { check_dimension<2>(); }
TEST_CASE("3D: 1 thread, 2 threads and the serial step agree bit for bit") { check_dimension<3>(); }
TEST_CASE("contact: 1 thread, 2 threads and the serial step agree bit for bit") {
  check_dimension<1>(coulomb_contact);
  check_dimension<2>(coulomb_contact);
  check_dimension<3>(coulomb_contact);
  check_dimension<2, GimpShape>(coulomb_contact);
}
TEST_CASE("contact on a coarse grid, the surface between node planes: 1 thread, 2 threads and serial agree bit for bit") {
  // The block of configs/contact sliding on the rigid plane (mu = 0.2) and
  // sticking on the deformable slab (mu = 0.7), 20 mm cells, the surface 3/4 of a cell above a node
  // plane: the block's bottom particle row on a node plane, so that held
  // sliver nodes take part in the contact (tests/test_contact.cpp), 0.05 s.
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {"contact/incline_block_rigid.toml",
       {"grid.cell_size=0.02", "grid.cells=[154, 9]", "grid.origin=[-0.02, -0.055]", "contacts[0].friction=0.2",
        "analysis.end_time=0.05"}},
      // The slab 3 cells thick (whole particle spacings), held 2.75 cells
      // below its surface, as in test_contact.cpp.
      {"contact/incline_block_slab.toml",
       {"grid.cell_size=0.02", "grid.cells=[154, 15]", "grid.origin=[-0.02, -0.095]", "bodies[1].min=[-0.01, -0.06]",
        "bodies[2].min=[0.0, -0.06]", "bodies[3].min=[0.2, -0.06]", "node_sets[0].at=-0.055",
        "contacts[0].friction=0.7", "analysis.end_time=0.05"}}};
  // The cases' time step is automatic (from the particles' largest speed,
  // a max, the same in any order): stepped to their end time.
  const auto run_to_end = [](const Case& c, int threads, bool serial) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
    auto sim = testing::simulation<2, LinearShape>(c);
    std::int64_t steps = 0;
    for (; sim.system().t < c.time_control.end_time; ++steps) serial ? sim.advance_serial() : sim.advance();
    CHECK(steps > 500);
    return sim.snapshot(default_output_fields());
  };
  for (const auto& [file, overrides] : cases) {
    CAPTURE(file);
    const Case c = read_case(testing::config(file), overrides);
    const ParticleSnapshot one = run_to_end(c, 1, false);
    check_identical(one, run_to_end(c, 2, false));
    check_identical(one, run_to_end(c, 2, true));
    // The bodies are stressed by the block's weight (about 1 kPa under it):
    // the comparison is not between zeros.
    double max_stress = 0.0;
    for (double v : one.find("stress")->real) max_stress = std::max(max_stress, std::abs(v));
    MESSAGE(file << ": largest stress component " << max_stress << " Pa");
    CHECK(max_stress > 100.0);
  }
}
TEST_CASE("an imperfect interface: 1 thread, 2 threads and the serial step agree bit for bit") {
  // The lap shear of configs/contact (two strands bonded by an interface,
  // its forces summed per slab of nodes) at 0.5 mm cells, 200 steps into
  // the pull (short: the sanitizer build runs this program at -O0).
  const Case c = read_case(testing::config("contact/lap_shear_interface.toml"),
                           {"grid.cell_size=0.0005", "grid.cells=[62, 6]", "analysis.dt=3e-8", "analysis.end_time=6e-6"});
  const ParticleSnapshot one = run<2, LinearShape>(c, 1, false);
  check_identical(one, run<2, LinearShape>(c, 2, false));
  check_identical(one, run<2, LinearShape>(c, 2, true));
  double max_stress = 0.0;
  for (double s : one.find("stress")->real) max_stress = std::max(max_stress, std::abs(s));
  MESSAGE("largest stress component " << max_stress << " Pa");
  CHECK(max_stress > 1e5);
}
TEST_CASE("APIC and XPIC(5): bit for bit too, with contact") {
  // APIC's affine velocity reaches the positions and velocities compared;
  // XPIC's projections are scatters in the colour order. 2D only: this
  // program also runs in the sanitizer build (-O0).
  check_dimension<2, QuadraticBSpline>("", "apic");
  check_dimension<2, LinearShape>(coulomb_contact, "apic");
  check_dimension<2, GimpShape>(coulomb_contact, "xpic");
  // XPIC's particles take its filtered velocity u, and without contact
  // under USL their strain too; with contact its iterates take the laws.
  check_dimension<2, LinearShape>("", "xpic");
  check_dimension<2, LinearShape>("", "xpic", "usl");
  check_dimension<2, LinearShape>(coulomb_contact, "xpic", "usl");
  // In 3D, where the contact nodes XPIC's iterates visit are gathered
  // over many slabs of the grid in parallel (joined in slab order; a
  // shared list once raced there and corrupted the heap).
  check_dimension<3, LinearShape>(coulomb_contact, "xpic");
}
TEST_CASE("uGIMP and B-splines (wider blocks): bit for bit too") {
  check_dimension<2, GimpShape>();
  check_dimension<2, QuadraticBSpline>();
  check_dimension<3, CubicBSpline>();
}

namespace {

// Two bodies thrown against each other as above, one orthotropic with
// turned axes, both conducting heat and diffusing solvent, expanding with
// both; a face held hot and wet, a surface flux.
std::string transport_case() {
  return R"(
[analysis]
dimension = 2
scheme = "usl"
velocity_update = "blend"
flip_fraction = 0.95
dt = 5e-4
steps = 120
[grid]
origin = [0.0, 0.0]
cell_size = 0.1
cells = [24, 24]
[materials.wood]
type = "orthotropic"
density = 2000.0
Ex = 8e6
Ey = 4e6
Ez = 4e6
Gxy = 1.5e6
Gxz = 1.5e6
Gyz = 1.2e6
nuxy = 0.3
nuxz = 0.3
nuyz = 0.4
heat_capacity = 1500.0
conductivity = [400.0, 100.0, 100.0]
diffusivity = [2e-2, 5e-3, 5e-3]
alpha = [3e-6, 3e-5, 4e-5]
beta = [0.002, 0.02, 0.03]
reference_temperature = 293.0
[materials.steel]
type = "linear_elastic"
density = 2000.0
youngs_modulus = 4e6
poisson_ratio = 0.25
heat_capacity = 500.0
conductivity = 800.0
diffusivity = 1e-3
alpha = 1e-5
beta = 0.01
reference_temperature = 293.0
[[bodies]]
name = "projectile"
material = "wood"
min = [0.3, 0.8]
max = [0.8, 1.3]
particles_per_cell = 2
velocity = [8.0, -1.0]
material_axes = [35.0]
temperature = 350.0
concentration = 0.05
[[bodies]]
name = "target"
material = "steel"
min = [1.0, 0.5]
max = [1.6, 1.4]
spacing = 0.04
concentration = 0.2
[[node_sets]]
name = "hot_wet_plane"
plane = "y"
at = 1.0
temperature = 400.0
concentration = [[0.0, 0.1], [0.05, 0.2]]
[[surface_fluxes]]
body = "target"
face = "x+"
heat_flux = 5e4
solvent_flux = 1.0
)";
}

template <int D, class Shape>
ParticleSnapshot run_transport(const Case& c, int threads, bool serial, TransportBranch branch,
                               std::int64_t* sorts = nullptr) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
  Simulation<D, Shape> sim(c.system, c.scheme->wiring, c.time_step.fixed_dt(), {}, branch);
  for (std::int64_t s = 0; s < c.time_control.steps; ++s) serial ? sim.advance_serial() : sim.advance();
  if (sorts) *sorts = sim.system().sorts;
  return sim.snapshot(c.output.fields);
}

}  // namespace

TEST_CASE("transport beside the mechanics: 1 thread, 2 threads, serial and one after the other agree bit for bit") {
  // MUSL with linear functions (USL lets the impact blow up there), USL with
  // B-splines: the branch joins before g2p_motion, and before the fused
  // g2p_motion & g2p_stress.
  for (auto [shape, scheme] : {std::pair{"linear", "musl"}, std::pair{"bspline2", "usl"}}) {
    CAPTURE(shape);
    const Case c = testing::case_from_text("impact_transport", transport_case(),
                                           {std::string("analysis.shape_function=") + shape,
                                            std::string("analysis.scheme=") + scheme});
    with_shape_function(c.system.shape_function, [&]<class Shape>() {
      std::int64_t sorts = 0;
      const ParticleSnapshot one = run_transport<2, Shape>(c, 1, false, TransportBranch::beside, &sorts);
      CHECK(sorts > 1);
      for (const ParticleSnapshot& other :
           {run_transport<2, Shape>(c, 2, false, TransportBranch::beside),
            run_transport<2, Shape>(c, 2, true, TransportBranch::beside),
            run_transport<2, Shape>(c, 2, false, TransportBranch::before)}) {
        check_identical(one, other);
        CHECK(one.find("temperature")->real == other.find("temperature")->real);
        CHECK(one.find("concentration")->real == other.find("concentration")->real);
      }
      // Heat and solvent moved: the comparison is not between constants.
      const auto& T = one.find("temperature")->real;
      const auto& conc = one.find("concentration")->real;
      CHECK(*std::ranges::max_element(T) - *std::ranges::min_element(T) > 10.0);
      CHECK(*std::ranges::max_element(conc) - *std::ranges::min_element(conc) > 0.05);
    });
  }
}

TEST_CASE("axisymmetric (the thick cylinder, its pressure ramping on): bit for bit too") {
  const Case c = read_case(testing::config("axisymmetric/thick_cylinder.toml"), {"analysis.end_time=0.3"});
  const ParticleSnapshot one = run<2, QuadraticBSpline>(c, 1, false);
  check_identical(one, run<2, QuadraticBSpline>(c, 2, false));
  check_identical(one, run<2, QuadraticBSpline>(c, 2, true));
  // The wall moved: the comparison is not between zeros.
  const auto& v = one.find("velocity")->real;
  CHECK(*std::ranges::max_element(v) > 0.0);
}

TEST_CASE("nonlocal averages (the symmetric strain-softening bar): bit for bit too") {
  const Case c = read_case(testing::config("materials/strain_softening_symmetric_bar.toml"));
  std::vector<std::string> fields = default_output_fields();
  fields.insert(fields.end(), {"damage", "dissipated_energy"});
  const ParticleSnapshot one = run<2, LinearShape>(c, 1, false, nullptr, fields);
  const std::vector<const char*> names = {"position", "velocity", "stress", "strain", "volume", "damage",
                                          "dissipated_energy"};
  check_identical(one, run<2, LinearShape>(c, 2, false, nullptr, fields), names);
  check_identical(one, run<2, LinearShape>(c, 2, true, nullptr, fields), names);
  // The band broke: the comparison is not between zeros.
  const auto& damage = one.find("damage")->real;
  CHECK(*std::max_element(damage.begin(), damage.end()) == 1.0);
}
