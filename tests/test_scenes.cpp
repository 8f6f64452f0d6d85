// Bodies of a scene (docs/guide/bodies.md): shapes filled on a lattice, set
// operations, particles from CSV and HDF5 files, overlapping bodies, and
// initial stress. Where a feature has an equivalent older form (a box
// shape and a box body, a file of a body's particles and the body, a
// per-particle value and a per-body one), the test asserts bit-identical
// particles or results; otherwise counts and values against closed forms.
#include <doctest/doctest.h>

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "discretisation/shapes/shape_functions.hpp"
#include "run_program.hpp"
#include "test_helpers.hpp"

using namespace flowmpm;

namespace {

// A 2D case on a 1 m x 1 m grid of 0.05 m cells; `bodies` holds the
// [[bodies]] tables (material "elastic").
std::string case_2d(const std::string& bodies, const std::string& extra = "", const std::string& analysis = "") {
  return "[analysis]\ndimension = 2\ndt = 1e-4\nsteps = 10\n" + analysis +
         "[grid]\norigin = [0.0, 0.0]\ncell_size = 0.05\ncells = [20, 20]\n"
         "[materials.elastic]\ntype = \"linear_elastic\"\ndensity = 1000.0\nyoungs_modulus = 1e6\npoisson_ratio = 0.3\n" +
         bodies + extra;
}

using Sim2 = Simulation<2, LinearShape>;

Sim2 build(const std::string& name, const std::string& text, const std::vector<std::string>& overrides = {}) {
  return testing::simulation<2, LinearShape>(testing::case_from_text(name, text, overrides));
}

// The particles of a system as sorted (x, y) pairs.
std::vector<std::pair<double, double>> positions(const Sim2& sim, int body = -1) {
  std::vector<std::pair<double, double>> xs;
  for (const auto& b : sim.system().batches) {
    if (body >= 0 && b.body != body) continue;
    for (const auto& x : b.x) xs.emplace_back(x[0], x[1]);
  }
  std::ranges::sort(xs);
  return xs;
}

double total_volume(const Sim2& sim, int body = -1) {
  double v = 0.0;
  for (const auto& b : sim.system().batches)
    if (body < 0 || b.body == body)
      for (double vp : b.volume) v += vp;
  return v;
}

// The message of the CaseError that reading or building `text` throws.
std::string rejection(const std::string& name, const std::string& text) {
  try {
    build(name, text);
  } catch (const CaseError& e) {
    return e.what();
  }
  return "";
}

std::string exact(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

}  // namespace

TEST_CASE("a box shape fills the particles of a box body, bit for bit, as the box body always did") {
  // The box is not a whole number of spacings (0.53 / 0.025 = 21.2): the
  // lattice is centred in it, with a margin on each side.
  const std::string legacy = "[[bodies]]\nmaterial = \"elastic\"\nmin = [0.2, 0.11]\nmax = [0.73, 0.6]\nspacing = 0.025\n";
  const std::string shaped =
      "[[bodies]]\nmaterial = \"elastic\"\nspacing = 0.025\nshape = { type = \"box\", min = [0.2, 0.11], max = [0.73, "
      "0.6] }\n";
  const Sim2 a = build("box_legacy", case_2d(legacy)), b = build("box_shape", case_2d(shaped));
  CHECK(positions(a) == positions(b));
  // The formula of the box body before shapes existed, evaluated here.
  std::vector<std::pair<double, double>> expected;
  const double lo[2] = {0.2, 0.11}, hi[2] = {0.73, 0.6}, s = 0.025;
  int count[2];
  double margin[2];
  for (int d = 0; d < 2; ++d) {
    count[d] = std::max(1, static_cast<int>(std::floor((hi[d] - lo[d]) / s + 1e-9)));
    margin[d] = 0.5 * ((hi[d] - lo[d]) - count[d] * s);
  }
  for (int j = 0; j < count[1]; ++j)
    for (int i = 0; i < count[0]; ++i)
      expected.emplace_back(lo[0] + margin[0] + (i + 0.5) * s, lo[1] + margin[1] + (j + 0.5) * s);
  std::ranges::sort(expected);
  CHECK(positions(b) == expected);
  for (const auto& batch : b.system().batches)
    for (double v : batch.volume) CHECK(v == s * s);
}

TEST_CASE("a disk holds exactly the lattice points inside it, each with the lattice cell's volume") {
  // Disk of radius 0.2 m about (0.5, 0.5), spacing 0.025 m: its bounds are
  // 16 spacings wide, so the lattice is aligned with them.
  const Sim2 sim = build("disk", case_2d("[[bodies]]\nmaterial = \"elastic\"\nparticles_per_cell = 2\n"
                                         "shape = { type = \"sphere\", center = [0.5, 0.5], radius = 0.2 }\n"));
  std::size_t inside = 0;
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 16; ++i)
      inside += std::hypot(0.3 + (i + 0.5) * 0.025 - 0.5, 0.3 + (j + 0.5) * 0.025 - 0.5) <= 0.2;
  CHECK(positions(sim).size() == inside);
  for (const auto& [x, y] : positions(sim)) CHECK(std::hypot(x - 0.5, y - 0.5) <= 0.2);
  // The lattice cells of the points inside cover the disk to within a cell
  // along its perimeter: |V - pi r^2| <= 2 pi r s.
  const double area = std::numbers::pi * 0.04;
  CHECK(std::abs(total_volume(sim) - area) <= 2 * std::numbers::pi * 0.2 * 0.025);
  CHECK(std::abs(total_volume(sim) - area) / area < 0.05);  // measured 3.5 %, 8 spacings per radius
}

TEST_CASE("set operations: a plate with a hole, a ring and an intersection are one body each") {
  const std::string plate =
      "[[bodies]]\nname = \"plate\"\nmaterial = \"elastic\"\nparticles_per_cell = 2\n[bodies.shape]\ntype = "
      "\"difference\"\n[[bodies.shape.parts]]\ntype = \"box\"\nmin = [0.1, 0.1]\nmax = [0.9, 0.9]\n"
      "[[bodies.shape.parts]]\ntype = \"sphere\"\ncenter = [0.5, 0.5]\nradius = 0.2\n";
  const Sim2 with_hole = build("plate_hole", case_2d(plate));
  const Sim2 box = build("plate_full", case_2d("[[bodies]]\nmaterial = \"elastic\"\nparticles_per_cell = 2\n"
                                               "min = [0.1, 0.1]\nmax = [0.9, 0.9]\n"));
  const Sim2 disk = build("plate_disk", case_2d("[[bodies]]\nmaterial = \"elastic\"\nparticles_per_cell = 2\n"
                                                "shape = { type = \"sphere\", center = [0.5, 0.5], radius = 0.2 }\n"));
  // The plate is filled on the box's lattice: the box's points outside the
  // disk, point for point; as many as the box's less the disk's (the two
  // lattices are the same points, both from grid lines).
  std::vector<std::pair<double, double>> hole;
  for (const auto& [x, y] : positions(box))
    if (std::hypot(x - 0.5, y - 0.5) > 0.2) hole.emplace_back(x, y);
  CHECK(positions(with_hole) == hole);
  CHECK(positions(with_hole).size() == positions(box).size() - positions(disk).size());

  // A ring, 0.1 m < r <= 0.3 m: the points of the lattice between the radii.
  const Sim2 ring = build("ring", case_2d("[[bodies]]\nmaterial = \"elastic\"\nparticles_per_cell = 2\n"
                                          "[bodies.shape]\ntype = \"difference\"\n[[bodies.shape.parts]]\n"
                                          "type = \"sphere\"\ncenter = [0.5, 0.5]\nradius = 0.3\n"
                                          "[[bodies.shape.parts]]\ntype = \"sphere\"\ncenter = [0.5, 0.5]\nradius = 0.1\n"));
  for (const auto& [x, y] : positions(ring)) {
    CHECK(std::hypot(x - 0.5, y - 0.5) <= 0.3);
    CHECK(std::hypot(x - 0.5, y - 0.5) > 0.1);
  }
  const double ring_area = std::numbers::pi * (0.09 - 0.01);
  CHECK(std::abs(total_volume(ring) - ring_area) / ring_area < 0.03);

  // A quarter disk: the intersection of a disk and a box.
  const Sim2 quarter = build("quarter", case_2d("[[bodies]]\nmaterial = \"elastic\"\nparticles_per_cell = 2\n"
                                                "[bodies.shape]\ntype = \"intersection\"\n[[bodies.shape.parts]]\n"
                                                "type = \"sphere\"\ncenter = [0.1, 0.1]\nradius = 0.4\n"
                                                "[[bodies.shape.parts]]\ntype = \"box\"\nmin = [0.1, 0.1]\nmax = [0.9, 0.9]\n"));
  const double quarter_area = std::numbers::pi * 0.16 / 4;
  CHECK(std::abs(total_volume(quarter) - quarter_area) / quarter_area < 0.03);

  // A union of two overlapping boxes holds each lattice point once.
  const Sim2 cross = build("cross", case_2d("[[bodies]]\nmaterial = \"elastic\"\nparticles_per_cell = 2\n"
                                            "[bodies.shape]\ntype = \"union\"\n[[bodies.shape.parts]]\n"
                                            "type = \"box\"\nmin = [0.1, 0.4]\nmax = [0.9, 0.6]\n[[bodies.shape.parts]]\n"
                                            "type = \"box\"\nmin = [0.4, 0.1]\nmax = [0.6, 0.9]\n"));
  CHECK(total_volume(cross) == doctest::Approx(0.8 * 0.2 * 2 - 0.2 * 0.2).epsilon(1e-12));
}

TEST_CASE("a 3D cylinder holds pi r^2 L of material, to the lattice resolution") {
  const Case c = testing::case_from_text(
      "cylinder", "[analysis]\ndimension = 3\ndt = 1e-4\nsteps = 1\n[grid]\norigin = [0.0, 0.0, 0.0]\ncell_size = 0.05\n"
                  "cells = [12, 20, 12]\n[materials.elastic]\ntype = \"linear_elastic\"\ndensity = 1000.0\n"
                  "youngs_modulus = 1e6\npoisson_ratio = 0.3\n[[bodies]]\nmaterial = \"elastic\"\nparticles_per_cell = 2\n"
                  "shape = { type = \"cylinder\", axis = \"y\", center = [0.3, 0.5, 0.3], radius = 0.2, length = 0.8 }\n");
  const auto sim = testing::simulation<3, LinearShape>(c);
  double volume = 0.0;
  for (const auto& b : sim.system().batches) {
    for (std::size_t p = 0; p < b.size(); ++p) {
      volume += b.volume[p];
      CHECK(std::hypot(b.x[p][0] - 0.3, b.x[p][2] - 0.3) <= 0.2);
      CHECK(std::abs(b.x[p][1] - 0.5) <= 0.4);
    }
  }
  const double exact_volume = std::numbers::pi * 0.04 * 0.8;
  CHECK(std::abs(volume - exact_volume) / exact_volume < 0.05);  // measured 3.5 %, as the disk
}

TEST_CASE("bad shapes are rejected with the file, the line, the key and what was expected") {
  SUBCASE("a shape with no lattice point inside it") {
    // A box less a disk that covers it.
    const std::string text = case_2d("[[bodies]]\nmaterial = \"elastic\"\nparticles_per_cell = 2\n[bodies.shape]\n"
                                     "type = \"difference\"\n[[bodies.shape.parts]]\ntype = \"box\"\nmin = [0.4, 0.4]\n"
                                     "max = [0.6, 0.6]\n[[bodies.shape.parts]]\ntype = \"sphere\"\ncenter = [0.5, 0.5]\n"
                                     "radius = 0.2\n");
    const std::string m = rejection("no_points", text);
    CHECK(m.find("no_points.toml:14: bodies[0]") != std::string::npos);
    CHECK(m.find("expected a shape that holds particle centres") != std::string::npos);
    CHECK(m.find("difference with none") != std::string::npos);
  }
  SUBCASE("a shape outside the grid") {
    const std::string m =
        rejection("outside", case_2d("[[bodies]]\nmaterial = \"elastic\"\nparticles_per_cell = 2\n"
                                     "shape = { type = \"sphere\", center = [0.95, 0.5], radius = 0.2 }\n"));
    CHECK(m.find("outside.toml:17: bodies[0].shape: expected a shape inside the grid: 0 <= x <= 1 (its bounds reach "
                 "0.75 to 1.15)") != std::string::npos);
  }
  SUBCASE("an unknown shape type lists the known ones") {
    const std::string m = rejection(
        "unknown_shape", case_2d("[[bodies]]\nmaterial = \"elastic\"\nparticles_per_cell = 2\n"
                                 "shape = { type = \"cone\" }\n"));
    CHECK(m.find("bodies[0].shape.type: expected one of \"box\", \"sphere\", \"cylinder\", \"union\", "
                 "\"intersection\", \"difference\"") != std::string::npos);
  }
  SUBCASE("a cylinder in 2D") {
    const std::string m = rejection(
        "cylinder_2d", case_2d("[[bodies]]\nmaterial = \"elastic\"\nparticles_per_cell = 2\n"
                               "shape = { type = \"cylinder\", axis = \"z\", center = [0.5, 0.5, 0.0], radius = 0.1, "
                               "length = 1.0 }\n"));
    CHECK(m.find("bodies[0].shape.type: expected a shape of a 2D or 1D analysis") != std::string::npos);
  }
  SUBCASE("a union of one part") {
    const std::string m = rejection(
        "one_part", case_2d("[[bodies]]\nmaterial = \"elastic\"\nparticles_per_cell = 2\n[bodies.shape]\n"
                            "type = \"union\"\n[[bodies.shape.parts]]\ntype = \"box\"\nmin = [0.1, 0.1]\nmax = [0.2, 0.2]\n"));
    CHECK(m.find("bodies[0].shape.parts: expected two or more shape tables") != std::string::npos);
  }
  SUBCASE("an unknown key inside a part") {
    const std::string m = rejection(
        "part_key", case_2d("[[bodies]]\nmaterial = \"elastic\"\nparticles_per_cell = 2\n[bodies.shape]\n"
                            "type = \"union\"\n[[bodies.shape.parts]]\ntype = \"box\"\nmin = [0.1, 0.1]\nmax = [0.2, 0.2]\n"
                            "[[bodies.shape.parts]]\ntype = \"sphere\"\ncenter = [0.5, 0.5]\nradius = 0.1\nradious = 2\n"));
    CHECK(m.find("part_key.toml:27: bodies[0].shape.parts[1].radious: unknown key (did you mean "
                 "bodies[0].shape.parts[1].radius?)") != std::string::npos);
  }
  SUBCASE("both a box and a shape") {
    const std::string m = rejection(
        "two_sources", case_2d("[[bodies]]\nmaterial = \"elastic\"\nparticles_per_cell = 2\nmin = [0.1, 0.1]\n"
                               "max = [0.2, 0.2]\nshape = { type = \"sphere\", center = [0.5, 0.5], radius = 0.1 }\n"));
    CHECK(m.find("bodies[0]: give the body's particles by exactly one of a box (min, max), a shape table (shape) or a "
                 "particle file (particles)") != std::string::npos);
  }
}

TEST_CASE("overlapping bodies are an error naming both and where, unless one wins over the other") {
  const std::string two =
      "[[bodies]]\nname = \"matrix\"\nmaterial = \"elastic\"\nparticles_per_cell = 2\nmin = [0.1, 0.1]\nmax = [0.9, 0.9]\n"
      "[[bodies]]\nname = \"inclusion\"\nmaterial = \"stiff\"\nparticles_per_cell = 2\n"
      "shape = { type = \"sphere\", center = [0.5, 0.5], radius = 0.2 }\n";
  const std::string stiff =
      "[materials.stiff]\ntype = \"linear_elastic\"\ndensity = 3000.0\nyoungs_modulus = 1e7\npoisson_ratio = 0.3\n";
  SUBCASE("without a winner: an error") {
    const std::string m = rejection("overlap", case_2d(two, stiff));
    INFO(m);
    CHECK(m.find("overlap.toml:20: bodies[1]: overlaps body \"matrix\": ") != std::string::npos);
    CHECK(m.find(" of its particles lie inside it, between (0.3125, 0.3125) and (0.6875, 0.6875) m") !=
          std::string::npos);
    CHECK(m.find("wins_over") != std::string::npos);
  }
  SUBCASE("the inclusion wins: the matrix loses its particles inside it, and the mass is not doubled") {
    std::string winner = two;
    winner.insert(winner.find("shape = { type = \"sphere\""), "wins_over = [\"matrix\"]\n");
    const Sim2 sim = build("overlap_won", case_2d(winner, stiff));
    const Sim2 disk = build("overlap_disk", case_2d("[[bodies]]\nmaterial = \"elastic\"\nparticles_per_cell = 2\n"
                                                    "shape = { type = \"sphere\", center = [0.5, 0.5], radius = 0.2 }\n"));
    CHECK(positions(sim, 1) == positions(disk));
    CHECK(positions(sim, 0).size() == 32 * 32 - positions(disk).size());
    double mass = 0.0;
    for (const auto& b : sim.system().batches)
      for (double m : b.mass) mass += m;
    const double disk_volume = total_volume(disk);
    CHECK(mass == doctest::Approx(1000.0 * (0.64 - disk_volume) + 3000.0 * disk_volume).epsilon(1e-12));
  }
  SUBCASE("each winning over the other") {
    std::string both = two;
    both.insert(both.find("min = [0.1, 0.1]"), "wins_over = [\"inclusion\"]\n");
    both.insert(both.find("shape = { type = \"sphere\""), "wins_over = [\"matrix\"]\n");
    const std::string m = rejection("both_win", case_2d(both, stiff));
    CHECK(m.find("bodies[1].wins_over: expected one winner per pair of bodies") != std::string::npos);
  }
  SUBCASE("an unknown name") {
    std::string unknown = two;
    unknown.insert(unknown.find("shape = { type = \"sphere\""), "wins_over = [\"matrx\"]\n");
    const std::string m = rejection("unknown_winner", case_2d(unknown, stiff));
    CHECK(m.find("bodies[1].wins_over: expected names of other bodies among \"matrix\", \"inclusion\"") !=
          std::string::npos);
  }
  SUBCASE("the flowmpm program: exit status 1, one message, nothing written") {
    testing::TempDir dir;
    std::ofstream(dir.path / "case.toml") << case_2d(two, stiff);
    const auto r = testing::run_flowmpm({"run", (dir.path / "case.toml").string(), "--output", (dir.path / "out").string()},
                                        dir.path);
    CHECK(r.status == 1);
    CHECK(r.output.find("overlaps body \"matrix\"") != std::string::npos);
    CHECK(!std::filesystem::exists(dir.path / "out"));
  }
}

namespace {

// The particles of `sim` written as a CSV file (17 digits), with optional
// extra columns per particle.
void write_csv(const std::filesystem::path& file, const Sim2& sim, const std::string& extra_header = "",
               const std::string& extra_values = "") {
  std::ofstream out(file);
  out << "# written by test_scenes\nx, y, volume" << extra_header << "\n";
  for (const auto& b : sim.system().batches)
    for (std::size_t p = 0; p < b.size(); ++p)
      out << exact(b.x[p][0]) << ", " << exact(b.x[p][1]) << ", " << exact(b.volume[p]) << extra_values << "\n";
}

void write_h5(const std::filesystem::path& file, const Sim2& sim, bool with_stress, std::size_t position_columns = 2) {
  std::vector<double> x, v, s;
  for (const auto& b : sim.system().batches) {
    for (std::size_t p = 0; p < b.size(); ++p) {
      for (std::size_t d = 0; d < position_columns; ++d) x.push_back(d < 2 ? b.x[p][d] : 0.0);
      v.push_back(b.volume[p]);
      // Listed xx, yy, zz, xy, yz, xz, as results.h5 writes them.
      for (const double value : {-20.0, -50.0, -21.0, 3.0, 0.0, 0.0}) s.push_back(value);
    }
  }
  const hid_t h5 = H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  auto dataset = [&](const char* name, const std::vector<double>& values, hsize_t columns) {
    hsize_t dims[2] = {values.size() / std::max<hsize_t>(columns, 1), columns};
    const hid_t space = H5Screate_simple(columns ? 2 : 1, dims, nullptr);
    const hid_t d = H5Dcreate2(h5, name, H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    H5Dclose(d);
    H5Sclose(space);
  };
  dataset("position", x, position_columns);
  dataset("volume", v, 0);
  if (with_stress) dataset("stress", s, 6);
  H5Fclose(h5);
}

// A column under gravity on a fixed base, stepped: its particles' state.
std::vector<double> column_state(const Case& c, int steps) {
  auto sim = testing::simulation<2, LinearShape>(c);
  for (int s = 0; s < steps; ++s) sim.advance();
  std::vector<double> state;
  for (const auto& b : sim.system().batches) {
    for (std::size_t p = 0; p < b.size(); ++p) {
      state.insert(state.end(), {b.x[p][0], b.x[p][1], b.v[p][0], b.v[p][1], b.volume[p]});
      state.insert(state.end(), b.stress[p].begin(), b.stress[p].end());
    }
  }
  return state;
}

const std::string column_extra = "[[node_sets]]\nname = \"base\"\nplane = \"y\"\nat = 0.1\nvelocity = { x = 0.0, y = 0.0 }\n";
const std::string gravity = "gravity = [0.0, -10.0]\n";

}  // namespace

TEST_CASE("particles from a CSV or HDF5 file run exactly as the body they were written from") {
  testing::TempDir dir;
  const std::string body = "[[bodies]]\nmaterial = \"elastic\"\nparticles_per_cell = 2\nmin = [0.2, 0.1]\nmax = [0.4, 0.7]\n";
  const Sim2 original = build("column_box", case_2d(body, column_extra, gravity));
  const auto reference = column_state(testing::case_from_text("column_box", case_2d(body, column_extra, gravity)), 50);
  write_csv(dir.path / "column.csv", original);
  write_h5(dir.path / "column.h5", original, false);
  for (const char* file : {"column.csv", "column.h5"}) {
    CAPTURE(file);
    const std::string from_file =
        "[[bodies]]\nmaterial = \"elastic\"\nparticles = \"" + (dir.path / file).string() + "\"\n";
    CHECK(column_state(testing::case_from_text("column_file", case_2d(from_file, column_extra, gravity)), 50) ==
          reference);
  }
}

TEST_CASE("per-particle material axes and initial stress from a file equal the body's own") {
  testing::TempDir dir;
  const std::string wood =
      "[materials.wood]\ntype = \"orthotropic\"\ndensity = 500.0\nEx = 1e7\nEy = 1e6\nEz = 1e6\nGxy = 5e5\n"
      "Gxz = 5e5\nGyz = 3e5\nnuxy = 0.3\nnuxz = 0.3\nnuyz = 0.4\n";
  const std::string body = "[[bodies]]\nmaterial = \"wood\"\nparticles_per_cell = 2\nmin = [0.2, 0.1]\nmax = [0.4, 0.7]\n";
  const std::string with_axes = body + "material_axes = [30.0]\n"
                                       "initial_stress = { type = \"uniform\", stress = [-20.0, -50.0, -21.0, 3.0, 0.0, 0.0] }\n";
  const Sim2 original = build("axes_box", case_2d(body, wood + column_extra, gravity));
  write_csv(dir.path / "axes.csv", original,
            ", material_axes_z, stress_xx, stress_yy, stress_zz, stress_yz, stress_xz, stress_xy",
            ", 30.0, -20.0, -50.0, -21.0, 0.0, 0.0, 3.0");
  const auto reference = column_state(testing::case_from_text("axes_box", case_2d(with_axes, wood + column_extra, gravity)), 50);
  const std::string from_file = "[[bodies]]\nmaterial = \"wood\"\nparticles = \"" + (dir.path / "axes.csv").string() + "\"\n";
  CHECK(column_state(testing::case_from_text("axes_file", case_2d(from_file, wood + column_extra, gravity)), 50) ==
        reference);
  // An HDF5 stress dataset too, with its shear in the listed order.
  write_h5(dir.path / "stress.h5", original, true);
  const std::string stress_body = body + "initial_stress = { type = \"uniform\", stress = [-20.0, -50.0, -21.0, 3.0, 0.0, 0.0] }\n";
  const std::string stress_file = "[[bodies]]\nmaterial = \"wood\"\nparticles = \"" + (dir.path / "stress.h5").string() + "\"\n";
  CHECK(column_state(testing::case_from_text("stress_file", case_2d(stress_file, wood + column_extra, gravity)), 20) ==
        column_state(testing::case_from_text("stress_box", case_2d(stress_body, wood + column_extra, gravity)), 20));
}

TEST_CASE("bad particle files are rejected naming the case key, the file, the line and the column") {
  testing::TempDir dir;
  auto rejected = [&](const std::string& name, const std::string& content) {
    const auto file = dir.path / name;
    std::ofstream(file) << content;
    return rejection("bad_file", case_2d("[[bodies]]\nmaterial = \"elastic\"\nparticles = \"" + file.string() + "\"\n"));
  };
  SUBCASE("a missing column") {
    const std::string m = rejected("no_volume.csv", "x, y\n0.5, 0.5\n");
    CHECK(m.find("bad_file.toml:16: bodies[0].particles: ") != std::string::npos);
    CHECK(m.find("no_volume.csv:1: missing column \"volume\"") != std::string::npos);
  }
  SUBCASE("a value that is not a finite number") {
    const std::string m = rejected("nan.csv", "x, y, volume\n0.5, 0.5, 1e-4\n0.55, nan, 1e-4\n");
    CHECK(m.find("nan.csv:3: column \"y\": expected a finite number, got \"nan\"") != std::string::npos);
  }
  SUBCASE("an unknown column") {
    const std::string m = rejected("unknown.csv", "x, y, volume, colour\n0.5, 0.5, 1e-4, 1\n");
    CHECK(m.find("unknown.csv:1: unknown column \"colour\"") != std::string::npos);
  }
  SUBCASE("a short row") {
    const std::string m = rejected("short.csv", "x, y, volume\n0.5, 0.5\n");
    CHECK(m.find("short.csv:2: expected 3 comma-separated values") != std::string::npos);
  }
  SUBCASE("some stress columns but not all") {
    const std::string m = rejected("stress.csv", "x, y, volume, stress_xx\n0.5, 0.5, 1e-4, 1\n");
    CHECK(m.find("missing column \"stress_yy\"; expected all six stress columns") != std::string::npos);
  }
  SUBCASE("a volume <= 0") {
    const std::string m = rejected("volume.csv", "x, y, volume\n0.5, 0.5, 0\n");
    CHECK(m.find("volume.csv: particle 0: expected a positive volume") != std::string::npos);
  }
  SUBCASE("no such file") {
    const std::string m = rejection("missing_file", case_2d("[[bodies]]\nmaterial = \"elastic\"\nparticles = \"none.csv\"\n"));
    CHECK(m.find("bodies[0].particles: ") != std::string::npos);
    CHECK(m.find("none.csv: cannot open the particle file") != std::string::npos);
  }
  SUBCASE("HDF5: a position dataset of the wrong shape") {
    const Sim2 sim = build("h5_source", case_2d("[[bodies]]\nmaterial = \"elastic\"\nparticles_per_cell = 1\n"
                                                "min = [0.2, 0.2]\nmax = [0.4, 0.4]\n"));
    write_h5(dir.path / "wide.h5", sim, false, 3);
    const std::string m =
        rejection("bad_h5", case_2d("[[bodies]]\nmaterial = \"elastic\"\nparticles = \"" + (dir.path / "wide.h5").string() + "\"\n"));
    CHECK(m.find("wide.h5: dataset \"position\": expected an n x 2 array of positions in m, got a dataset of rank 2 (16 x 3)") !=
          std::string::npos);
  }
  SUBCASE("HDF5: a missing dataset") {
    const auto file = dir.path / "empty.h5";
    H5Fclose(H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT));
    const std::string m = rejection("no_dataset", case_2d("[[bodies]]\nmaterial = \"elastic\"\nparticles = \"" + file.string() + "\"\n"));
    CHECK(m.find("empty.h5: missing dataset \"position\"") != std::string::npos);
  }
}

TEST_CASE("initial stress: uniform, and geostatic from gravity and depth, which holds a column at rest") {
  const std::string column = "[[bodies]]\nmaterial = \"elastic\"\nparticles_per_cell = 2\nmin = [0.2, 0.1]\nmax = [0.4, 0.7]\n";
  const std::string rollers = column_extra +
                              "[[node_sets]]\nname = \"left\"\nplane = \"x\"\nat = 0.2\nvelocity = { x = 0.0 }\n"
                              "[[node_sets]]\nname = \"right\"\nplane = \"x\"\nat = 0.4\nvelocity = { x = 0.0 }\n";
  // K0 = nu / (1 - nu): the at-rest state of an elastic column in plane strain.
  const double k0 = 0.3 / 0.7;
  const std::string geostatic = column + "initial_stress = { type = \"geostatic\", k0 = " + exact(k0) + " }\n";
  const Sim2 sim = build("geostatic", case_2d(geostatic, rollers, gravity));
  for (const auto& b : sim.system().batches) {
    for (std::size_t p = 0; p < b.size(); ++p) {
      const double sv = -1000.0 * 10.0 * (0.7 - b.x[p][1]);
      CHECK(b.stress[p][1] == doctest::Approx(sv).epsilon(1e-12));
      CHECK(b.stress[p][0] == doctest::Approx(k0 * sv).epsilon(1e-12));
      CHECK(b.stress[p][2] == doctest::Approx(k0 * sv).epsilon(1e-12));
      CHECK(b.stress[p][5] == 0.0);
    }
  }
  // A surcharge q on the top, on a slope (gravity tilted 30 degrees towards
  // x): sigma_v = -(q + rho |g_y| (top - y)), the shear g_x (q / |g_y| +
  // rho (top - y)), the infinite slope's with the load's weight on it.
  {
    const std::string loaded = column + "initial_stress = { type = \"geostatic\", k0 = 0.5, surcharge = 800.0 }\n";
    const Sim2 slope = build("geostatic_surcharge", case_2d(loaded, "", "gravity = [5.0, -8.660254037844386]\n"));
    for (const auto& b : slope.system().batches) {
      for (std::size_t p = 0; p < b.size(); ++p) {
        const double depth = 0.7 - b.x[p][1], gy = 8.660254037844386;
        CHECK(b.stress[p][1] == doctest::Approx(-(800.0 + 1000.0 * gy * depth)).epsilon(1e-12));
        CHECK(b.stress[p][0] == doctest::Approx(-0.5 * (800.0 + 1000.0 * gy * depth)).epsilon(1e-12));
        CHECK(b.stress[p][5] == doctest::Approx(5.0 * (800.0 / gy + 1000.0 * depth)).epsilon(1e-12));
      }
    }
  }
  // Gravity switched on: without initial stress the column sinks and
  // oscillates about its static settlement (top: rho g H^2 / (2 M), M the
  // constrained modulus); with the geostatic stress it is already in
  // equilibrium and stays within 2 % of that (measured 0.3 %: the
  // particles' stress is the continuum's at their centres, the lumped
  // forces differ at the cells of the top and the base).
  auto largest_displacement = [&](const std::string& body) {
    auto s = testing::simulation<2, LinearShape>(testing::case_from_text("geostatic_run", case_2d(body, rollers, gravity)));
    const auto x0 = s.system().batches[0].x;
    double largest = 0.0;
    for (int step = 0; step < 1000; ++step) {  // 0.1 s, more than a period 4 H / c = 0.065 s
      s.advance();
      for (std::size_t p = 0; p < x0.size(); ++p)
        largest = std::max(largest, std::abs(s.system().batches[0].x[p][1] - x0[p][1]));
    }
    return largest;
  };
  const double M = 1e6 * 0.7 / (1.3 * 0.4), settlement = 1000.0 * 10.0 * 0.36 / (2 * M);
  const double free = largest_displacement(column), held = largest_displacement(geostatic);
  CHECK(free > settlement);
  CHECK(held < 0.02 * settlement);
}

TEST_CASE("bad initial stress is rejected with the key and what was expected") {
  const std::string column = "[[bodies]]\nmaterial = \"elastic\"\nparticles_per_cell = 2\nmin = [0.2, 0.1]\nmax = [0.4, 0.7]\n";
  SUBCASE("geostatic without gravity") {
    const std::string geostatic = column + "initial_stress = { type = \"geostatic\", k0 = 0.5 }\n";
    const std::string m = rejection("geostatic_no_g", case_2d(geostatic));
    CHECK(m.find("bodies[0].initial_stress.type: expected a case with gravity (analysis.gravity)") != std::string::npos);
  }
  SUBCASE("a negative surcharge") {
    const std::string m = rejection(
        "negative_surcharge",
        case_2d(column + "initial_stress = { type = \"geostatic\", k0 = 0.5, surcharge = -1.0 }\n", "", gravity));
    CHECK(m.find("bodies[0].initial_stress.surcharge: expected a load on the body's top >= 0 in Pa") != std::string::npos);
  }
  SUBCASE("a stress component the analysis does not carry") {
    const std::string m = rejection(
        "uniform_zz", case_2d(column + "initial_stress = { type = \"uniform\", stress = [0.0, 0.0, 0.0, 0.0, 1.0, 0.0] }\n"));
    CHECK(m.find("bodies[0].initial_stress.stress: expected sigma_yz and sigma_xz zero in 2D") != std::string::npos);
  }
}

TEST_CASE("an initial angular velocity: v = velocity + omega x (x - x_c), x_c the centre of mass") {
  SUBCASE("2D: a disk off the grid's centre, moving and spinning") {
    const Sim2 sim = build("spin_2d", case_2d("[[bodies]]\nmaterial = \"elastic\"\nparticles_per_cell = 2\n"
                                              "shape = { type = \"sphere\", center = [0.4, 0.55], radius = 0.2 }\n"
                                              "velocity = [1.0, -2.0]\nangular_velocity = 3.0\n"));
    // The lattice is symmetric about the disk's centre: x_c = (0.4, 0.55).
    double m = 0.0, px = 0.0, py = 0.0, L = 0.0, I = 0.0;
    for (const auto& b : sim.system().batches) {
      for (std::size_t p = 0; p < b.size(); ++p) {
        const double rx = b.x[p][0] - 0.4, ry = b.x[p][1] - 0.55;
        CHECK(b.v[p][0] == doctest::Approx(1.0 - 3.0 * ry).epsilon(1e-12));
        CHECK(b.v[p][1] == doctest::Approx(-2.0 + 3.0 * rx).epsilon(1e-12));
        m += b.mass[p], px += b.mass[p] * b.v[p][0], py += b.mass[p] * b.v[p][1];
        L += b.mass[p] * (rx * b.v[p][1] - ry * b.v[p][0]);
        I += b.mass[p] * (rx * rx + ry * ry);
      }
    }
    // The spin adds no linear momentum, and angular momentum I omega.
    CHECK(px == doctest::Approx(m * 1.0).epsilon(1e-12));
    CHECK(py == doctest::Approx(m * -2.0).epsilon(1e-12));
    CHECK(L == doctest::Approx(I * 3.0).epsilon(1e-12));
  }
  SUBCASE("3D: a box spun about an oblique axis") {
    const Case c = testing::case_from_text(
        "spin_3d",
        "[analysis]\ndimension = 3\ndt = 1e-4\nsteps = 1\n[grid]\norigin = [0.0, 0.0, 0.0]\ncell_size = 0.1\n"
        "cells = [10, 10, 10]\n[materials.elastic]\ntype = \"linear_elastic\"\ndensity = 1000.0\n"
        "youngs_modulus = 1e6\npoisson_ratio = 0.3\n[[bodies]]\nmaterial = \"elastic\"\nparticles_per_cell = 2\n"
        "min = [0.2, 0.3, 0.4]\nmax = [0.6, 0.5, 0.8]\nangular_velocity = [1.0, -2.0, 0.5]\n");
    const auto sim = testing::simulation<3, LinearShape>(c);
    const Eigen::Vector3d omega(1.0, -2.0, 0.5), centre(0.4, 0.4, 0.6);
    for (const auto& b : sim.system().batches) {
      for (std::size_t p = 0; p < b.size(); ++p) {
        const Eigen::Vector3d v = omega.cross(Eigen::Vector3d(b.x[p][0], b.x[p][1], b.x[p][2]) - centre);
        for (int d = 0; d < 3; ++d) CHECK(b.v[p][d] == doctest::Approx(v[d]).scale(1.0).epsilon(1e-12));
      }
    }
  }
  SUBCASE("refused in 1D, as a 2D array, and for a rigid body") {
    const std::string body = "[[bodies]]\nmaterial = \"elastic\"\nparticles_per_cell = 2\nmin = [0.2, 0.2]\nmax = [0.4, 0.4]\n";
    CHECK(rejection("spin_array", case_2d(body + "angular_velocity = [1.0, 2.0]\n"))
              .find("bodies[0].angular_velocity: expected a number") != std::string::npos);
    const std::string rigid = "[[bodies]]\nname = \"wall\"\nrigid = {}\nangular_velocity = 1.0\nparticles_per_cell = 2\n"
                              "min = [0.2, 0.2]\nmax = [0.4, 0.4]\n";
    CHECK(rejection("spin_rigid", case_2d(rigid)).find("bodies[0].angular_velocity: expected nothing: a rigid body") !=
          std::string::npos);
    const std::string one_d =
        "[analysis]\ndimension = 1\ndt = 1e-4\nsteps = 1\n[grid]\norigin = [0.0]\ncell_size = 0.1\ncells = [10]\n"
        "[materials.elastic]\ntype = \"linear_elastic\"\ndensity = 1000.0\nyoungs_modulus = 1e6\npoisson_ratio = 0.3\n"
        "[[bodies]]\nmaterial = \"elastic\"\nparticles_per_cell = 2\nmin = [0.2]\nmax = [0.4]\nangular_velocity = 1.0\n";
    std::string m;
    try {
      testing::case_from_text("spin_1d", one_d);
    } catch (const CaseError& e) {
      m = e.what();
    }
    CHECK(m.find("bodies[0].angular_velocity: expected no angular_velocity in 1D") != std::string::npos);
  }
}
