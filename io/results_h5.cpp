#include "io/results_h5.hpp"

#include <fcntl.h>
#include <hdf5.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <utility>

#include "io/hdf5_handle.hpp"

namespace flowmpm {
namespace {

static_assert(sizeof(hid_t) == sizeof(long long), "ResultsH5 keeps its hid_t in a long long");

herr_t keep_innermost(unsigned n, const H5E_error2_t* error, void* data) {
  if (n == 0 && error->desc != nullptr) *static_cast<std::string*>(data) = error->desc;
  return 0;
}

// The cause in HDF5's innermost message, in a few words: the system's
// error when it names one ("... errno = 28, error message = 'No space left
// on device', ..." gives "No space left on device"), else the message's
// first line.
std::string cause(const std::string& detail) {
  const std::string marker = "error message = '";
  if (const auto at = detail.find(marker); at != std::string::npos) {
    const auto begin = at + marker.size();
    return detail.substr(begin, detail.find('\'', begin) - begin);
  }
  return detail.substr(0, detail.find('\n'));
}

// Throws, in one line, what failed and the innermost cause on HDF5's error
// stack (e.g. "No space left on device").
[[noreturn]] void fail(const std::string& file, const std::string& what) {
  std::string detail;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, keep_innermost, &detail);
  H5Eclear2(H5E_DEFAULT);
  std::string message = "HDF5 file " + file + ": " + what;
  if (!detail.empty()) message += " (" + cause(detail) + ")";
  throw std::runtime_error(message);
}

// File access with a small metadata cache. HDF5's adaptive cache grows to
// 32 MiB by default, holding the object headers of steps already written
// that a run never reads again: a long run's resident size grew by about
// 30 kB per output step until the cache was full. 2 MiB holds one step's
// metadata many times over.
hid_t bounded_cache_access(const std::string& file) {
  Hdf5Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  H5AC_cache_config_t config{};
  config.version = H5AC__CURR_CACHE_CONFIG_VERSION;
  if (!access.valid() || H5Pget_mdc_config(access.get(), &config) < 0) fail(file, "cannot set up file access");
  config.set_initial_size = true;
  config.initial_size = 1 << 20;
  config.min_size = 1 << 19;
  config.max_size = 2 << 20;
  if (H5Pset_mdc_config(access.get(), &config) < 0) fail(file, "cannot set up file access");
  return access.release();
}

template <typename T>
void write_scalar_attribute(hid_t object, const char* name, hid_t file_type, hid_t memory_type,
                            const T& value, const std::string& file, const std::string& where) {
  const std::string what = "cannot write attribute " + where + "@" + name;
  Hdf5Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  if (!space.valid()) fail(file, what);
  Hdf5Handle attribute(H5Acreate2(object, name, file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT),
                   H5Aclose);
  if (!attribute.valid() || H5Awrite(attribute.get(), memory_type, &value) < 0) fail(file, what);
}

// A variable-length UTF-8 string attribute (h5py reads it as str), or an
// array of them.
void write_string_attribute(hid_t object, const char* name, const std::vector<std::string>& values, bool array,
                            const std::string& file, const std::string& where) {
  const std::string what = "cannot write attribute " + where + "@" + name;
  Hdf5Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  if (!type.valid() || H5Tset_size(type.get(), H5T_VARIABLE) < 0 || H5Tset_cset(type.get(), H5T_CSET_UTF8) < 0)
    fail(file, what);
  const hsize_t n = values.size();
  Hdf5Handle space(array ? H5Screate_simple(1, &n, nullptr) : H5Screate(H5S_SCALAR), H5Sclose);
  if (!space.valid()) fail(file, what);
  std::vector<const char*> pointers;
  for (const std::string& v : values) pointers.push_back(v.c_str());
  Hdf5Handle attribute(H5Acreate2(object, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!attribute.valid() || H5Awrite(attribute.get(), type.get(), pointers.data()) < 0) fail(file, what);
}

void write_string_attribute(hid_t object, const char* name, const std::string& value, const std::string& file,
                            const std::string& where) {
  write_string_attribute(object, name, std::vector<std::string>{value}, false, file, where);
}

// One dataset of count x components values (1D when components == 1).
struct Field {
  const char* name;
  const void* data;
  std::size_t size;  // number of values in `data`
  std::size_t components;
  hid_t file_type, memory_type;
  std::size_t value_bytes;
  const char* units;  // nullptr: no units attribute
};

// Writes one field into `group`; returns the raw data bytes written.
std::uintmax_t write_field(hid_t group, const std::string& group_name, std::size_t count,
                           const Field& field, const std::string& file) {
  const std::string where = group_name + "/" + field.name;
  const hsize_t dims[2] = {count, field.components};
  Hdf5Handle space(H5Screate_simple(field.components == 1 ? 1 : 2, dims, nullptr), H5Sclose);
  if (!space.valid()) fail(file, "cannot create dataspace for " + where);
  Hdf5Handle dataset(H5Dcreate2(group, field.name, field.file_type, space.get(), H5P_DEFAULT,
                            H5P_DEFAULT, H5P_DEFAULT),
                 H5Dclose);
  if (!dataset.valid()) fail(file, "cannot create dataset " + where);
  // A zero-size dataset has nothing to write (and `data` may be null).
  if (count > 0 &&
      H5Dwrite(dataset.get(), field.memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, field.data) < 0)
    fail(file, "cannot write dataset " + where);
  if (field.units != nullptr) write_string_attribute(dataset.get(), "units", field.units, file, where);
  if (field.components == 6)
    write_string_attribute(dataset.get(), "components", tensor_output_components, file, where);
  return static_cast<std::uintmax_t>(field.size) * field.value_bytes;
}

// Reads a numeric attribute into `value`; false when it is absent or unreadable.
template <typename T>
bool read_attribute(hid_t object, const char* name, hid_t memory_type, T& value) {
  if (H5Aexists(object, name) <= 0) return false;
  Hdf5Handle attribute(H5Aopen(object, name, H5P_DEFAULT), H5Aclose);
  return attribute.valid() && H5Aread(attribute.get(), memory_type, &value) >= 0;
}

herr_t collect_link_name(hid_t, const char* name, const H5L_info_t*, void* names) {
  static_cast<std::vector<std::string>*>(names)->push_back(name);
  return 0;
}

// The names of the links in `group`, in name order.
std::vector<std::string> link_names(hid_t group) {
  std::vector<std::string> names;
  hsize_t index = 0;
  if (H5Literate(group, H5_INDEX_NAME, H5_ITER_INC, &index, collect_link_name, &names) < 0) names.clear();
  return names;
}

// A step group as found in a file.
struct StoredStep {
  std::string name;  // "/steps/00000010"
  std::int64_t step = -1;
  double time = 0.0;
  bool complete = false;
  std::size_t count = 0;  // rows of its position dataset
  std::vector<std::string> datasets;
};

// The step groups of an open file, in step order (their names are the steps, zero-padded).
std::vector<StoredStep> stored_steps(hid_t file, const std::string& path) {
  Hdf5Handle steps(H5Gopen2(file, "/steps", H5P_DEFAULT), H5Gclose);
  if (!steps.valid()) fail(path, "has no group /steps");
  std::vector<StoredStep> stored;
  for (const std::string& name : link_names(steps.get())) {
    StoredStep s;
    s.name = "/steps/" + name;
    Hdf5Handle group(H5Gopen2(steps.get(), name.c_str(), H5P_DEFAULT), H5Gclose);
    if (group.valid()) {
      int complete = 0;
      s.complete = read_attribute(group.get(), "complete", H5T_NATIVE_INT, complete) && complete == 1 &&
                   read_attribute(group.get(), "step", H5T_NATIVE_INT64, s.step) &&
                   read_attribute(group.get(), "time", H5T_NATIVE_DOUBLE, s.time);
      s.datasets = link_names(group.get());
      Hdf5Handle position(H5Dopen2(group.get(), "position", H5P_DEFAULT), H5Dclose);
      Hdf5Handle space(position.valid() ? H5Dget_space(position.get()) : H5I_INVALID_HID, H5Sclose);
      hsize_t dims[2] = {0, 0};
      if (space.valid() && H5Sget_simple_extent_dims(space.get(), dims, nullptr) >= 1) s.count = dims[0];
    }
    // A group cut off before its step attribute: its name tells the step.
    if (s.step < 0) s.step = std::strtoll(name.c_str(), nullptr, 10);
    stored.push_back(std::move(s));
  }
  return stored;
}

// The groups a continuation keeps, checked; throws naming what is missing.
std::vector<StoredStep> kept_steps(const std::vector<StoredStep>& stored, const ResultsH5::Continuation& from,
                                   const std::string& path) {
  std::vector<StoredStep> kept;
  for (const StoredStep& s : stored)
    if (s.step <= from.last_step) kept.push_back(s);
  const auto lacks = [&](const std::string& what) {
    throw std::runtime_error("HDF5 file " + path + ": " + what + ", so the run cannot continue from the checkpoint");
  };
  if (kept.size() != from.keep || (from.keep > 0 && kept.back().step != from.last_step)) {
    lacks("holds " + std::to_string(kept.size()) + " output steps up to step " + std::to_string(from.last_step) +
          ", not the " + std::to_string(from.keep) + " the checkpoint was written after");
  }
  std::vector<std::string> expected;
  for (const OutputField& f : from.fields) expected.emplace_back(f.name);
  std::ranges::sort(expected);
  for (const StoredStep& s : kept) {
    if (!s.complete) lacks(s.name + " is incomplete");
    if (s.datasets != expected) lacks(s.name + " has other fields than the case writes");
  }
  return kept;
}

}  // namespace

void ResultsH5::check_continuation(const std::filesystem::path& path, const Continuation& from) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const std::string name = path.string();
  if (!std::filesystem::is_regular_file(path)) {
    throw std::runtime_error("HDF5 file " + name + ": not found, so the run cannot continue from the checkpoint");
  }
  Hdf5Handle file(H5Fopen(name.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!file.valid()) fail(name, "cannot open it to continue it");
  kept_steps(stored_steps(file.get(), name), from, name);
}

ResultsH5::ResultsH5(const std::filesystem::path& path, const Continuation& from)
    : file_(H5I_INVALID_HID), path_(path.string()) {
  check_continuation(path, from);
  const Hdf5Handle access(bounded_cache_access(path_), H5Pclose);
  Hdf5Handle file(H5Fopen(path_.c_str(), H5F_ACC_RDWR, access.get()), H5Fclose);
  if (!file.valid()) fail(path_, "cannot open it to continue it");
  const std::vector<StoredStep> stored = stored_steps(file.get(), path_);
  for (const StoredStep& s : kept_steps(stored, from, path_)) written_.push_back({s.step, s.time, s.count});
  for (const StoredStep& s : stored) {
    if (s.step > from.last_step && H5Ldelete(file.get(), s.name.c_str(), H5P_DEFAULT) < 0)
      fail(path_, "cannot remove " + s.name + ", written after the checkpoint");
  }
  if (H5Fflush(file.get(), H5F_SCOPE_GLOBAL) < 0) fail(path_, "cannot flush");
  if (!written_.empty()) {
    fields_ = from.fields;
    index_length_ = written_.front().count;
  }
  file_ = file.release();
}

ResultsH5::ResultsH5(const std::filesystem::path& path, const ResultsMetadata& m)
    : file_(H5I_INVALID_HID), path_(path.string()) {
  // HDF5 closes what is still open at exit; after a write failed for lack
  // of space, the HDF5 1.10 of Debian 12 crashes doing so (a segmentation
  // fault in H5F__close_cb) although the file was closed. Everything is
  // closed and flushed by the destructors, so the exit handler is not
  // needed; this must come before the first HDF5 call of the process.
  static const bool no_exit_handler = H5dont_atexit() >= 0;
  (void)no_exit_handler;
  // Errors are reported by exceptions; HDF5 must not print its own stack.
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const Hdf5Handle access(bounded_cache_access(path_), H5Pclose);
  Hdf5Handle file(H5Fcreate(path_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get()), H5Fclose);
  if (!file.valid()) fail(path_, "cannot create file");
  const hid_t root = file.get();
  write_scalar_attribute(root, "format_version", H5T_STD_I32LE, H5T_NATIVE_INT, format_version, path_, "/");
  write_string_attribute(root, "program", "flowmpm " + m.program_version, path_, "/");
  write_string_attribute(root, "commit", m.commit, path_, "/");
  write_string_attribute(root, "case", m.case_name, path_, "/");
  write_string_attribute(root, "case_file", m.case_file, path_, "/");
  write_scalar_attribute(root, "dimension", H5T_STD_I32LE, H5T_NATIVE_INT, m.dimension, path_, "/");
  write_string_attribute(root, "stress_state", m.stress_state, path_, "/");
  write_string_attribute(root, "scheme", m.scheme, path_, "/");
  write_string_attribute(root, "shape_function", m.shape_function, path_, "/");
  write_string_attribute(root, "units", "SI: m, s, kg, Pa, J", path_, "/");
  write_string_attribute(root, "tensor_components", tensor_output_components, path_, "/");
  write_string_attribute(root, "vector_components", "x y z (padded with 0 below 3D)", path_, "/");
  write_string_attribute(root, "rows", "particle id: row i is the same particle at every step", path_, "/");
  write_string_attribute(root, "materials", m.materials, true, path_, "/");
  Hdf5Handle steps(H5Gcreate2(root, "/steps", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  if (!steps.valid() || H5Fflush(root, H5F_SCOPE_GLOBAL) < 0) fail(path_, "cannot create group /steps");
  file_ = file.release();
}

ResultsH5::~ResultsH5() { H5Fclose(file_); }

std::string ResultsH5::group_name(std::int64_t step) {
  char name[32];
  std::snprintf(name, sizeof name, "/steps/%08" PRId64, step);
  return name;
}

void ResultsH5::write(const ParticleSnapshot& snapshot) {
  const std::string name = group_name(snapshot.step);
  std::vector<Field> fields;
  for (const SnapshotField& f : snapshot.fields) {
    const OutputField& o = f.field;
    fields.push_back(o.integer ? Field{o.name, f.integer.data(), f.integer.size(), 1, H5T_STD_I32LE, H5T_NATIVE_INT32,
                                       sizeof(std::int32_t), o.units}
                               : Field{o.name, f.real.data(), f.real.size(), static_cast<std::size_t>(o.components),
                                       H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, sizeof(double), o.units});
  }

  // Checked before anything is written, so that a bad snapshot leaves no
  // partial group behind.
  for (const Field& field : fields)
    if (field.size != snapshot.count * field.components)
      throw std::invalid_argument("HDF5 file " + path_ + ": " + name + "/" + field.name + " has " +
                                  std::to_string(field.size) + " values, expected " +
                                  std::to_string(snapshot.count * field.components));
  std::vector<OutputField> layout;
  for (const SnapshotField& f : snapshot.fields) layout.push_back(f.field);
  const auto same = [](const OutputField& a, const OutputField& b) { return std::string_view(a.name) == b.name; };
  if (!written_.empty() && !std::ranges::equal(layout, fields_, same))
    throw std::invalid_argument("HDF5 file " + path_ + ": " + name + " has other fields than the earlier steps");

  if (!written_.empty() && snapshot.count > index_length_)
    throw std::invalid_argument("HDF5 file " + path_ + ": " + name + " has more particles than the first step");

  // Room for the step first. HDF5 cannot undo a step that the disk filled
  // up in the middle of: its metadata is then left inconsistent, and the
  // whole file may no longer open. So a full disk stops the run between
  // steps, while every step in the file is whole: the file system must have
  // the step's data twice over (HDF5's metadata, the XDMF index and
  // timeseries.csv follow it) and 1 MiB, and results.h5 gets its share
  // allocated ahead, so that another process filling the disk meanwhile
  // cannot take it.
  std::uintmax_t step_bytes = 0;
  for (const Field& field : fields) step_bytes += field.size * field.value_bytes;
  const double needed = 2.0 * static_cast<double>(step_bytes) + 1024.0 * 1024.0;
  const auto no_room = [&](double room) {
    throw std::runtime_error("HDF5 file " + path_ + ": no room for " + name + " (" + std::strerror(ENOSPC) + ": " +
                             std::to_string(static_cast<long long>(needed / 1024)) + " kB needed" +
                             (room >= 0 ? ", " + std::to_string(static_cast<long long>(room / 1024)) + " kB free"
                                        : std::string()) +
                             ")");
  };
  struct statvfs disk {};
  if (::statvfs(path_.c_str(), &disk) == 0) {
    const double room = static_cast<double>(disk.f_bavail) * static_cast<double>(disk.f_frsize);
    if (room < needed) no_room(room);
  }
  if (const int fd = ::open(path_.c_str(), O_WRONLY | O_CLOEXEC); fd >= 0) {
    struct stat file {};
    // FALLOC_FL_KEEP_SIZE: blocks allocated past the end, the size (which
    // HDF5 checks) unchanged. File systems without fallocate rely on the
    // check above alone.
    const bool reserved = ::fstat(fd, &file) == 0 &&
                          ::fallocate(fd, FALLOC_FL_KEEP_SIZE, file.st_size,
                                      static_cast<off_t>(2 * step_bytes + 64 * 1024)) == 0;
    const int error = errno;
    ::close(fd);
    if (!reserved && (error == ENOSPC || error == EDQUOT)) no_room(-1.0);
  }

  // The connectivity 0..n-1, once: every step's topology reads its first n.
  std::uintmax_t bytes = 0;
  if (written_.empty()) {
    std::vector<std::int32_t> index(snapshot.count);
    for (std::size_t i = 0; i < index.size(); ++i) index[i] = static_cast<std::int32_t>(i);
    Hdf5Handle root(H5Gopen2(file_, "/", H5P_DEFAULT), H5Gclose);
    bytes += write_field(root.get(), "", snapshot.count,
                         Field{particle_index + 1, index.data(), index.size(), 1, H5T_STD_I32LE, H5T_NATIVE_INT32,
                               sizeof(std::int32_t), nullptr},
                         path_);
    index_length_ = snapshot.count;
  }

  try {
    Hdf5Handle group(H5Gcreate2(file_, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
    if (!group.valid()) fail(path_, "cannot create group " + name);
    write_scalar_attribute(group.get(), "time", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, snapshot.time, path_, name);
    write_scalar_attribute(group.get(), "step", H5T_STD_I64LE, H5T_NATIVE_INT64, snapshot.step, path_, name);
    for (const Field& field : fields) bytes += write_field(group.get(), name, snapshot.count, field, path_);
    // Complete only now: written last, then flushed.
    write_scalar_attribute(group.get(), "complete", H5T_STD_I32LE, H5T_NATIVE_INT, 1, path_, name);
    if (H5Fflush(file_, H5F_SCOPE_GLOBAL) < 0) fail(path_, "cannot flush after " + name);
  } catch (const std::runtime_error&) {
    // A step is complete or absent: the partial group is unlinked (if the
    // file can still take that; a reader skips a group not marked complete).
    H5Ldelete(file_, name.c_str(), H5P_DEFAULT);
    H5Eclear2(H5E_DEFAULT);
    throw;
  }
  written_.push_back({snapshot.step, snapshot.time, snapshot.count});
  fields_ = std::move(layout);
  bytes_ += bytes;
}

}  // namespace flowmpm
