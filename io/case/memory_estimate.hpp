// What a case will cost before anything is built: the particles, grid nodes
// and steps it makes and the memory they take at peak, from the sizes of
// the arrays the engine and the writers hold (counted in double, so that an
// absurd case cannot overflow the count). read_case rejects a case whose
// estimate exceeds the memory available (or --max-memory), naming the
// figure and the keys that drive it, so that neither `check` nor `run`
// meets std::bad_alloc or an overflowing count. See docs/guide/running.md.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "io/case/case_file.hpp"

namespace flowmpm {

class TableReader;

struct MemoryEstimate {
  std::vector<double> body_particles;  // per body of the case
  double particles = 0.0;
  double nodes = 0.0;
  double padded_cells = 0.0;        // cells of the grid padded to whole blocks (the sort's keys)
  double steps = 0.0;               // planned (with dt = "auto": end_time over the first dt)
  double bytes_per_particle = 0.0;  // at peak: stored columns, sort buffers, output snapshots
  double bytes_per_node = 0.0;      // nodal fields and the sort's per-cell counts
  double particle_bytes = 0.0, node_bytes = 0.0;
  double total_bytes = 0.0;         // the above and the program itself
};

MemoryEstimate estimate_memory(const Case& c);

// The memory a case may take: --max-memory if given, else what the
// machine has available (MemAvailable of /proc/meminfo, the cgroup's limit
// less its use where one is set, and the address space limit, ulimit -v).
std::uint64_t memory_limit();
// Sets the --max-memory limit (nullopt: the machine's available memory).
void set_memory_limit(std::optional<std::uint64_t> bytes);
// "512M", "2G", "1.5G", "1000000" (bytes; K, M, G, T are powers of 1024):
// the bytes, or nullopt if the text is none of these.
std::optional<std::uint64_t> parse_memory_size(const std::string& text);

// "1.5 GB", "320 MB": for messages.
std::string memory_text(double bytes);

// One line for the log: particles, nodes, steps and the memory estimate.
std::string estimate_text(const MemoryEstimate& e);

// A case with more steps than this is logged as long (a warning).
constexpr double long_run_steps = 1e7;

// Throws CaseError, from `root` (the case file's root table), naming the
// figure and the keys that drive it when the estimate exceeds
// memory_limit() or the particle count exceeds what the engine indexes
// (32-bit particle ids).
void check_memory(const Case& c, TableReader& root);

}  // namespace flowmpm
