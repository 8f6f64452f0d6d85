// The order in which the stages of one step run, recorded from the flow
// graph, against the wirings of engine/schemes.hpp:
//   USF:  p2g_momentum -> grid_velocity -> g2p_stress -> p2g_force -> grid_integrate -> g2p_motion
//   USL:  p2g_momentum + p2g_force -> grid_velocity -> grid_integrate -> g2p_motion -> g2p_stress
//   MUSL: p2g_momentum + p2g_force -> grid_velocity -> grid_integrate -> g2p_motion -> remap
//         -> grid_velocity -> g2p_stress
// ("+": the two p2g stages may run in either order, or at once.) A scene
// whose models ask for nonlocal averages gets nonlocal_settle right after
// the node running g2p_stress; no other scene has it. The engine
// runs the two p2g stages, and USL's two g2p stages, in one pass over the
// particles ("&" in the wiring's description); the observer still sees each
// stage, in the order above.
// A scene that conducts heat or diffuses solvent adds the transport branch
//   transport_p2g -> transport_flux -> transport_update -> transport_g2p,
// which starts with the step beside the momentum stages and joins before
// the first node that writes particles (USL: g2p_motion & g2p_stress; USF:
// g2p_stress; MUSL: g2p_motion): its stages come in that order, all before
// the join, in any interleaving with the momentum stages before it, and
// the two branches do run at the same time.
#include <doctest/doctest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>

#include <tbb/global_control.h>

#include "discretisation/shapes/shape_linear.hpp"
#include "engine/simulation.hpp"
#include "test_helpers.hpp"

using namespace flowmpm;


namespace {

template <int D = 3>
std::vector<Stage> recorded_order(const std::string& scheme, bool serial,
                                  const std::string& config = "uniaxial_stress/case1_usl.toml") {
  const Case c = read_case(testing::config(config), {"analysis.scheme=" + scheme});
  std::mutex mutex;
  std::vector<Stage> order;
  auto sim = testing::simulation<D, LinearShape>(c, [&](Stage s) {
    std::lock_guard lock(mutex);
    order.push_back(s);
  });
  serial ? sim.advance_serial() : sim.advance();
  return order;
}

// Equal, except that the first `parallel_heads` stages may come in any order.
void check_order(std::vector<Stage> got, std::vector<Stage> expected, int parallel_heads) {
  REQUIRE(got.size() == expected.size());
  std::sort(got.begin(), got.begin() + parallel_heads);
  std::sort(expected.begin(), expected.begin() + parallel_heads);
  for (std::size_t i = 0; i < got.size(); ++i) {
    INFO("position " << i << ": got " << stage_name(got[i]) << ", expected " << stage_name(expected[i]));
    CHECK(got[i] == expected[i]);
  }
}

}  // namespace

TEST_CASE("USF wiring") {
  const std::vector<Stage> usf{Stage::p2g_momentum, Stage::grid_velocity,  Stage::g2p_stress,
                               Stage::p2g_force,    Stage::grid_integrate, Stage::g2p_motion};
  check_order(recorded_order("usf", false), usf, 1);
  check_order(recorded_order("usf", true), usf, 1);
  CHECK(scheme_named("usf").wiring.describe() ==
        "p2g_momentum -> grid_velocity -> g2p_stress -> p2g_force -> grid_integrate -> g2p_motion");
}

TEST_CASE("USL wiring") {
  const std::vector<Stage> usl{Stage::p2g_momentum,   Stage::p2g_force,  Stage::grid_velocity,
                               Stage::grid_integrate, Stage::g2p_motion, Stage::g2p_stress};
  check_order(recorded_order("usl", false), usl, 2);
  check_order(recorded_order("usl", true), usl, 2);
  CHECK(scheme_named("usl").wiring.describe() ==
        "p2g_momentum & p2g_force -> grid_velocity -> grid_integrate -> g2p_motion & g2p_stress");
}

TEST_CASE("MUSL wiring") {
  const std::vector<Stage> musl{Stage::p2g_momentum, Stage::p2g_force, Stage::grid_velocity, Stage::grid_integrate,
                                Stage::g2p_motion,   Stage::remap,     Stage::grid_velocity, Stage::g2p_stress};
  check_order(recorded_order("musl", false), musl, 2);
  check_order(recorded_order("musl", true), musl, 2);
  CHECK(scheme_named("musl").wiring.describe() ==
        "p2g_momentum & p2g_force -> grid_velocity -> grid_integrate -> g2p_motion -> remap -> "
        "grid_velocity -> g2p_stress");
}

TEST_CASE("nonlocal averages: nonlocal_settle right after g2p_stress, only where a model asks") {
  const std::string bar = "materials/strain_softening_symmetric_bar.toml";  // the default nonlocal band, MUSL
  using enum Stage;
  check_order(recorded_order<2>("usl", false, bar),
              {p2g_momentum, p2g_force, grid_velocity, grid_integrate, g2p_motion, g2p_stress, nonlocal_settle}, 2);
  check_order(recorded_order<2>("usf", true, bar),
              {p2g_momentum, grid_velocity, g2p_stress, nonlocal_settle, p2g_force, grid_integrate, g2p_motion}, 1);
  check_order(recorded_order<2>("musl", false, bar),
              {p2g_momentum, p2g_force, grid_velocity, grid_integrate, g2p_motion, remap, grid_velocity, g2p_stress,
               nonlocal_settle},
              2);
  const Case c = read_case(testing::config(bar));
  CHECK(testing::simulation<2, LinearShape>(c).graph().wiring().describe() ==
        "p2g_momentum & p2g_force -> grid_velocity -> grid_integrate -> g2p_motion -> remap -> grid_velocity -> "
        "g2p_stress -> nonlocal_settle");
  // The notched bar (strain_softening, nonlocal_length = 0): the plain wiring.
  const Case notched = read_case(testing::config("materials/strain_softening_bar.toml"));
  CHECK(testing::simulation<2, LinearShape>(notched).graph().wiring().describe() ==
        scheme_named("usl").wiring.describe());
}

TEST_CASE("the graph runs each stage node once per step, for many steps") {
  const Case c = read_case(testing::config("uniaxial_stress/case2_musl.toml"));
  std::atomic<int> calls{0};
  auto sim = testing::simulation<3, LinearShape>(c, [&](Stage) { ++calls; });
  for (int i = 0; i < 50; ++i) sim.advance();
  CHECK(calls == 50 * 8);
  CHECK(sim.system().step == 50);
  CHECK(sim.system().t == doctest::Approx(0.05).epsilon(1e-12));
}

namespace {

// The stages of one step of the slab conduction case (a transport scene)
// under `scheme`.
std::vector<Stage> recorded_transport_order(const std::string& scheme, bool serial) {
  const Case c = read_case(testing::config("verification/slab_conduction.toml"), {"analysis.scheme=" + scheme});
  std::mutex mutex;
  std::vector<Stage> order;
  auto sim = testing::simulation<1, LinearShape>(c, [&](Stage s) {
    std::lock_guard lock(mutex);
    order.push_back(s);
  });
  serial ? sim.advance_serial() : sim.advance();
  return order;
}

// The transport stages in their order, all before `join`; the other stages
// in the order of the mechanical wiring.
void check_transport_order(const std::vector<Stage>& got, const std::vector<Stage>& mechanical, Stage join) {
  const std::vector<Stage> transport{Stage::transport_p2g, Stage::transport_flux, Stage::transport_update,
                                     Stage::transport_g2p};
  std::vector<Stage> got_transport, got_mechanical;
  for (Stage s : got) (std::ranges::find(transport, s) != transport.end() ? got_transport : got_mechanical).push_back(s);
  CHECK(got_transport == transport);
  check_order(got_mechanical, mechanical, 2);
  const auto last_transport = std::ranges::find(got, Stage::transport_g2p) - got.begin();
  const auto first_join = std::ranges::find(got, join) - got.begin();
  CHECK(last_transport < first_join);
}

}  // namespace

TEST_CASE("the transport branch: beside the momentum stages, joining before the first g2p node") {
  using enum Stage;
  const std::string branch = " || transport_p2g -> transport_flux -> transport_update -> transport_g2p -> ";
  CHECK(with_transport(scheme_named("usl").wiring).describe() ==
        "p2g_momentum & p2g_force -> grid_velocity -> grid_integrate -> g2p_motion & g2p_stress" + branch +
            "g2p_motion & g2p_stress");
  CHECK(with_transport(scheme_named("usf").wiring).describe() ==
        "p2g_momentum -> grid_velocity -> g2p_stress -> p2g_force -> grid_integrate -> g2p_motion" + branch +
            "g2p_stress");
  CHECK(with_transport(scheme_named("musl").wiring).describe() ==
        "p2g_momentum & p2g_force -> grid_velocity -> grid_integrate -> g2p_motion -> remap -> grid_velocity -> "
        "g2p_stress" + branch + "g2p_motion");
  // One after the other (bench/): the transport chain, then the mechanics.
  CHECK(with_transport(scheme_named("usl").wiring, TransportBranch::before).describe() ==
        "transport_p2g -> transport_flux -> transport_update -> transport_g2p -> p2g_momentum & p2g_force -> "
        "grid_velocity -> grid_integrate -> g2p_motion & g2p_stress");
  for (bool serial : {false, true}) {
    CAPTURE(serial);
    check_transport_order(recorded_transport_order("usl", serial),
                          {p2g_momentum, p2g_force, grid_velocity, grid_integrate, g2p_motion, g2p_stress}, g2p_motion);
    check_transport_order(recorded_transport_order("usf", serial),
                          {p2g_momentum, grid_velocity, g2p_stress, p2g_force, grid_integrate, g2p_motion}, g2p_stress);
    check_transport_order(recorded_transport_order("musl", serial),
                          {p2g_momentum, p2g_force, grid_velocity, grid_integrate, g2p_motion, remap, grid_velocity,
                           g2p_stress},
                          g2p_motion);
  }
  // A scene without transport keeps the scheme's wiring: no branch.
  const Case plain = read_case(testing::config("uniaxial_stress/case1_usl.toml"));
  CHECK(testing::simulation<3, LinearShape>(plain).graph().wiring().nodes.size() == 4);
}

TEST_CASE("the transport branch and the momentum stages run at the same time") {
  // On 2 threads, transport_p2g and p2g_momentum each wait (up to 10 s) for
  // the other to have started: they meet only if the graph runs them side
  // by side.
  tbb::global_control two(tbb::global_control::max_allowed_parallelism, 2);
  const Case c = read_case(testing::config("verification/slab_conduction.toml"));
  std::atomic<bool> transport_started{false}, momentum_started{false}, met{true};
  auto wait_for = [&](std::atomic<bool>& other) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (!other.load()) {
      if (std::chrono::steady_clock::now() > deadline) {
        met = false;
        return;
      }
      std::this_thread::yield();
    }
  };
  auto sim = testing::simulation<1, LinearShape>(c, [&](Stage s) {
    if (s == Stage::transport_p2g) {
      transport_started = true;
      wait_for(momentum_started);
    } else if (s == Stage::p2g_momentum) {
      momentum_started = true;
      wait_for(transport_started);
    }
  });
  sim.advance();
  CHECK(transport_started);
  CHECK(momentum_started);
  CHECK(met);
}

TEST_CASE("the graph refuses a wiring that lets stages touching the same data run at the same time") {
  // Every wiring the engine builds passes: each scheme, with the transport
  // branch, with nonlocal_settle, with both.
  for (const Scheme& s : schemes()) {
    CHECK_NOTHROW(s.wiring.check_disjoint());
    CHECK_NOTHROW(with_transport(s.wiring).check_disjoint());
    CHECK_NOTHROW(with_nonlocal_settle(s.wiring).check_disjoint());
    CHECK_NOTHROW(with_transport(with_nonlocal_settle(s.wiring)).check_disjoint());
  }
  using enum Stage;
  // USL with the edge from the p2g node to grid_velocity left out: the
  // grid velocity would be computed from a momentum still being mapped.
  Wiring usl;
  usl.nodes = {{p2g_momentum, p2g_force}, {grid_velocity}, {grid_integrate}, {g2p_motion, g2p_stress}};
  usl.edges = {{1, 2}, {2, 3}, {0, 2}};
  CHECK_THROWS_WITH_AS(StepGraph(usl, [](int) {}),
                       doctest::Contains("\"p2g_momentum & p2g_force\" and \"grid_velocity\" run at the same time, "
                                         "but one writes what the other reads or writes (grid_momentum)"),
                       std::logic_error);
  // The transport branch without its join: transport_p2g would read the
  // positions while g2p_motion moves the particles.
  Wiring unjoined = scheme_named("usl").wiring;
  const int first = static_cast<int>(unjoined.nodes.size());
  for (Stage s : {transport_p2g, transport_flux, transport_update, transport_g2p}) unjoined.nodes.push_back({s});
  for (int i = first; i + 1 < static_cast<int>(unjoined.nodes.size()); ++i) unjoined.edges.emplace_back(i, i + 1);
  CHECK_THROWS_WITH_AS(StepGraph(unjoined, [](int) {}),
                       doctest::Contains("\"g2p_motion & g2p_stress\" and \"transport_p2g\""), std::logic_error);
}
