#include "io/results/results_h5.hpp"

#include <hdf5.h>
#include <sys/statvfs.h>

#include <algorithm>
#include <cerrno>
#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <regex>
#include <stdexcept>
#include <utility>

#include "io/results/atomic_file.hpp"
#include "io/results/hdf5_handle.hpp"

namespace flowmpm {
namespace {

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

// A 1D array attribute of 64-bit integers.
void write_array_attribute(hid_t object, const char* name, const std::vector<std::int64_t>& values,
                           const std::string& file, const std::string& where) {
  const std::string what = "cannot write attribute " + where + "@" + name;
  const hsize_t n = values.size();
  Hdf5Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose);
  if (!space.valid()) fail(file, what);
  Hdf5Handle attribute(H5Acreate2(object, name, H5T_STD_I64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!attribute.valid() || H5Awrite(attribute.get(), H5T_NATIVE_INT64, values.data()) < 0) fail(file, what);
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

// Writes one field into `group`.
void write_field(hid_t group, const std::string& group_name, std::size_t count, const Field& field,
                 const std::string& file, const char* tensor_components) {
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
    write_string_attribute(dataset.get(), "components", tensor_components, file, where);
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

// HDF5 reports errors by return values here, never on stderr. After a
// write failed for lack of space, the HDF5 1.10 of Debian 12 crashes at exit
// closing what it believes open (a segmentation fault in H5F__close_cb)
// although every file was closed: its exit handler is not needed, since
// every file is closed where it is written. Both before the first HDF5 call.
void quiet_hdf5() {
  static const bool no_exit_handler = H5dont_atexit() >= 0;
  (void)no_exit_handler;
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

// Closes a file that was written, reporting a failure (HDF5 writes the
// last of its data when the file closes); `file` names it in messages.
// After a failed close HDF5 1.10 keeps the file open until the process ends
// (closing it again crashes); write_file_atomically_by_name frees its disk
// space.
void close_file(Hdf5Handle& handle, const std::string& file) {
  if (H5Fclose(handle.release()) < 0) fail(file, "cannot close");
}

// A step file as found in the directory steps/.
struct StoredStep {
  std::string file;  // its path, for messages
  std::int64_t step = -1;
  double time = 0.0;
  bool readable = false;  // opens, with its step and time
  std::size_t count = 0;  // rows of its position dataset
  std::vector<std::string> datasets;
};

// The step files of `directory`/steps (names of 8 or more digits, ".h5"),
// in step order; a file that does not open is kept, not readable.
std::vector<StoredStep> stored_steps(const std::filesystem::path& directory) {
  static const std::regex step_name(R"((\d{8,})\.h5)");
  std::vector<StoredStep> stored;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(directory / "steps", error)) {
    const std::string name = entry.path().filename().string();
    std::smatch match;
    if (!std::regex_match(name, match, step_name)) continue;
    StoredStep s;
    s.file = entry.path().string();
    s.step = std::strtoll(match[1].str().c_str(), nullptr, 10);
    Hdf5Handle file(H5Fopen(s.file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
    Hdf5Handle root(file.valid() ? H5Gopen2(file.get(), "/", H5P_DEFAULT) : H5I_INVALID_HID, H5Gclose);
    std::int64_t step = -1;
    s.readable = root.valid() && read_attribute(root.get(), "step", H5T_NATIVE_INT64, step) && step == s.step &&
                 read_attribute(root.get(), "time", H5T_NATIVE_DOUBLE, s.time);
    if (s.readable) {
      s.datasets = link_names(root.get());
      Hdf5Handle position(H5Dopen2(root.get(), "position", H5P_DEFAULT), H5Dclose);
      Hdf5Handle space(position.valid() ? H5Dget_space(position.get()) : H5I_INVALID_HID, H5Sclose);
      hsize_t dims[2] = {0, 0};
      if (space.valid() && H5Sget_simple_extent_dims(space.get(), dims, nullptr) >= 1) s.count = dims[0];
    }
    H5Eclear2(H5E_DEFAULT);
    stored.push_back(std::move(s));
  }
  std::ranges::sort(stored, {}, &StoredStep::step);
  return stored;
}

// The step files a continuation keeps, checked; throws naming what is missing.
std::vector<StoredStep> kept_steps(const std::vector<StoredStep>& stored, const ResultsH5::Continuation& from,
                                   const std::filesystem::path& directory) {
  std::vector<StoredStep> kept;
  for (const StoredStep& s : stored)
    if (s.step <= from.last_step) kept.push_back(s);
  const auto lacks = [&](const std::string& what) {
    throw std::runtime_error(what + ", so the run cannot continue from the checkpoint");
  };
  if (kept.size() != from.keep || (from.keep > 0 && kept.back().step != from.last_step)) {
    lacks((directory / "steps").string() + " holds " + std::to_string(kept.size()) + " output steps up to step " +
          std::to_string(from.last_step) + ", not the " + std::to_string(from.keep) +
          " the checkpoint was written after");
  }
  std::vector<std::string> expected;
  for (const OutputField& f : from.fields) expected.emplace_back(f.name);
  std::ranges::sort(expected);
  for (const StoredStep& s : kept) {
    if (!s.readable) lacks("HDF5 file " + s.file + " does not open as a step file");
    if (s.datasets != expected) lacks("HDF5 file " + s.file + " has other fields than the case writes");
  }
  return kept;
}

}  // namespace

ResultsH5::ResultsH5(const std::filesystem::path& path, const ResultsMetadata& metadata)
    : path_(path), directory_(path.parent_path()), metadata_(metadata) {
  quiet_hdf5();
  std::error_code error;
  std::filesystem::create_directory(directory_ / "steps", error);
  if (error) {
    throw std::runtime_error("HDF5 file " + path_.string() + ": cannot create the directory " +
                             (directory_ / "steps").string() + " for its steps: " + error.message());
  }
  write_index();
}

void ResultsH5::check_continuation(const std::filesystem::path& path, const Continuation& from) {
  quiet_hdf5();
  kept_steps(stored_steps(path.parent_path()), from, path.parent_path());
}

ResultsH5::ResultsH5(const std::filesystem::path& path, const ResultsMetadata& metadata, const Continuation& from)
    : path_(path), directory_(path.parent_path()), metadata_(metadata) {
  quiet_hdf5();
  const std::vector<StoredStep> stored = stored_steps(directory_);
  for (const StoredStep& s : kept_steps(stored, from, directory_)) written_.push_back({s.step, s.time, s.count});
  for (const StoredStep& s : stored) {
    std::error_code error;
    if (s.step > from.last_step && !std::filesystem::remove(s.file, error) && error) {
      throw std::runtime_error("cannot remove " + s.file + ", written after the checkpoint: " + error.message());
    }
  }
  if (!written_.empty()) {
    fields_ = from.fields;
    index_length_ = written_.front().count;
  }
  write_index();
}

std::string ResultsH5::step_label(std::int64_t step) {
  char label[32];
  std::snprintf(label, sizeof label, "%08" PRId64, step);
  return label;
}

std::string ResultsH5::group_name(std::int64_t step) { return "/steps/" + step_label(step); }

std::string ResultsH5::step_file(std::int64_t step) { return "steps/" + step_label(step) + ".h5"; }

void ResultsH5::write_index() const {
  const std::string file = path_.string();
  flush_directory(directory_ / "steps");  // the step files' names, before the index names them
  write_file_atomically_by_name(path_, [&](const std::filesystem::path& temporary) {
    Hdf5Handle handle(H5Fcreate(temporary.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
    if (!handle.valid()) fail(file, "cannot create file");
    const hid_t root = handle.get();
    const ResultsMetadata& m = metadata_;
    write_scalar_attribute(root, "format_version", H5T_STD_I32LE, H5T_NATIVE_INT, format_version, file, "/");
    write_string_attribute(root, "program", "flowmpm " + m.program_version, file, "/");
    write_string_attribute(root, "commit", m.commit, file, "/");
    write_string_attribute(root, "case", m.case_name, file, "/");
    write_string_attribute(root, "case_file", m.case_file, file, "/");
    write_scalar_attribute(root, "dimension", H5T_STD_I32LE, H5T_NATIVE_INT, m.dimension, file, "/");
    write_string_attribute(root, "stress_state", m.stress_state, file, "/");
    write_string_attribute(root, "scheme", m.scheme, file, "/");
    write_string_attribute(root, "shape_function", m.shape_function, file, "/");
    write_string_attribute(root, "units", "SI: m, s, kg, Pa, J", file, "/");
    write_string_attribute(root, "tensor_components", tensor_output_components_of(m.stress_state), file, "/");
    write_string_attribute(root, "vector_components", vector_output_components_of(m.stress_state), file, "/");
    write_string_attribute(root, "rows", "particle id: row i is the same particle at every step", file, "/");
    write_string_attribute(root, "materials", m.materials, true, file, "/");
    if (!m.bodies.empty()) {  // HDF5 writes no empty attribute
      write_string_attribute(root, "bodies", m.bodies, true, file, "/");
      write_array_attribute(root, "body_rows", m.body_rows, file, "/");
    }
    // The connectivity 0..n-1: every step's topology reads its first n.
    if (index_length_ > 0) {
      std::vector<std::int32_t> index(index_length_);
      for (std::size_t i = 0; i < index.size(); ++i) index[i] = static_cast<std::int32_t>(i);
      write_field(root, "", index_length_,
                  Field{particle_index + 1, index.data(), index.size(), 1, H5T_STD_I32LE, H5T_NATIVE_INT32,
                        sizeof(std::int32_t), nullptr},
                  file, tensor_output_components_of(m.stress_state));
    }
    {
      Hdf5Handle steps(H5Gcreate2(root, "/steps", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
      if (!steps.valid()) fail(file, "cannot create group /steps");
      for (const WrittenStep& s : written_) {
        if (H5Lcreate_external(step_file(s.step).c_str(), "/", steps.get(), step_label(s.step).c_str(), H5P_DEFAULT,
                               H5P_DEFAULT) < 0)
          fail(file, "cannot link " + group_name(s.step) + " to " + step_file(s.step));
      }
    }
    close_file(handle, file);
  });
}

void ResultsH5::write(const ParticleSnapshot& snapshot) {
  const std::filesystem::path path = directory_ / step_file(snapshot.step);
  const std::string file = path.string();
  std::vector<Field> fields;
  for (const SnapshotField& f : snapshot.fields) {
    const OutputField& o = f.field;
    fields.push_back(o.integer ? Field{o.name, f.integer.data(), f.integer.size(), 1, H5T_STD_I32LE, H5T_NATIVE_INT32,
                                       sizeof(std::int32_t), o.units}
                               : Field{o.name, f.real.data(), f.real.size(), static_cast<std::size_t>(o.components),
                                       H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, sizeof(double), o.units});
  }

  // Checked before anything is written.
  for (const Field& field : fields)
    if (field.size != snapshot.count * field.components)
      throw std::invalid_argument("HDF5 file " + file + ": /" + field.name + " has " + std::to_string(field.size) +
                                  " values, expected " + std::to_string(snapshot.count * field.components));
  std::vector<OutputField> layout;
  for (const SnapshotField& f : snapshot.fields) layout.push_back(f.field);
  const auto same = [](const OutputField& a, const OutputField& b) { return std::string_view(a.name) == b.name; };
  if (!written_.empty() && !std::ranges::equal(layout, fields_, same))
    throw std::invalid_argument("HDF5 file " + file + " has other fields than the earlier steps");
  if (!written_.empty() && snapshot.count > index_length_)
    throw std::invalid_argument("HDF5 file " + file + " has more particles than the first step");
  if (!written_.empty() && snapshot.step <= written_.back().step)
    throw std::invalid_argument("HDF5 file " + file + ": step " + std::to_string(snapshot.step) +
                                " is not after the last step written, " + std::to_string(written_.back().step));

  // Room for the step first, so that a full disk stops the run between
  // steps rather than in the middle of the small files that follow a step
  // (the index, the XDMF index, timeseries.csv): the step's data twice over
  // and 1 MiB.
  std::uintmax_t step_bytes = 0;
  for (const Field& field : fields) step_bytes += field.size * field.value_bytes;
  const double needed = 2.0 * static_cast<double>(step_bytes) + 1024.0 * 1024.0;
  struct statvfs disk {};
  if (::statvfs(directory_.c_str(), &disk) == 0) {
    const double room = static_cast<double>(disk.f_bavail) * static_cast<double>(disk.f_frsize);
    if (room < needed)
      throw std::runtime_error("HDF5 file " + file + ": no room for it (" + std::strerror(ENOSPC) + ": " +
                               std::to_string(static_cast<long long>(needed / 1024)) + " kB needed, " +
                               std::to_string(static_cast<long long>(room / 1024)) + " kB free)");
  }

  write_file_atomically_by_name(path, [&](const std::filesystem::path& temporary) {
    Hdf5Handle handle(H5Fcreate(temporary.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
    if (!handle.valid()) fail(file, "cannot create file");
    const hid_t root = handle.get();
    write_scalar_attribute(root, "time", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, snapshot.time, file, "/");
    write_scalar_attribute(root, "step", H5T_STD_I64LE, H5T_NATIVE_INT64, snapshot.step, file, "/");
    for (const Field& field : fields)
      write_field(root, "", snapshot.count, field, file, tensor_output_components_of(metadata_.stress_state));
    close_file(handle, file);
  });
  if (written_.empty()) index_length_ = snapshot.count;
  written_.push_back({snapshot.step, snapshot.time, snapshot.count});
  fields_ = std::move(layout);
  bytes_ += step_bytes;
}

}  // namespace flowmpm
