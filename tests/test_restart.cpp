// Checkpoint and restart (docs/guide/checkpoint_restart.md): a run that
// restarts from a checkpoint at step K writes, from K on, the same results
// as a run that was never stopped, to the last bit. Checked with the
// program itself (run, --restart, SIGINT, sweeps) on cases with every kind
// of carried state: von_mises plastic strain, mohr_coulomb plastic strains,
// strain_softening damage and dissipated energy, orthotropic material axes,
// every shape function,
// particle re-sorts (the memory order changes), dt = "auto" (dt and t carry),
// a reference's error sums, constraint reactions and the blow-up guard's last
// good state. The step files are compared dataset by dataset, byte for
// byte, through results.h5, and with HDF5's own h5diff; timeseries.csv as
// text.
#include <doctest/doctest.h>
#include <hdf5.h>
#include <signal.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <numbers>
#include <string>
#include <thread>
#include <vector>

#include "engine/state_records.hpp"
#include "io/results/checkpoint_file.hpp"
#include "materials/material.hpp"
#include "run_program.hpp"

namespace fs = std::filesystem;
using namespace flowmpm;
using namespace flowmpm::testing;

namespace {

fs::path config_file(const std::string& relative) { return fs::path(FLOWMPM_SOURCE_DIR) / "configs" / relative; }

// The step groups of a results.h5, flattened: "<group>@<attribute>" and
// "<group>/<dataset>" -> the stored bytes.
herr_t add_name(hid_t, const char* name, const H5L_info_t*, void* names) {
  static_cast<std::vector<std::string>*>(names)->push_back(name);
  return 0;
}
std::vector<std::string> links_of(hid_t group) {
  std::vector<std::string> names;
  hsize_t index = 0;
  H5Literate(group, H5_INDEX_NAME, H5_ITER_INC, &index, add_name, &names);
  return names;
}
std::map<std::string, std::string> step_contents(const fs::path& file) {
  std::map<std::string, std::string> contents;
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  REQUIRE(f >= 0);
  const hid_t steps = H5Gopen2(f, "/steps", H5P_DEFAULT);
  for (const std::string& step : links_of(steps)) {
    const hid_t group = H5Gopen2(steps, step.c_str(), H5P_DEFAULT);
    for (const char* attribute : {"time", "step"}) {
      const hid_t a = H5Aopen(group, attribute, H5P_DEFAULT);
      const hid_t type = H5Aget_type(a);
      std::string bytes(H5Tget_size(type), '\0');
      H5Aread(a, type, bytes.data());
      contents[step + "@" + attribute] = bytes;
      H5Tclose(type);
      H5Aclose(a);
    }
    for (const std::string& name : links_of(group)) {
      const hid_t d = H5Dopen2(group, name.c_str(), H5P_DEFAULT);
      const hid_t type = H5Dget_type(d), space = H5Dget_space(d);
      std::string bytes(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)) * H5Tget_size(type), '\0');
      if (!bytes.empty()) H5Dread(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, bytes.data());
      contents[step + "/" + name] = bytes;
      H5Sclose(space);
      H5Tclose(type);
      H5Dclose(d);
    }
    H5Gclose(group);
  }
  H5Gclose(steps);
  H5Fclose(f);
  return contents;
}

// h5diff's exit status: 0 when the files (or their `object`s) hold the same
// objects, attributes and values, the step files that results.h5 links
// included (--follow-symlinks; without it h5diff compares the links' file
// names only).
int h5diff(const fs::path& a, const fs::path& b, const std::string& object = {}) {
  std::vector<std::string> argv{"/usr/bin/h5diff", "--follow-symlinks", a.string(), b.string()};
  if (!object.empty()) argv.insert(argv.end(), {object, object});
  return wait_for(start_program(argv, fs::current_path())).status;
}

// The step of the checkpoint in `dir`, and the particle sorts before it.
struct CheckpointAt {
  std::int64_t step = -1, sorts = -1;
  double t = 0.0;
};
CheckpointAt checkpoint_in(const fs::path& dir) {
  const StateRecords records = read_checkpoint(dir / checkpoint_file_name);
  const StateReader read(records);
  CheckpointAt at;
  read("clock.step", at.step);
  read("clock.sorts", at.sorts);
  read("clock.t", at.t);
  return at;
}

// A column of the checkpoint in `dir`, e.g. "batch.0.state".
template <class T>
std::vector<T> checkpoint_column(const fs::path& dir, const std::string& record) {
  std::vector<T> values;
  StateReader(read_checkpoint(dir / checkpoint_file_name))(record, values);
  return values;
}

// The particle sorts of the run's last session ("done: ... particles sorted N times").
long sorts_at_end(const fs::path& dir) {
  const std::string log = read_text(dir / "run.log");
  const auto at = log.rfind("particles sorted ");
  REQUIRE(at != std::string::npos);
  return std::stol(log.substr(at + 17));
}

std::vector<std::string> with_sets(std::vector<std::string> args, const std::vector<std::string>& sets) {
  for (const std::string& s : sets) args.insert(args.end(), {"--set", s});
  return args;
}

// Runs `file` uninterrupted (in dir/uninterrupted), and again with a
// checkpoint every `k` steps (dir/restarted), then restarts the second run
// from its checkpoint at step `k`: both must give the same results.h5,
// results.xdmf and timeseries.csv. `status`: the runs' exit status (2 for a
// blow-up, whose run writes no output step after k).
void check_restart_matches(const TempDir& dir, const fs::path& file, std::int64_t k,
                           const std::vector<std::string>& sets = {}, int status = 0) {
  const fs::path plain = dir.path / "uninterrupted", restarted = dir.path / "restarted";
  const auto run = [&](std::vector<std::string> args) {
    const Result r = run_flowmpm(with_sets(args, sets), dir.path);
    CHECK_MESSAGE(r.status == status, r.output);
    return r;
  };
  const std::string every = "output.checkpoint_every=" + std::to_string(k);
  run({"run", file.string(), "--threads", "2", "--output", plain.string()});
  run({"run", file.string(), "--threads", "2", "--output", restarted.string(), "--set", every});
  const CheckpointAt at = checkpoint_in(restarted);
  CHECK(at.step == k);
  const auto before = step_contents(restarted / "results.h5");
  run({"run", file.string(), "--threads", "1", "--restart", restarted.string(), "--set", every});
  CHECK(contains(read_text(restarted / "run.log"), "restart from the checkpoint at step " + std::to_string(k)));

  // The restart rewrote the steps after k (removed, then computed again),
  // and every step equals the uninterrupted run's, byte for byte.
  const auto expected = step_contents(plain / "results.h5");
  const auto got = step_contents(restarted / "results.h5");
  REQUIRE(expected.size() == got.size());
  std::size_t after_k = 0;
  for (const auto& [key, bytes] : expected) {
    CAPTURE(key);
    REQUIRE(got.count(key) == 1);
    CHECK(got.at(key) == bytes);
    after_k += std::stoll(key.substr(0, 8)) > k;
  }
  CHECK((after_k > 0 || status == 2));
  CHECK(before == got);  // and as the first run wrote them before the restart
  CHECK(h5diff(plain / "results.h5", restarted / "results.h5") == 0);
  CHECK(read_text(plain / "timeseries.csv") == read_text(restarted / "timeseries.csv"));
  CHECK(read_text(plain / "results.xdmf") == read_text(restarted / "results.xdmf"));
}

}  // namespace

TEST_CASE("von_mises with B-spline 3 and dt = auto: re-sorts before and after the checkpoint") {
  // Two blocks fly 0.4 m (8 cells) into each other and yield: plastic
  // strain, re-sorts, and a time step that changes every step.
  TempDir dir("flowmpm_restart");
  const fs::path file = dir.path / "von_mises_impact.toml";
  write_text(file, R"(
[analysis]
dimension = 2
shape_function = "bspline3"
dt = "auto"
end_time = 0.07
[grid]
origin = [0.0, 0.0]
cell_size = 0.05
cells = [60, 20]
[materials.metal]
type = "von_mises"
density = 1000.0
youngs_modulus = 1e6
poisson_ratio = 0.3
yield_stress = 1e5
hardening = "linear"
hardening_modulus = 1e5
[[bodies]]
material = "metal"
min = [0.3, 0.3]
max = [0.8, 0.7]
particles_per_cell = 2
velocity = [10.0, 0.0]
[[bodies]]
material = "metal"
min = [1.6, 0.3]
max = [2.1, 0.7]
particles_per_cell = 2
velocity = [-10.0, 0.0]
[output]
every = 10
fields = ["position", "velocity", "stress", "strain", "plastic_strain", "volume"]
)");
  check_restart_matches(dir, file, 75);
  const fs::path restarted = dir.path / "restarted";
  // Sorted again before the checkpoint (its memory order is not the initial
  // one) and after it.
  const CheckpointAt at = checkpoint_in(restarted);
  CHECK(at.sorts >= 2);
  CHECK(sorts_at_end(restarted) > at.sorts);
  // The metal has yielded by then: the checkpoint carries plastic strain.
  double eps_p = 0.0;
  for (const VonMises::State& s : checkpoint_column<VonMises::State>(restarted, "batch.0.state"))
    eps_p = std::max(eps_p, s.eps_p);
  CHECK(eps_p > 1e-3);
}

TEST_CASE("strain_softening with uGIMP: damage and dissipated energy carry") {
  // The notched bar of configs/materials/strain_softening_bar.toml in 1D,
  // pulled at both ends until the notch softens (issue: material state).
  TempDir dir("flowmpm_restart");
  const fs::path file = dir.path / "softening_bar.toml";
  write_text(file, R"(
[analysis]
dimension = 1
shape_function = "gimp"
dt = 3.833259389999639e-07
steps = 126
[grid]
origin = [-0.10317460317460318]
cell_size = 0.0031746031746031746
cells = [65]
[materials.concrete]
type = "strain_softening"
density = 2400.0
youngs_modulus = 30e9
poisson_ratio = 0.2
initiation_strain = 1e-4
fracture_energy = 2.5
nonlocal_length = 0
[materials.notch]
type = "strain_softening"
density = 2400.0
youngs_modulus = 30e9
poisson_ratio = 0.2
initiation_strain = 0.9e-4
fracture_energy = 2.5
nonlocal_length = 0
[[bodies]]
material = "concrete"
min = [-0.1]
max = [-0.0015873015873015873]
particles_per_cell = 1
[[bodies]]
material = "notch"
min = [-0.0015873015873015873]
max = [0.0015873015873015873]
particles_per_cell = 1
[[bodies]]
material = "concrete"
min = [0.0015873015873015873]
max = [0.1]
particles_per_cell = 1
[[node_sets]]
name = "left"
plane = "x"
at = -0.1
velocity = { x = [[0.0, 0.0], [5.366563145999496e-06, -0.16793786053180504]] }
[[node_sets]]
name = "right"
plane = "x"
at = 0.1
velocity = { x = [[0.0, 0.0], [5.366563145999496e-06, 0.16793786053180504]] }
[output]
every = 10
fields = ["position", "stress", "strain", "damage", "dissipated_energy"]
)");
  check_restart_matches(dir, file, 95);
  // The notch has softened by then: the checkpoint carries damage.
  double dissipated = 0.0;
  for (const StrainSoftening::State& s : checkpoint_column<StrainSoftening::State>(dir.path / "restarted", "batch.1.state"))
    dissipated = std::max(dissipated, s.dissipated);
  CHECK(dissipated > 0.0);
}

TEST_CASE("orthotropic with B-spline 2 and MUSL: the material axes rotate and carry") {
  // Two blocks collide off-centre and spin: the axes rotate with them.
  TempDir dir("flowmpm_restart");
  const fs::path file = dir.path / "orthotropic_spin.toml";
  write_text(file, R"(
[analysis]
dimension = 2
scheme = "musl"
shape_function = "bspline2"
dt = 2e-4
end_time = 0.05
[grid]
origin = [0.0, 0.0]
cell_size = 0.05
cells = [44, 24]
[materials.fibre]
type = "orthotropic"
density = 1000.0
Ex = 2e6
Ey = 1e6
Ez = 1e6
Gxy = 4e5
Gxz = 4e5
Gyz = 3e5
nuxy = 0.3
nuxz = 0.3
nuyz = 0.3
[[bodies]]
material = "fibre"
min = [0.3, 0.3]
max = [0.8, 0.7]
particles_per_cell = 2
velocity = [8.0, 2.0]
material_axes = [30.0]
[[bodies]]
material = "fibre"
min = [1.3, 0.5]
max = [1.8, 0.9]
particles_per_cell = 2
velocity = [-8.0, -2.0]
material_axes = [-20.0]
[output]
every = 25
)");
  check_restart_matches(dir, file, 130);
  CHECK(checkpoint_in(dir.path / "restarted").sorts >= 2);
  // The blocks have turned by then: the axes carried are not the initial 30 degrees.
  double turned = 0.0;
  for (const Orthotropic::State& s : checkpoint_column<Orthotropic::State>(dir.path / "restarted", "batch.0.state"))
    turned = std::max(turned, std::abs(2.0 * std::atan2(s.axes.z(), s.axes.w()) * 180.0 / std::numbers::pi - 30.0));
  CHECK(turned > 0.1);
}

TEST_CASE("neo_hookean: the deformation gradient carries") {
  // Sulsky's disks of neo-Hookean material, checkpointed during the impact
  // (t = 1.7 s; they meet near 1.6 s), to 2.2 s; volume_ratio (det F) is
  // written.
  TempDir dir("flowmpm_restart");
  check_restart_matches(dir, config_file("benchmarks/sulsky_disks.toml"), 1700,
                        {"materials.elastic.type=neo_hookean", "analysis.end_time=2.2", "output.every=100",
                         "output.fields=[\"position\",\"stress\",\"volume_ratio\"]"});
}

TEST_CASE("linear shape functions: a reference's error sums, and reactions, carry") {
  TempDir dir("flowmpm_restart");
  // The vibrating bar with its axial_vibration reference (error columns).
  check_restart_matches(dir, config_file("verification/bar_vibration_small.toml"), 400,
                        {"analysis.shape_function=linear", "output.every=40"});
  const std::string csv = read_text(dir.path / "restarted" / "timeseries.csv");
  CHECK(contains(csv, "error.stress"));
}

TEST_CASE("APIC: the affine velocity carries; XPIC carries nothing and continues the same") {
  // The colliding blocks of configs/hard, checkpointed during the impact
  // (step 100 of 200), MUSL (its remap maps with the affine velocity too).
  TempDir apic("flowmpm_restart"), xpic("flowmpm_restart");
  check_restart_matches(apic, config_file("hard/impact_2d.toml"), 100,
                        {"analysis.velocity_update=\"apic\"", "analysis.scheme=\"musl\"",
                         "analysis.shape_function=\"bspline2\""});
  CHECK(!checkpoint_column<std::array<double, 4>>(apic.path / "restarted", "batch.0.affine_velocity").empty());
  check_restart_matches(xpic, config_file("hard/impact_2d.toml"), 100, {"analysis.velocity_update=\"xpic\""});
}

TEST_CASE("von_mises plate with loaded node sets: reactions and plastic strain carry") {
  TempDir dir("flowmpm_restart");
  check_restart_matches(dir, config_file("materials/von_mises_plate.toml"), 2600,
                        {"output.every=250", "output.fields=[\"position\",\"stress\",\"plastic_strain\"]"});
}

TEST_CASE("mohr_coulomb biaxial block: the plastic shear and volumetric strains and the dissipated energy carry") {
  // Checkpointed at step 1500 of 2400, on the plateau where every particle flows.
  TempDir dir("flowmpm_restart");
  check_restart_matches(dir, config_file("materials/mohr_coulomb_biaxial.toml"), 1500,
                        {"output.every=200",
                         "output.fields=[\"position\",\"stress\",\"plastic_shear_strain\","
                         "\"plastic_volumetric_strain\",\"dissipated_energy\"]"});
}

TEST_CASE("transport: temperature, concentration, their pending expansion and the energy balance carry") {
  // Solvent diffusing into a held bar that swells (the expansion work in
  // the energy balance, the swelling_slab reference's sums), and heat
  // conducted through a slab (slab_transport's sums).
  TempDir swelling("flowmpm_restart"), conduction("flowmpm_restart");
  check_restart_matches(swelling, config_file("verification/swelling_bar.toml"), 1500);
  CHECK(contains(read_text(swelling.path / "restarted" / "timeseries.csv"), "error.concentration"));
  check_restart_matches(conduction, config_file("verification/slab_conduction.toml"), 64);
}

TEST_CASE("loads and damping: the pressure's work and the damping's dissipation carry") {
  // The thick cylinder of configs/benchmarks: a pressure on the inner
  // surface (its faces follow their particles through re-sorts) and local
  // damping; load_work and dissipated_energy are columns of timeseries.csv.
  TempDir dir("flowmpm_restart");
  check_restart_matches(dir, config_file("benchmarks/thick_cylinder.toml"), 1500, {"output.every=250"});
}

TEST_CASE("contact: the contact forces, the rigid body's force and work, and the contact's work carry") {
  // The block sliding on the rigid incline of configs/contact, checkpointed
  // mid-slide; the rigid floor's particles are re-sorted as the block
  // moves. timeseries.csv has the contact columns.
  TempDir dir("flowmpm_restart");
  check_restart_matches(dir, config_file("contact/incline_block_rigid.toml"), 3000,
                        {"output.every=1000", "analysis.end_time=0.15"});  // 4400 steps
}

TEST_CASE("axisymmetric: the hoop terms, the axis, a pressure and heat with its expansion carry") {
  // Lame's thick cylinder of configs/axisymmetric (a pressure on r-weighted
  // faces, the hoop force and strain rate) and the heated solid cylinder
  // (the axis node set, conduction weighted by r, the thermal expansion);
  // timeseries.csv's columns are labelled rr zz tt and reactions carry
  // their full-turn column.
  TempDir lame("flowmpm_restart"), heated("flowmpm_restart");
  check_restart_matches(lame, config_file("axisymmetric/thick_cylinder.toml"), 1000, {"output.every=250"});
  CHECK(contains(read_text(lame.path / "restarted" / "timeseries.csv"), ".stress_tt"));
  check_restart_matches(heated, config_file("axisymmetric/heated_cylinder.toml"), 1000,
                        {"output.every=250", "analysis.end_time=1.0"});  // 2000 steps, into the ramp
}

TEST_CASE("an imperfect interface: its stored energy and the initial positions it measures from carry") {
  // The lap shear of configs/contact at 0.5 mm cells, checkpointed during
  // the pull: timeseries.csv has the interface's energy (part of the
  // stored energy) and the lap_shear reference's error.
  TempDir dir("flowmpm_restart");
  check_restart_matches(dir, config_file("contact/lap_shear_interface.toml"), 1000,
                        {"grid.cell_size=0.0005", "grid.cells=[62, 6]"});
  CHECK(contains(read_text(dir.path / "restarted" / "timeseries.csv"), "contact.lower~upper.interface_energy"));
}

TEST_CASE("nonlocal strain softening: the averages and the damage carry") {
  // The symmetric bar of configs/materials: a band opens through the
  // nonlocal averages (weights rebuilt after the restart from x0, carried);
  // the checkpoint at step 240 of 442 is taken just after the onset (L / c,
  // step 232), while the band opens.
  TempDir dir("flowmpm_restart");
  check_restart_matches(dir, config_file("materials/strain_softening_symmetric_bar.toml"), 240,
                        {"output.fields=[\"position\",\"stress\",\"damage\"]"});
}

TEST_CASE("a blow-up after the restart writes the same last good state") {
  // The bar of test_hard_cases that gravity pushes past the guard at step
  // 240: the last good state, kept at step 230 (every 10 steps), carries
  // across the checkpoint at step 235.
  TempDir dir("flowmpm_restart");
  const fs::path file = dir.path / "blow_up.toml";
  write_text(file, R"(
[analysis]
dimension = 1
dt = 6.25e-4
end_time = 0.5
gravity = [-100.0]
guard_speed_factor = 1.5
[grid]
origin = [-3.5]
cell_size = 0.03125
cells = [150]
[materials.bar]
type = "linear_elastic"
density = 1.0
youngs_modulus = 100.0
poisson_ratio = 0.0
[[bodies]]
material = "bar"
min = [0.0]
max = [1.0]
particles_per_cell = 2
[output]
every = 50
)");
  check_restart_matches(dir, file, 235, {}, 2);
  // The restart removed step 230 (after the last output step, 200) and
  // wrote it again from the state the checkpoint carried.
  CHECK(contains(read_text(dir.path / "restarted" / "run.log"),
                 "restart from the checkpoint at step 235 (t = 0.146875 s), " +
                     (dir.path / "restarted" / checkpoint_file_name).string() +
                     "; results.h5, results.xdmf and timeseries.csv continue after its output step 200"));
  CHECK(contains(read_text(dir.path / "restarted" / "run.log"), "the last good state (step 230"));
}

namespace {

// Two elastic blocks colliding: 5,600 particles for 500 steps, a quarter
// of a second or more, long enough for an interrupt to land in its middle.
constexpr const char* long_case = R"(
name = "long_impact"
[analysis]
dimension = 2
dt = 2e-4
end_time = 0.1
[grid]
origin = [0.0, 0.0]
cell_size = 0.02
cells = [100, 40]
[materials.rubber]
type = "linear_elastic"
density = 1000.0
youngs_modulus = 1e6
poisson_ratio = 0.3
[[bodies]]
material = "rubber"
min = [0.2, 0.2]
max = [0.9, 0.6]
particles_per_cell = 2
velocity = [2.0, 0.0]
[[bodies]]
material = "rubber"
min = [1.1, 0.2]
max = [1.8, 0.6]
particles_per_cell = 2
velocity = [-2.0, 0.0]
[output]
every = 25
)";

// The long case, and its uninterrupted run (once per test program).
struct LongRun {
  TempDir dir{"flowmpm_restart_long"};
  fs::path file = dir.path / "long_impact.toml", plain = dir.path / "uninterrupted";
  LongRun() {
    write_text(file, long_case);
    const Result r = run_flowmpm({"run", file.string(), "--threads", "1", "--output", plain.string()}, dir.path);
    REQUIRE_MESSAGE(r.status == 0, r.output);
  }
};
const LongRun& long_run() {
  static const LongRun run;
  return run;
}

// Starts flowmpm with `args`, sends it SIGINT once `csv` has more than
// `rows` rows (or after 60 s), and waits for it to end.
Result interrupt_after(const std::vector<std::string>& args, const fs::path& cwd, const fs::path& csv,
                       std::size_t rows) {
  std::vector<std::string> argv{FLOWMPM_EXECUTABLE};
  argv.insert(argv.end(), args.begin(), args.end());
  const Running program = start_program(argv, cwd);
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < give_up &&
         (!fs::exists(csv) || lines_of(read_text(csv)).size() <= rows + 1)) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  ::kill(program.pid, SIGINT);
  return wait_for(program);
}

// Every file of a directory with its contents.
std::map<std::string, std::string> files_of(const fs::path& dir) {
  std::map<std::string, std::string> files;
  if (!fs::exists(dir)) return files;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (entry.is_regular_file()) files[fs::relative(entry.path(), dir).string()] = read_text(entry.path());
  return files;
}

}  // namespace

TEST_CASE("Ctrl-C writes a checkpoint; --restart continues to the same results") {
  const LongRun& run = long_run();
  TempDir dir("flowmpm_restart");
  const fs::path cut = dir.path / "cut";
  const Result stopped = interrupt_after({"run", run.file.string(), "--threads", "1", "--output", cut.string()},
                                         dir.path, cut / "timeseries.csv", 3);
  REQUIRE_MESSAGE(stopped.status == 130, stopped.output);
  CHECK(contains(stopped.output, "continue it with flowmpm run " + run.file.string() + " --restart " + cut.string()));
  const CheckpointAt at = checkpoint_in(cut);
  MESSAGE("interrupted at step " << at.step << " of 500");
  CHECK(at.step >= 75);
  CHECK(at.step < 500);
  // The results up to the interrupted step are kept (the step itself too).
  char group[32];
  std::snprintf(group, sizeof group, "%08lld@step", static_cast<long long>(at.step));
  CHECK(step_contents(cut / "results.h5").count(group) == 1);

  const Result resumed = run_flowmpm({"run", run.file.string(), "--threads", "2", "--restart", cut.string()}, dir.path);
  REQUIRE_MESSAGE(resumed.status == 0, resumed.output);
  CHECK(step_contents(run.plain / "results.h5") == step_contents(cut / "results.h5"));
  CHECK(h5diff(run.plain / "results.h5", cut / "results.h5") == 0);
  CHECK(read_text(run.plain / "timeseries.csv") == read_text(cut / "timeseries.csv"));
  CHECK(read_text(run.plain / "results.xdmf") == read_text(cut / "results.xdmf"));
  // A run without checkpoint_every writes no checkpoint.
  CHECK_FALSE(fs::exists(run.plain / checkpoint_file_name));
}

TEST_CASE("an interrupted sweep resumes its case from the checkpoint") {
  const LongRun& run = long_run();
  TempDir dir("flowmpm_restart");
  write_text(dir.path / "sweep.toml", "base = \"" + run.file.string() +
                                          "\"\n[vary]\n\"analysis.end_time\" = [0.1, 0.01]\n");
  const std::vector<std::string> sweep{"sweep", "sweep.toml", "--threads", "1", "--output", "out"};
  const fs::path first = dir.path / "out" / "cases" / "000";
  const Result stopped = interrupt_after(sweep, dir.path, first / "timeseries.csv", 3);
  REQUIRE_MESSAGE(stopped.status == 130, stopped.output);
  CHECK(fs::exists(first / checkpoint_file_name));
  CHECK_FALSE(fs::exists(first / "sweep_row.txt"));
  const std::int64_t step = checkpoint_in(first).step;

  const Result resumed = run_flowmpm(sweep, dir.path);
  REQUIRE_MESSAGE(resumed.status == 0, resumed.output);
  CHECK(contains(read_text(first / "run.log"), "restart from the checkpoint at step " + std::to_string(step)));
  CHECK(step_contents(run.plain / "results.h5") == step_contents(first / "results.h5"));
  CHECK(h5diff(run.plain / "results.h5", first / "results.h5", "/steps") == 0);
  CHECK(read_text(run.plain / "timeseries.csv") == read_text(first / "timeseries.csv"));
  CHECK(contains(read_text(dir.path / "out" / "sweep.csv"), "completed"));
}

TEST_CASE("a restart that cannot be made says why in one line, exits 1 and writes nothing") {
  TempDir dir("flowmpm_restart");
  const std::string plate = config_file("materials/von_mises_plate.toml").string();
  const fs::path done = dir.path / "done";
  const std::vector<std::string> every{"--set", "output.checkpoint_every=2600"};
  const auto run = [&](const std::vector<std::string>& args) { return run_flowmpm(args, dir.path); };
  auto with_every = [&](std::vector<std::string> args) {
    args.insert(args.end(), every.begin(), every.end());
    return args;
  };
  REQUIRE(run(with_every({"run", plate, "--output", done.string()})).status == 0);
  const auto copy = [&](const std::string& name) {
    fs::copy(done, dir.path / name, fs::copy_options::recursive);
    return dir.path / name;
  };
  // Refused: exit 1, one line naming the problem, the directory unchanged.
  const auto refused = [&](const fs::path& restart_dir, const std::vector<std::string>& args, const std::string& why) {
    CAPTURE(why);
    const auto files = files_of(restart_dir);
    const Result r = run(args);
    CHECK(r.status == 1);
    CHECK(non_empty_lines(r.output).size() == 1);
    CHECK_MESSAGE(contains(r.output, why), r.output);
    CHECK(files_of(restart_dir) == files);
  };

  refused(dir.path / "nowhere", with_every({"run", plate, "--restart", (dir.path / "nowhere").string()}),
          "no checkpoint to restart from");
  CHECK_FALSE(fs::exists(dir.path / "nowhere"));
  const fs::path plain = dir.path / "plain";
  REQUIRE(run({"run", plate, "--output", plain.string()}).status == 0);
  refused(plain, {"run", plate, "--restart", plain.string()}, "no checkpoint to restart from");

  refused(done, {"run", plate, "--set", "output.checkpoint_every=2000", "--restart", done.string()},
          "a checkpoint of another case");

  const fs::path flipped = copy("flipped");
  {
    std::string bytes = read_text(flipped / checkpoint_file_name);
    bytes[bytes.size() / 2] ^= 1;
    write_text(flipped / checkpoint_file_name, bytes);
  }
  refused(flipped, with_every({"run", plate, "--restart", flipped.string()}), "a damaged checkpoint");
  const fs::path cut = copy("cut");
  fs::resize_file(cut / checkpoint_file_name, fs::file_size(cut / checkpoint_file_name) / 2);
  refused(cut, with_every({"run", plate, "--restart", cut.string()}), "a damaged checkpoint");

  const fs::path lost = copy("lost");
  fs::remove_all(lost / "steps");
  refused(lost, with_every({"run", plate, "--restart", lost.string()}),
          "steps holds 0 output steps up to step 2400, not the 7 the checkpoint was written after, so the run "
          "cannot continue from the checkpoint");
  const fs::path damaged = copy("damaged");
  write_text(damaged / "steps" / "00000400.h5", "not HDF5");
  refused(damaged, with_every({"run", plate, "--restart", damaged.string()}),
          "00000400.h5 does not open as a step file, so the run cannot continue from the checkpoint");
  const fs::path short_csv = copy("short_csv");
  write_text(short_csv / "timeseries.csv", lines_of(read_text(done / "timeseries.csv")).at(0) + "\n");
  refused(short_csv, with_every({"run", plate, "--restart", short_csv.string()}),
          "timeseries.csv: holds 0 rows up to step 2400, not the 7 the checkpoint was written after");

  const Result negative = run({"check", plate, "--set", "output.checkpoint_every=-5"});
  CHECK(negative.status == 1);
  CHECK_MESSAGE(contains(negative.output, "output.checkpoint_every: expected a number of steps >= 0 between checkpoints"),
                negative.output);

  const Result both = run(with_every({"run", plate, "--output", done.string(), "--restart", done.string()}));
  CHECK(both.status == 1);
  CHECK(contains(both.output, "--output excludes --restart"));

  // A run without --restart starts afresh and removes the old checkpoint.
  const Result fresh = run({"run", plate, "--output", done.string()});
  CHECK(fresh.status == 0);
  CHECK(contains(fresh.output, "this run starts afresh and replaces it"));
  CHECK_FALSE(fs::exists(done / checkpoint_file_name));
}

TEST_CASE("a sweep's case whose checkpoint does not fit starts afresh") {
  TempDir dir("flowmpm_restart");
  write_text(dir.path / "sweep.toml",
             "base = \"" + config_file("materials/von_mises_plate.toml").string() + "\"\noutput = \"out\"\n");
  const fs::path folder = dir.path / "out" / "cases" / "000";
  fs::create_directories(folder);
  write_text(folder / checkpoint_file_name, "not a checkpoint");
  const Result r = run_flowmpm({"sweep", "sweep.toml", "--threads", "1"}, dir.path);
  REQUIRE_MESSAGE(r.status == 0, r.output);
  const std::string log = read_text(folder / "run.log");
  CHECK(contains(log, "a damaged checkpoint"));
  CHECK(contains(log, "this run starts afresh and replaces it"));
  CHECK_FALSE(fs::exists(folder / checkpoint_file_name));
  CHECK(contains(read_text(folder / "sweep_row.txt"), "completed"));
}
