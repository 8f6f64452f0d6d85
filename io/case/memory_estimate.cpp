#include "io/case/memory_estimate.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <mutex>
#include <string_view>
#include <type_traits>

#include "core/number_text.hpp"
#include "discretisation/shapes/shape_functions.hpp"
#include "engine/take_snapshot.hpp"
#include "io/case/case_reader.hpp"

namespace flowmpm {
namespace {

// The program itself (code, libraries, the TBB pool, HDF5's caches): the
// resident size of a run with a handful of particles, measured 25-30 MB.
constexpr double program_bytes = 32.0 * 1024 * 1024;

std::mutex limit_mutex;
std::optional<std::uint64_t> max_memory;

// A /proc/meminfo value in bytes ("MemAvailable:  1234 kB").
std::optional<double> meminfo(std::string_view key) {
  std::ifstream in("/proc/meminfo");
  for (std::string name; in >> name;) {
    double kb = 0.0;
    std::string unit;
    in >> kb >> unit;
    if (name == std::string(key) + ":") return kb * 1024.0;
  }
  return std::nullopt;
}

// A cgroup v2 file holding one number (or "max").
std::optional<double> cgroup_value(const std::string& file) {
  std::ifstream in("/sys/fs/cgroup/" + file);
  std::string text;
  if (!(in >> text) || text == "max") return std::nullopt;
  try {
    return std::stod(text);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

// A body's particles: those of its file, or at most the lattice points of
// the box around its shape (whole spacings per axis, at least one), as
// build_system lays them; an upper bound for shapes other than a box.
double particles_of(const BodySpec& b, int dimension) {
  if (b.particles) return static_cast<double>(b.particles->size());
  const BoxShape box = b.shape.bounds();
  double n = 1.0;
  for (int d = 0; d < dimension; ++d) n *= std::max(1.0, std::floor((box.max[d] - box.min[d]) / b.spacing[d] + 1e-9));
  return n;
}

// Bytes per particle of a model's internal variables (none stored when it has none).
std::size_t state_bytes(const Material& m) {
  return std::visit(
      [](const auto& model) -> std::size_t {
        using State = typename std::decay_t<decltype(model)>::State;
        return std::is_empty_v<State> ? 0 : sizeof(State);
      },
      m);
}

}  // namespace

MemoryEstimate estimate_memory(const Case& c) {
  const SystemSpec& s = c.system;
  MemoryEstimate e;
  for (const BodySpec& b : s.bodies) {
    e.body_particles.push_back(particles_of(b, s.dimension));
    e.particles += e.body_particles.back();
  }
  e.steps = static_cast<double>(c.time_step.planned_steps());

  std::vector<Material> materials;
  std::size_t largest_state = 0;
  for (const NamedMaterial& m : s.materials) {
    materials.push_back(m.model);
    largest_state = std::max(largest_state, state_bytes(m.model));
  }
  // One output snapshot's bytes per particle (the guard keeps a second).
  double snapshot = 0.0;
  for (const OutputField& f : output_fields_of(materials)) {
    if (std::ranges::find(c.output.fields, f.name) == c.output.fields.end()) continue;
    snapshot += f.integer ? 4.0 : 8.0 * f.components;
  }

  with_dimension_and_shape(s.dimension, s.shape_function, [&]<int D, class Shape>() {
    const double vec = sizeof(Vec<D>);
    // ParticleBatch's columns (discretisation/grid/particles.hpp): x, v, x0 when
    // kept, mass, volume, stress, strain, id, APIC's affine velocity and the
    // model's state.
    const double affine = s.velocity_update == VelocityUpdate::apic ? D * D * sizeof(double) : 0.0;
    double columns = 2 * vec + (s.keep_initial_positions ? vec : 0.0) + 2 * sizeof(double) + 2 * sizeof(Voigt) +
                     sizeof(std::uint32_t) + affine + static_cast<double>(largest_state);
    // Transient: x grows by push_back at set-up (up to twice its size), and
    // a sort holds a key, an order and one permuted column.
    const double transient = std::max(vec, 8.0 + std::max<double>(sizeof(Voigt), static_cast<double>(largest_state)));
    e.bytes_per_particle = columns + transient + snapshot * (c.guard_every > 0 ? 2.0 : 1.0);

    // Grid<D>: mass, momentum, force, velocity, velocity change; the
    // stiffness where the gradient jumps; XPIC's nodes (mass, momentum,
    // iterate, correction). The sort counts particles per cell of the
    // block-padded grid (two 32-bit arrays).
    e.nodes = e.padded_cells = 1.0;
    for (int d = 0; d < D; ++d) {
      const int B = BlockLayout<D, Shape>::block_cells;
      e.nodes *= s.grid.cells[d] + 1.0;
      e.padded_cells *= std::ceil(static_cast<double>(s.grid.cells[d]) / B) * B;
    }
    const double xpic = s.velocity_update == VelocityUpdate::xpic ? 1.0 + 3.0 * D : 0.0;
    e.bytes_per_node = sizeof(double) * (1.0 + 4.0 * D + (Shape::gradient_jumps ? 1.0 : 0.0) + xpic) +
                       2.0 * sizeof(std::uint32_t) * e.padded_cells / e.nodes;
  });
  e.particle_bytes = e.particles * e.bytes_per_particle;
  e.node_bytes = e.nodes * e.bytes_per_node;
  e.total_bytes = program_bytes + e.particle_bytes + e.node_bytes;
  return e;
}

std::uint64_t memory_limit() {
  {
    const std::lock_guard lock(limit_mutex);
    if (max_memory) return *max_memory;
  }
  double available = meminfo("MemAvailable").value_or(std::numeric_limits<double>::max());
  if (const auto limit = cgroup_value("memory.max")) {
    available = std::min(available, *limit - cgroup_value("memory.current").value_or(0.0));
  }
  // ulimit -v: the address space (which counts more than the resident
  // memory estimated, so a case close to it may still run out: exit 2).
  struct rlimit space {};
  if (::getrlimit(RLIMIT_AS, &space) == 0 && space.rlim_cur != RLIM_INFINITY) {
    available = std::min(available, static_cast<double>(space.rlim_cur));
  }
  return static_cast<std::uint64_t>(std::clamp(available, 0.0, 1.8e19));
}

void set_memory_limit(std::optional<std::uint64_t> bytes) {
  const std::lock_guard lock(limit_mutex);
  max_memory = bytes;
}

std::optional<std::uint64_t> parse_memory_size(const std::string& text) {
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  const std::string suffix = text.substr(used);
  double scale = 1.0;
  if (suffix == "K" || suffix == "k") scale = 1024.0;
  else if (suffix == "M") scale = 1024.0 * 1024;
  else if (suffix == "G") scale = 1024.0 * 1024 * 1024;
  else if (suffix == "T") scale = 1024.0 * 1024 * 1024 * 1024;
  else if (!suffix.empty()) return std::nullopt;
  const double bytes = value * scale;
  if (!std::isfinite(bytes) || bytes < 1.0 || bytes > 1.8e19) return std::nullopt;
  return static_cast<std::uint64_t>(bytes);
}

std::string memory_text(double bytes) {
  const char* units[] = {"B", "kB", "MB", "GB", "TB", "PB", "EB"};
  int u = 0;
  while (bytes >= 1000.0 && u < 6) bytes /= 1000.0, ++u;
  if (u == 6 && bytes >= 1000.0) return readable_text(bytes) + " EB";
  char text[32];
  std::snprintf(text, sizeof text, bytes < 10.0 ? "%.2g %s" : "%.0f %s", bytes, units[u]);
  return text;
}

std::string estimate_text(const MemoryEstimate& e) {
  return "estimate: " + readable_text(e.particles) + " particles (" + readable_text(e.bytes_per_particle) +
         " B each at peak), " + readable_text(e.nodes) + " grid nodes (" + readable_text(e.bytes_per_node) +
         " B each), " + readable_text(e.steps) + " steps; about " + memory_text(e.total_bytes) + " of memory";
}

void check_memory(const Case& c, TableReader& root) {
  const MemoryEstimate e = estimate_memory(c);
  // The body with the most particles: the keys to change if particles dominate.
  const auto largest = std::max_element(e.body_particles.begin(), e.body_particles.end());
  const std::size_t body = static_cast<std::size_t>(largest - e.body_particles.begin());
  TableReader largest_body = root.tables("bodies")[body];
  const std::string spacing_key = largest_body.has("spacing") ? "spacing" : "particles_per_cell";
  const auto blame = [&](const std::string& problem) {
    if (e.node_bytes >= e.particle_bytes) root.table("grid").fail("cells", problem);
    largest_body.fail(spacing_key, problem);
  };
  const std::string figures = readable_text(e.particles) + " particles (" + memory_text(e.particle_bytes) + ", " +
                              readable_text(*largest) + " of them in bodies[" + std::to_string(body) +
                              "] from its min, max and " + spacing_key + ") and " + readable_text(e.nodes) +
                              " grid nodes (" + memory_text(e.node_bytes) + ", from grid.cells)";
  const double limit = static_cast<double>(memory_limit());
  if (e.total_bytes > limit) {
    blame("a case that fits in memory: it needs about " + memory_text(e.total_bytes) + " for " + figures +
          ", more than the " + memory_text(limit) + " available (--max-memory sets the limit)");
  }
  // Particle ids and the sort's keys (a cell of the block-padded grid) are 32-bit.
  if (e.particles >= 4.29e9) blame("fewer than 2^32 particles in all; the case makes " + figures);
  if (e.padded_cells >= 4.29e9) {
    root.table("grid").fail("cells", "fewer than 2^32 cells in all (counted in whole blocks of cells; these are " +
                                         readable_text(e.padded_cells) + ")");
  }
}

}  // namespace flowmpm
