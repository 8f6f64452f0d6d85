// Output writers: the step files and their index results.h5 read back
// through the HDF5 C API, the XDMF index, timeseries.csv, summary.json and
// atomic file replacement.
#include <doctest/doctest.h>
#include <hdf5.h>
#include <signal.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/lsan_interface.h>
#endif

#include "io/results/atomic_file.hpp"
#include "io/results/results_h5.hpp"
#include "io/results/results_index.hpp"
#include "io/results/summary_json.hpp"
#include "io/results/timeseries_csv.hpp"
#include "io/results/xdmf.hpp"

namespace fs = std::filesystem;
using namespace flowmpm;

namespace {

// A fresh directory, removed with everything in it at the end of the test.
struct TempDir {
  fs::path path;
  TempDir() {
    static std::atomic<int> counter{0};
    path = fs::temp_directory_path() /
           ("flowmpm_test_output_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
};

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, separator)) parts.push_back(part);
  return parts;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// The field `name` of a snapshot, which must have it.
SnapshotField& field(ParticleSnapshot& s, std::string_view name) {
  for (SnapshotField& f : s.fields)
    if (std::string_view(f.field.name) == name) return f;
  FAIL("no field " << name);
  throw std::logic_error("unreachable");
}
const std::vector<double>& real(const ParticleSnapshot& s, std::string_view name) { return s.find(name)->real; }

// Every output field, with values that only survive a write exactly if no
// digit is lost.
ParticleSnapshot make_snapshot(std::int64_t step, double time, std::size_t count) {
  ParticleSnapshot s;
  s.step = step;
  s.time = time;
  s.count = count;
  for (const OutputField& f : builtin_output_fields) {
    for (const char* name :
         {"position", "velocity", "stress", "strain", "volume", "mass", "material", "temperature", "concentration"})
      if (std::string_view(f.name) == name) s.fields.push_back({f, {}, {}});
  }
  for (std::size_t i = 0; i < count; ++i) {
    const double x = static_cast<double>(i) + static_cast<double>(step);
    for (int c = 0; c < 3; ++c) {
      field(s, "position").real.push_back(0.1 * x + c / 3.0);
      field(s, "velocity").real.push_back(-x / 7.0 + c * 1e-17);
    }
    for (int c = 0; c < 6; ++c) {
      field(s, "stress").real.push_back(1.0e6 * std::sin(x + c));
      field(s, "strain").real.push_back(1.0e-4 * std::cos(x - c));
    }
    field(s, "volume").real.push_back(1e-9 * (1.0 + x / 3.0));
    field(s, "mass").real.push_back(2.7e-6 * (1.0 + x / 11.0));
    field(s, "material").integer.push_back(static_cast<std::int32_t>(i % 3));
    field(s, "temperature").real.push_back(293.15 + x / 13.0);
    field(s, "concentration").real.push_back(0.01 * (1.0 + x / 17.0));
  }
  return s;
}

ResultsMetadata metadata() {
  return {"0.1.0", "abc123", "test case", "cases/test.toml", 2, "plane strain", "USL", "bspline2",
          {"steel", "rubber \"soft\""}, {"block", "lid"}, {0, 3, 5}};
}

// The snapshot without the fields named.
ParticleSnapshot without(ParticleSnapshot s, const std::vector<std::string>& names) {
  std::erase_if(s.fields, [&](const SnapshotField& f) { return std::ranges::find(names, f.field.name) != names.end(); });
  return s;
}

// Minimal readers over the HDF5 C API; each REQUIREs success.
struct H5Reader {
  hid_t file;
  explicit H5Reader(const fs::path& path) {
    file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    REQUIRE(file >= 0);
  }
  ~H5Reader() { H5Fclose(file); }

  bool exists(const std::string& name) const {
    return H5Lexists(file, name.c_str(), H5P_DEFAULT) > 0;
  }

  std::vector<hsize_t> dims(const std::string& name) const {
    const hid_t dataset = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
    REQUIRE(dataset >= 0);
    const hid_t space = H5Dget_space(dataset);
    std::vector<hsize_t> result(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)));
    H5Sget_simple_extent_dims(space, result.data(), nullptr);
    H5Sclose(space);
    H5Dclose(dataset);
    return result;
  }

  template <typename T>
  std::vector<T> read(const std::string& name, hid_t memory_type, std::size_t size) const {
    std::vector<T> values(size);
    const hid_t dataset = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
    REQUIRE(dataset >= 0);
    REQUIRE(H5Dread(dataset, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0);
    H5Dclose(dataset);
    return values;
  }

  template <typename T>
  T attribute(const std::string& object, const char* name, hid_t memory_type) const {
    T value{};
    const hid_t attr = H5Aopen_by_name(file, object.c_str(), name, H5P_DEFAULT, H5P_DEFAULT);
    REQUIRE(attr >= 0);
    REQUIRE(H5Aread(attr, memory_type, &value) >= 0);
    H5Aclose(attr);
    return value;
  }

  // A scalar variable-length string attribute (what ResultsH5 writes). The
  // object is opened first: H5Aopen_by_name with a path through an external
  // link reads the string from the wrong file's heap in HDF5 1.10.8 (docs/guide/output.md).
  std::string string_attribute(const std::string& object, const char* name) const {
    const hid_t opened = H5Oopen(file, object.c_str(), H5P_DEFAULT);
    REQUIRE(opened >= 0);
    const hid_t attr = H5Aopen(opened, name, H5P_DEFAULT);
    H5Oclose(opened);
    REQUIRE(attr >= 0);
    const hid_t type = H5Aget_type(attr);
    REQUIRE(H5Tis_variable_str(type) > 0);
    char* text = nullptr;
    REQUIRE(H5Aread(attr, type, &text) >= 0);
    const std::string value = text ? text : "";
    H5free_memory(text);
    H5Tclose(type);
    H5Aclose(attr);
    return value;
  }
};

}  // namespace

TEST_CASE("ResultsH5 writes steps that read back exactly") {
  TempDir dir;
  const fs::path file = dir.path / "results.h5";
  const ParticleSnapshot first = make_snapshot(0, 0.0, 5);
  const ParticleSnapshot second = make_snapshot(1250, 0.1 + 1.0 / 3.0, 4);
  {
    ResultsH5 results(file, metadata());
    results.write(first);
    results.write(second);
    REQUIRE(results.written().size() == 2);
    CHECK(results.written()[1].step == 1250);
    CHECK(results.written()[1].time == second.time);
    CHECK(results.written()[1].count == 4);
    CHECK(results.index_length() == 5);
    const std::uintmax_t per_particle = (3 + 3 + 6 + 6 + 1 + 1 + 1 + 1) * sizeof(double) + 4;
    CHECK(results.bytes_written() == (5 + 4) * per_particle);
    // More particles than the first step: refused, nothing written.
    CHECK_THROWS_AS(results.write(make_snapshot(1300, 0.5, 6)), std::invalid_argument);
    CHECK(results.written().size() == 2);
    CHECK(!fs::exists(dir.path / "steps/00001300.h5"));
    // A step file each, complete under its final name, and no temporary left.
    CHECK(ResultsH5::step_file(1250) == "steps/00001250.h5");
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir.path / "steps")) names.push_back(entry.path().filename());
    std::ranges::sort(names);
    CHECK(names == std::vector<std::string>{"00000000.h5", "00001250.h5"});
    // The index lists the steps once rewritten: read through it below.
    CHECK(H5Reader(file).exists("/steps") == true);
    CHECK(H5Reader(file).exists("/steps/00000000") == false);
    results.write_index();
  }

  CHECK(ResultsH5::group_name(1250) == "/steps/00001250");
  H5Reader h5(file);
  for (const ParticleSnapshot* s : {&first, &second}) {
    const std::string group = ResultsH5::group_name(s->step);
    CAPTURE(group);
    CHECK(h5.attribute<double>(group, "time", H5T_NATIVE_DOUBLE) == s->time);
    CHECK(h5.attribute<std::int64_t>(group, "step", H5T_NATIVE_INT64) == s->step);
    const hsize_t n = s->count;
    CHECK(h5.dims(group + "/position") == std::vector<hsize_t>{n, 3});
    CHECK(h5.dims(group + "/stress") == std::vector<hsize_t>{n, 6});
    CHECK(h5.dims(group + "/mass") == std::vector<hsize_t>{n});
    CHECK(h5.read<double>(group + "/position", H5T_NATIVE_DOUBLE, n * 3) == real(*s, "position"));
    CHECK(h5.read<double>(group + "/velocity", H5T_NATIVE_DOUBLE, n * 3) == real(*s, "velocity"));
    CHECK(h5.read<double>(group + "/stress", H5T_NATIVE_DOUBLE, n * 6) == real(*s, "stress"));
    CHECK(h5.read<double>(group + "/strain", H5T_NATIVE_DOUBLE, n * 6) == real(*s, "strain"));
    CHECK(h5.read<double>(group + "/volume", H5T_NATIVE_DOUBLE, n) == real(*s, "volume"));
    CHECK(h5.read<double>(group + "/mass", H5T_NATIVE_DOUBLE, n) == real(*s, "mass"));
    CHECK(h5.read<std::int32_t>(group + "/material", H5T_NATIVE_INT32, n) == s->find("material")->integer);
    CHECK(h5.string_attribute(group + "/position", "units") == "m");
    CHECK(h5.string_attribute(group + "/velocity", "units") == "m/s");
    CHECK(h5.string_attribute(group + "/stress", "units") == "Pa");
    CHECK(h5.string_attribute(group + "/strain", "units") == "-");
    CHECK(h5.string_attribute(group + "/volume", "units") == "m^3");
    CHECK(h5.string_attribute(group + "/mass", "units") == "kg");
    // Tensors say their component order.
    CHECK(h5.string_attribute(group + "/stress", "components") == "xx yy zz xy yz xz");
    CHECK(h5.string_attribute(group + "/strain", "components") == "xx yy zz xy yz xz");
    // The step file alone reads the same.
    const H5Reader alone(dir.path / ResultsH5::step_file(s->step));
    CHECK(alone.attribute<std::int64_t>("/", "step", H5T_NATIVE_INT64) == s->step);
    CHECK(alone.read<double>("/stress", H5T_NATIVE_DOUBLE, n * 6) == real(*s, "stress"));
  }
  CHECK(h5.read<std::int32_t>("/particle_index", H5T_NATIVE_INT32, 5) == std::vector<std::int32_t>{0, 1, 2, 3, 4});
  // The root group's metadata.
  CHECK(h5.attribute<std::int32_t>("/", "format_version", H5T_NATIVE_INT32) == ResultsH5::format_version);
  CHECK(h5.string_attribute("/", "program") == "flowmpm 0.1.0");
  CHECK(h5.string_attribute("/", "commit") == "abc123");
  CHECK(h5.string_attribute("/", "case") == "test case");
  CHECK(h5.string_attribute("/", "case_file") == "cases/test.toml");
  CHECK(h5.attribute<std::int32_t>("/", "dimension", H5T_NATIVE_INT32) == 2);
  CHECK(h5.string_attribute("/", "stress_state") == "plane strain");
  CHECK(h5.string_attribute("/", "scheme") == "USL");
  CHECK(h5.string_attribute("/", "shape_function") == "bspline2");
  CHECK(h5.string_attribute("/", "tensor_components") == "xx yy zz xy yz xz");
  CHECK(contains(h5.string_attribute("/", "units"), "SI"));
  // The bodies' rows: 64-bit integers, one more than the bodies.
  const hid_t rows = H5Aopen(h5.file, "body_rows", H5P_DEFAULT);
  REQUIRE(rows >= 0);
  const hid_t space = H5Aget_space(rows);
  CHECK(H5Sget_simple_extent_npoints(space) == 3);
  std::int64_t values[3] = {};
  CHECK(H5Aread(rows, H5T_NATIVE_INT64, values) >= 0);
  CHECK((values[0] == 0 && values[1] == 3 && values[2] == 5));
  H5Sclose(space);
  H5Aclose(rows);
}

// Issue 15: a step file that fails while HDF5 writes it (here: the file
// size limit, EFBIG, as a full disk gives ENOSPC) is absent, no temporary
// file is left, and the steps before it stay whole.
TEST_CASE("a step whose file cannot be written in full leaves no file, and the earlier steps whole") {
  TempDir dir;
  const ParticleSnapshot first = make_snapshot(1, 0.5, 2000);  // about 330 kB
  ResultsH5 results(dir.path / "results.h5", metadata());
  results.write(first);

  rlimit before{};
  REQUIRE(::getrlimit(RLIMIT_FSIZE, &before) == 0);
  rlimit small = before;
  small.rlim_cur = 100 * 1024;
  const auto previous = ::signal(SIGXFSZ, SIG_IGN);  // a write past the limit fails with EFBIG instead
  REQUIRE(::setrlimit(RLIMIT_FSIZE, &small) == 0);
  std::string message;
  {
    // HDF5 1.10 keeps a file whose close failed open, with its structures,
    // until the process ends (closing it again crashes): memory of HDF5's
    // failure path, not ours to free, which LeakSanitizer is told to ignore
    // (HDF5's free lists emptied first, so that all it holds is allocated
    // in this scope).
#if defined(__SANITIZE_ADDRESS__)
    H5garbage_collect();
    const __lsan::ScopedDisabler hdf5_keeps_the_failed_file;
#endif
    try {
      results.write(make_snapshot(2, 1.0, 2000));
    } catch (const std::runtime_error& e) {
      message = e.what();
    }
  }
  ::setrlimit(RLIMIT_FSIZE, &before);
  ::signal(SIGXFSZ, previous);

  INFO(message);
  CHECK(contains(message, (dir.path / "steps/00000002.h5").string()));
  CHECK(contains(message, "File too large"));
  CHECK(results.written().size() == 1);
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir.path / "steps")) names.push_back(entry.path().filename());
  CHECK(names == std::vector<std::string>{"00000001.h5"});
  const H5Reader step(dir.path / "steps/00000001.h5");
  CHECK(step.read<double>("/stress", H5T_NATIVE_DOUBLE, 2000 * 6) == real(first, "stress"));
  // The run can go on: the next step is written.
  results.write(make_snapshot(3, 1.5, 2000));
  CHECK(fs::exists(dir.path / "steps/00000003.h5"));
}

TEST_CASE("ResultsH5 writes only the enabled fields, and empty steps") {
  TempDir dir;
  const fs::path file = dir.path / "results.h5";
  ParticleSnapshot empty = without(make_snapshot(3, 1.5, 0), {"strain", "mass"});
  {
    ResultsH5 results(file, metadata());
    results.write(empty);
    CHECK(results.bytes_written() == 0);
    results.write_index();

    const std::string xdmf = xdmf_document("results.h5", results);
    CHECK(contains(xdmf, "steps/00000003.h5:/stress"));
    CHECK_FALSE(contains(xdmf, "strain"));
    CHECK_FALSE(contains(xdmf, "mass"));
  }
  H5Reader h5(file);
  CHECK(h5.dims("/steps/00000003/position") == std::vector<hsize_t>{0, 3});
  CHECK(h5.dims("/steps/00000003/volume") == std::vector<hsize_t>{0});
  CHECK(h5.exists("/steps/00000003/stress"));
  CHECK_FALSE(h5.exists("/steps/00000003/strain"));
  CHECK_FALSE(h5.exists("/steps/00000003/mass"));
}

TEST_CASE("ResultsH5 rejects bad snapshots and reports errors with the file name") {
  TempDir dir;
  const fs::path file = dir.path / "results.h5";
  {
    ResultsH5 results(file, metadata());
    ParticleSnapshot bad = make_snapshot(1, 0.5, 3);
    field(bad, "stress").real.pop_back();
    CHECK_THROWS_AS(results.write(bad), std::invalid_argument);
    CHECK(results.written().empty());

    results.write(make_snapshot(2, 1.0, 3));
    try {
      results.write(make_snapshot(2, 1.0, 3));
      FAIL("writing a step twice must throw");
    } catch (const std::invalid_argument& e) {
      CHECK(contains(e.what(), (dir.path / "steps/00000002.h5").string()));
      CHECK(contains(e.what(), "not after the last step written"));
    }
    // An HDF5 error (here: its directory is gone) names the step's file and
    // leaves nothing under its name.
    fs::remove_all(dir.path / "steps");
    try {
      results.write(make_snapshot(4, 2.0, 3));
      FAIL("writing into a missing directory must throw");
    } catch (const std::runtime_error& e) {
      CHECK(contains(e.what(), (dir.path / "steps/00000004.h5").string()));
    }
    CHECK(!fs::exists(dir.path / "steps/00000004.h5"));
    CHECK(results.written().size() == 1);
  }
  H5Reader h5(file);
  CHECK_FALSE(h5.exists("/steps/00000001"));

  const fs::path missing = dir.path / "no_such_dir" / "results.h5";
  try {
    ResultsH5 results(missing, metadata());
    FAIL("creating a file in a missing directory must throw");
  } catch (const std::runtime_error& e) {
    CHECK(contains(e.what(), missing.string()));
  }
}

TEST_CASE("XDMF indexes every written step") {
  TempDir dir;
  ResultsH5 results(dir.path / "results.h5", metadata());
  const double time = 0.1 + 0.2;
  results.write(make_snapshot(0, 0.0, 7));
  results.write(make_snapshot(20, time, 4));

  const std::string xdmf = xdmf_document("results.h5", results);
  CHECK(contains(xdmf, "<Xdmf Version=\"3.0\">"));
  CHECK(contains(xdmf, "GridType=\"Collection\" CollectionType=\"Temporal\""));
  CHECK(contains(xdmf, "<Time Value=\"0\"/>"));
  CHECK(contains(xdmf, "<Time Value=\"0.30000000000000004\"/>"));
  CHECK(contains(xdmf, "NumberOfElements=\"4\" NodesPerElement=\"1\""));
  CHECK(contains(xdmf, "NumberOfElements=\"7\" NodesPerElement=\"1\""));
  CHECK(contains(xdmf, "Dimensions=\"7 3\" NumberType=\"Float\" Precision=\"8\">"
                       "steps/00000000.h5:/position</DataItem>"));
  CHECK(contains(xdmf, "Dimensions=\"4 3\" NumberType=\"Float\" Precision=\"8\">"
                       "steps/00000020.h5:/position</DataItem>"));
  // The topology's connectivity: the first n entries of /particle_index
  // (7 long), through a HyperSlab (ParaView's default reader needs it).
  CHECK(contains(xdmf, "<DataItem ItemType=\"HyperSlab\" Dimensions=\"4\">\n"
                       "            <DataItem Dimensions=\"3 1\" Format=\"XML\">0 1 4</DataItem>\n"
                       "            <DataItem Format=\"HDF\" Dimensions=\"7\" NumberType=\"Int\" Precision=\"4\">"
                       "results.h5:/particle_index</DataItem>"));
  // "Matrix", not "Tensor6": the data are in the order ParaView labels a
  // 6-component array (xx yy zz xy yz xz); the legacy reader would expand a
  // Tensor6 to 9 components numbered 0-8.
  CHECK(contains(xdmf, "<Attribute Name=\"stress\" AttributeType=\"Matrix\""));
  CHECK(contains(xdmf, "Dimensions=\"4 6\" NumberType=\"Float\" Precision=\"8\">"
                       "steps/00000020.h5:/strain</DataItem>"));
  CHECK(contains(xdmf, "Dimensions=\"4\" NumberType=\"Int\" Precision=\"4\">"
                       "steps/00000020.h5:/material</DataItem>"));
  CHECK(contains(xdmf, "<Attribute Name=\"velocity\" AttributeType=\"Vector\""));
  CHECK(contains(xdmf, "<Attribute Name=\"mass\" AttributeType=\"Scalar\""));

  const fs::path path = dir.path / "results.xdmf";
  write_xdmf(path, "results.h5", results);
  CHECK(read_text(path) == xdmf);

  ResultsH5 no_position(dir.path / "other.h5", metadata());
  no_position.write(without(make_snapshot(0, 0.0, 4), {"position"}));
  CHECK_THROWS_AS(xdmf_document("other.h5", no_position), std::invalid_argument);
}

// Issue 15, finding 10: the indexes are rewritten when the number of steps
// has doubled (or after their interval, here too long to matter) and at the
// end, not at every output step: 1,001 steps, 11 rewrites. The XDMF index is
// streamed to the file a step at a time, and reads as the document held
// whole would; results.h5 links every step.
TEST_CASE("the indexes are rewritten when the steps double, and the XDMF one written a step at a time") {
  TempDir dir;
  ResultsH5 results(dir.path / "results.h5", metadata());
  ResultsIndex index(dir.path / "results.xdmf", 1e9);
  for (std::int64_t k = 0; k <= 1000; ++k) {
    results.write(make_snapshot(10 * k, 1e-3 * static_cast<double>(k), 2));
    index.update(results);
  }
  CHECK(index.rewrites() == 10);  // at 1, 2, 4, ..., 512 steps
  CHECK(H5Reader(dir.path / "results.h5").exists("/steps/00005110"));
  CHECK_FALSE(H5Reader(dir.path / "results.h5").exists("/steps/00005120"));
  index.finish(results);
  CHECK(index.rewrites() == 11);
  const std::string text = read_text(dir.path / "results.xdmf");
  CHECK(text == xdmf_document("results.h5", results));
  CHECK(contains(text, "steps/00010000.h5:/position"));
  std::size_t pieces = 0;
  xdmf_document("results.h5", results, [&](std::string_view) { ++pieces; });
  CHECK(pieces == 1001 + 2);  // the head, one per step, the tail
  const H5Reader h5(dir.path / "results.h5");
  CHECK(h5.attribute<double>("/steps/00010000", "time", H5T_NATIVE_DOUBLE) == 1.0);
}

TEST_CASE("timeseries CSV: header, and rows that parse back exactly") {
  TempDir dir;
  const fs::path path = dir.path / "timeseries.csv";
  Diagnostics row;
  row.step = 42;
  row.time = 1.0 / 3.0;
  row.kinetic_energy = 2.0 / 3.0 * 1e-7;
  row.stored_energy = std::nextafter(1.0, 2.0);
  row.dissipated_energy = 0.125;
  row.work = {-1.0 / 7.0, 3e-300, 1e300};
  const double balance_error = -1.0 / 9.0;
  BodyMeans block, ground;
  for (std::size_t i = 0; i < 6; ++i) {
    block.stress[i] = -1.0e5 / static_cast<double>(i + 3);
    block.strain[i] = 1.0e-5 * std::sqrt(static_cast<double>(i + 2));
    ground.stress[i] = std::numeric_limits<double>::denorm_min() * static_cast<double>(i);
    ground.strain[i] = std::numeric_limits<double>::max() / static_cast<double>(i + 1);
  }
  row.bodies = {block, ground};
  row.reactions = {{"base", 1, 12.5 / 3.0}, {"top", 0, -1e-300}};
  CHECK(reaction_names(row) == std::vector<std::string>{"reaction.base.y", "reaction.top.x"});
  {
    TimeseriesCsv csv(path, {"block", "ground"}, reaction_names(row));
    csv.write(row, balance_error);
    // Flushed after each row: the file is complete while still open.
    const std::vector<std::string> lines = split(read_text(path), '\n');
    REQUIRE(lines.size() == 2);
    const std::vector<std::string> header = split(lines[0], ',');
    REQUIRE(header.size() == 10 + 2 * 12 + 2);
    CHECK(lines[0].rfind("step,time,kinetic_energy,stored_energy,dissipated_energy,gravity_work,boundary_work,"
                         "expansion_work,load_work,energy_balance_error,block.stress_xx,"
                         "block.stress_yy,block.stress_zz,block.stress_yz,block.stress_xz,"
                         "block.stress_xy,block.strain_xx,",
                         0) == 0);
    CHECK(header[21] == "block.strain_xy");
    CHECK(header[22] == "ground.stress_xx");
    CHECK(header[33] == "ground.strain_xy");
    CHECK(header[34] == "reaction.base.y");
    CHECK(header.back() == "reaction.top.x");

    const std::vector<std::string> cells = split(lines[1], ',');
    REQUIRE(cells.size() == header.size());
    CHECK(cells[0] == "42");
    std::vector<double> expected = {row.time,          row.kinetic_energy, row.stored_energy,
                                    row.dissipated_energy, row.work.gravity, row.work.boundary,
                                    row.work.expansion, row.work.load,  balance_error};
    for (const BodyMeans& body : row.bodies) {
      expected.insert(expected.end(), body.stress.begin(), body.stress.end());
      expected.insert(expected.end(), body.strain.begin(), body.strain.end());
    }
    for (const Reaction& r : row.reactions) expected.push_back(r.value);
    for (std::size_t i = 1; i < cells.size(); ++i) {
      CAPTURE(header[i]);
      CHECK(std::strtod(cells[i].c_str(), nullptr) == expected[i - 1]);
    }

    row.reactions.pop_back();
    CHECK_THROWS_AS(csv.write(row, balance_error), std::invalid_argument);
    row.reactions.push_back({"top", 0, 0.0});
    row.bodies.pop_back();
    CHECK_THROWS_AS(csv.write(row, balance_error), std::invalid_argument);
  }

  const fs::path missing = dir.path / "no_such_dir" / "timeseries.csv";
  try {
    TimeseriesCsv csv(missing, {});
    FAIL("opening a file in a missing directory must throw");
  } catch (const std::runtime_error& e) {
    CHECK(contains(e.what(), missing.string()));
  }
}

TEST_CASE("summary JSON escapes strings and writes null for non-finite numbers") {
  RunSummary summary;
  summary.case_name = "say \"hi\"\\now";
  summary.case_file = "cases/a\tb\x01.toml";
  summary.particles = 123456;
  summary.steps = 1000;
  summary.dt = 1.0e-4 / 3.0;
  summary.particle_steps_per_second = std::numeric_limits<double>::quiet_NaN();
  summary.output_seconds = std::numeric_limits<double>::infinity();
  BodySummary body;
  body.name = "block";
  body.mean_stress = {1.5, -2.0, 0.1, 0.0, 0.0, 3.0e-300};
  summary.bodies = {body};
  summary.errors = {{"l2_displacement", 0.25}, {"max_stress", std::nan("")}};

  const std::string json = summary_json(summary);
  CHECK(contains(json, R"("case": "say \"hi\"\\now",)"));
  CHECK(contains(json, R"("case_file": "cases/a\tb\u0001.toml",)"));
  CHECK(contains(json, R"("status": "completed",)"));
  CHECK(contains(json, R"("particles": 123456,)"));
  CHECK(contains(json, R"("steps": 1000,)"));
  CHECK(contains(json, "\"dt\": 3.3333333333333335e-05,"));
  CHECK(contains(json, "\"particle_steps_per_second\": null,"));
  CHECK(contains(json, "\"output_seconds\": null,"));
  CHECK(contains(json, R"("name": "block")"));
  CHECK(contains(json, R"("mean_stress": {"xx": 1.5, "yy": -2, "zz": 0.10000000000000001, )"
                       R"("yz": 0, "xz": 0, "xy": 3.0000000000000002e-300})"));
  // Axisymmetric: the components named as timeseries.csv and results.h5 name them.
  RunSummary axisymmetric = summary;
  axisymmetric.axisymmetric = true;
  CHECK(contains(summary_json(axisymmetric), R"("mean_stress": {"rr": 1.5, "zz": -2, "tt": 0.10000000000000001, )"
                                             R"("zt": 0, "rt": 0, "rz": 3.0000000000000002e-300})"));
  CHECK(contains(json, R"("l2_displacement": 0.25,)"));
  CHECK(contains(json, R"("max_stress": null)"));
  CHECK_FALSE(contains(json, "nan"));
  CHECK_FALSE(contains(json, "inf"));

  TempDir dir;
  write_summary(dir.path / "summary.json", summary);
  CHECK(read_text(dir.path / "summary.json") == json);

  const RunSummary empty;
  const std::string minimal = summary_json(empty);
  CHECK(contains(minimal, "\"bodies\": [],"));
  CHECK(contains(minimal, "\"errors\": {}\n}"));
}

TEST_CASE("write_file_atomically replaces files and leaves no temporary behind") {
  TempDir dir;
  const fs::path path = dir.path / "out.txt";
  write_file_atomically(path, "first version, longer than the second\n");
  write_file_atomically(path, "second\n");
  CHECK(read_text(path) == "second\n");
  write_file_atomically(path, "");
  CHECK(read_text(path).empty());
  std::vector<fs::path> entries;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir.path))
    entries.push_back(entry.path().filename());
  CHECK(entries == std::vector<fs::path>{"out.txt"});

  // A text handed in pieces, longer than the 64 kB gathered per write; a
  // producer that throws part way leaves the file as it was.
  const std::string piece(1000, 'x');
  write_file_atomically(path, [&](const TextSink& sink) {
    for (int k = 0; k < 200; ++k) sink(piece);
  });
  CHECK(read_text(path) == std::string(200000, 'x'));
  CHECK_THROWS_AS(write_file_atomically(path,
                                        [&](const TextSink& sink) {
                                          sink("partial");
                                          throw std::invalid_argument("stop");
                                        }),
                  std::invalid_argument);
  CHECK(read_text(path) == std::string(200000, 'x'));
  entries.clear();
  for (const fs::directory_entry& entry : fs::directory_iterator(dir.path))
    entries.push_back(entry.path().filename());
  CHECK(entries == std::vector<fs::path>{"out.txt"});

  const fs::path missing = dir.path / "no_such_dir" / "out.txt";
  try {
    write_file_atomically(missing, "text");
    FAIL("writing into a missing directory must throw");
  } catch (const std::runtime_error& e) {
    CHECK(contains(e.what(), missing.string()));
    CHECK(contains(e.what(), "No such file or directory"));
  }

  // Renaming onto a directory fails after the temporary was written: it must
  // be removed again.
  fs::create_directory(dir.path / "taken");
  CHECK_THROWS_AS(write_file_atomically(dir.path / "taken", "text"), std::runtime_error);
  std::size_t count = 0;
  for ([[maybe_unused]] const fs::directory_entry& entry : fs::directory_iterator(dir.path))
    ++count;
  CHECK(count == 2);
}
