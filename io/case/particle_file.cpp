#include "io/case/particle_file.hpp"

#include <hdf5.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <utility>

#include "core/errors.hpp"
#include "core/registry.hpp"
#include "io/results/hdf5_handle.hpp"

namespace flowmpm {
namespace {

const char* const axis_columns[3] = {"x", "y", "z"};
const char* const axes_columns[3] = {"material_axes_z", "material_axes_y", "material_axes_x"};

// The columns a file may hold for `dimension`, by kind.
struct Columns {
  std::vector<std::string> position, axes, stress;
};
Columns columns_for(int dimension) {
  Columns c;
  for (int d = 0; d < dimension; ++d) c.position.push_back(axis_columns[d]);
  if (dimension >= 2) c.axes.push_back(axes_columns[0]);
  if (dimension == 3) c.axes.insert(c.axes.end(), {axes_columns[1], axes_columns[2]});
  for (const char* s : voigt_component_names) c.stress.push_back(std::string("stress_") + s);
  return c;
}

std::string trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return "";
  const auto last = s.find_last_not_of(" \t\r");
  return std::string(s.substr(first, last - first + 1));
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(trim(std::string_view(line).substr(start, comma - start)));
    if (comma == std::string::npos) return fields;
    start = comma + 1;
  }
}

void check_volumes(const ParticleList& list, const std::string& file) {
  for (std::size_t p = 0; p < list.size(); ++p) {
    if (!(list.volume[p] > 0.0)) {
      throw CaseError(file + ": particle " + std::to_string(p) + ": expected a positive volume, got " +
                      std::to_string(list.volume[p]));
    }
  }
  if (list.size() == 0) throw CaseError(file + ": expected at least one particle, got none");
}

ParticleList read_csv(const std::filesystem::path& path, int dimension) {
  const std::string file = path.string();
  std::ifstream in(path);
  if (!in) throw CaseError(file + ": cannot open the particle file");
  const Columns known = columns_for(dimension);
  std::vector<std::string> all = known.position;
  all.push_back("volume");
  all.insert(all.end(), known.axes.begin(), known.axes.end());
  all.insert(all.end(), known.stress.begin(), known.stress.end());

  std::string line;
  std::size_t line_number = 0;
  std::vector<std::string> header;
  while (header.empty() && std::getline(in, line)) {
    ++line_number;
    if (trim(line).empty() || trim(line)[0] == '#') continue;
    header = split(line);
  }
  if (header.empty()) throw CaseError(file + ": expected a header line naming the columns, got an empty file");
  std::map<std::string, std::size_t> column;
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (std::ranges::find(all, header[i]) == all.end()) {
      throw CaseError(file + ":" + std::to_string(line_number) + ": unknown column \"" + header[i] +
                      "\"; expected columns among " + quoted_list(all));
    }
    if (!column.emplace(header[i], i).second) {
      throw CaseError(file + ":" + std::to_string(line_number) + ": column \"" + header[i] + "\" given twice");
    }
  }
  auto require_all = [&](const std::vector<std::string>& names, const std::string& what) {
    for (const std::string& name : names) {
      if (!column.count(name)) {
        throw CaseError(file + ":" + std::to_string(line_number) + ": missing column \"" + name + "\"; expected " +
                        what);
      }
    }
  };
  require_all(known.position, "the columns " + quoted_list(known.position) + " (m) and \"volume\"");
  require_all({"volume"}, "a column \"volume\" (m^3; m^2 per unit thickness in 2D)");
  const bool has_axes = std::ranges::any_of(known.axes, [&](const auto& n) { return column.count(n) > 0; });
  const bool has_stress = std::ranges::any_of(known.stress, [&](const auto& n) { return column.count(n) > 0; });
  if (has_axes) require_all(known.axes, "all of " + quoted_list(known.axes) + " (degrees) or none");
  if (has_stress) require_all(known.stress, "all six stress columns " + quoted_list(known.stress) + " (Pa) or none");

  ParticleList list;
  list.source = file;
  while (std::getline(in, line)) {
    ++line_number;
    if (trim(line).empty() || trim(line)[0] == '#') continue;
    const std::vector<std::string> fields = split(line);
    if (fields.size() != header.size()) {
      throw CaseError(file + ":" + std::to_string(line_number) + ": expected " + std::to_string(header.size()) +
                      " comma-separated values (one per column of the header), got " +
                      std::to_string(fields.size()));
    }
    auto value = [&](const std::string& name) {
      const std::string& text = fields[column.at(name)];
      double v = 0.0;
      const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
      if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(v)) {
        throw CaseError(file + ":" + std::to_string(line_number) + ": column \"" + name +
                        "\": expected a finite number, got \"" + text + "\"");
      }
      return v;
    };
    Vec3 x{};
    for (int d = 0; d < dimension; ++d) x[d] = value(known.position[d]);
    list.position.push_back(x);
    list.volume.push_back(value("volume"));
    if (has_axes) {
      Vec3 a{};
      for (std::size_t k = 0; k < known.axes.size(); ++k) a[k] = value(known.axes[k]);
      list.material_axes.push_back(a);
    }
    if (has_stress) {
      Voigt s{};
      for (int k = 0; k < 6; ++k) s[k] = value(known.stress[k]);
      list.stress.push_back(s);
    }
  }
  check_volumes(list, file);
  return list;
}

herr_t collect_name(hid_t, const char* name, const H5L_info_t*, void* data) {
  static_cast<std::vector<std::string>*>(data)->emplace_back(name);
  return 0;
}

// Dataset `name` as rows x columns doubles; `columns` 0 for a 1D dataset.
// Empty when absent and not `required`.
std::vector<double> read_dataset(hid_t h5, const std::string& file, const std::string& name, std::size_t columns,
                                 std::size_t& rows, bool required, const std::string& expected) {
  if (H5Lexists(h5, name.c_str(), H5P_DEFAULT) <= 0) {
    if (required) throw CaseError(file + ": missing dataset \"" + name + "\"; expected " + expected);
    return {};
  }
  Hdf5Handle dataset(H5Dopen2(h5, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (!dataset.valid()) throw CaseError(file + ": \"" + name + "\" is not a dataset; expected " + expected);
  Hdf5Handle space(H5Dget_space(dataset.get()), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  hsize_t dims[2] = {0, 0};
  if (rank != (columns == 0 ? 1 : 2) || H5Sget_simple_extent_dims(space.get(), dims, nullptr) < 0 ||
      (columns != 0 && dims[1] != columns) || (rows != 0 && dims[0] != rows)) {
    throw CaseError(file + ": dataset \"" + name + "\": expected " + expected + (rows ? " with " + std::to_string(rows) + " rows" : "") +
                    ", got a dataset of rank " + std::to_string(rank) +
                    (rank >= 1 ? " (" + std::to_string(dims[0]) + (rank == 2 ? " x " + std::to_string(dims[1]) : "") + ")" : ""));
  }
  rows = dims[0];
  std::vector<double> values(rows * std::max<std::size_t>(columns, 1));
  if (!values.empty() &&
      H5Dread(dataset.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0) {
    throw CaseError(file + ": dataset \"" + name + "\": cannot read it as numbers; expected " + expected);
  }
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) {
      const std::size_t c = std::max<std::size_t>(columns, 1);
      throw CaseError(file + ": dataset \"" + name + "\": row " + std::to_string(i / c) +
                      (columns ? ", column " + std::to_string(i % c) : "") + ": expected a finite number, got " +
                      std::to_string(values[i]));
    }
  }
  return values;
}

ParticleList read_h5(const std::filesystem::path& path, int dimension) {
  const std::string file = path.string();
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  Hdf5Handle h5(H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!h5.valid()) throw CaseError(file + ": cannot open it as an HDF5 file");
  std::vector<std::string> names;
  H5Literate(h5.get(), H5_INDEX_NAME, H5_ITER_INC, nullptr, collect_name, &names);
  const std::vector<std::string> known = {"position", "volume", "material_axes", "stress"};
  for (const std::string& name : names) {
    if (std::ranges::find(known, name) == known.end()) {
      throw CaseError(file + ": unknown dataset \"" + name + "\"; expected datasets among " + quoted_list(known));
    }
  }
  const std::size_t D = static_cast<std::size_t>(dimension);
  std::size_t n = 0;
  const auto position = read_dataset(h5.get(), file, "position", D, n, true,
                                     "an n x " + std::to_string(D) + " array of positions in m");
  const auto volume = read_dataset(h5.get(), file, "volume", 0, n, true, "n volumes in m^3");
  const std::size_t axes_columns = dimension == 3 ? 3 : 1;
  const auto axes = read_dataset(h5.get(), file, "material_axes", axes_columns, n, false,
                                 "an n x " + std::to_string(axes_columns) + " array of angles in degrees");
  if (!axes.empty() && dimension == 1) throw CaseError(file + ": dataset \"material_axes\": no material axes in 1D");
  const auto stress = read_dataset(h5.get(), file, "stress", 6, n, false, "an n x 6 array of stresses in Pa (xx, yy, zz, xy, yz, xz)");
  ParticleList list;
  list.source = file;
  for (std::size_t p = 0; p < n; ++p) {
    Vec3 x{};
    for (std::size_t d = 0; d < D; ++d) x[d] = position[p * D + d];
    list.position.push_back(x);
    list.volume.push_back(volume[p]);
    if (!axes.empty()) {
      Vec3 a{};
      for (std::size_t k = 0; k < axes_columns; ++k) a[k] = axes[p * axes_columns + k];
      list.material_axes.push_back(a);
    }
    if (!stress.empty()) {
      Voigt s{};
      for (int k = 0; k < 6; ++k) s[voigt_slot_of_listed[k]] = stress[p * 6 + k];
      list.stress.push_back(s);
    }
  }
  check_volumes(list, file);
  return list;
}

}  // namespace

ParticleList read_particle_file(const std::filesystem::path& file, int dimension) {
  const std::string extension = file.extension().string();
  if (extension == ".csv") return read_csv(file, dimension);
  if (extension == ".h5" || extension == ".hdf5") return read_h5(file, dimension);
  throw CaseError(file.string() + ": expected a particle file ending in .csv, .h5 or .hdf5");
}

}  // namespace flowmpm
