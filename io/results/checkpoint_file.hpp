// checkpoint.bin: the state records of a run (engine/state_records.hpp) in
// one binary file, written atomically (temporary file, fsync, rename) so
// that the file in place is always a whole checkpoint. Layout: the magic
// line "flowmpm checkpoint 1\n", then per record its name length (u32),
// name, value length (u64) and value, then the FNV-1a digest (u64) of all
// that went before; integers little-endian. The digest tells a damaged file
// (cut short, overwritten) from a whole one. See
// docs/guide/checkpoint_restart.md.
#pragma once
#include <filesystem>

#include "engine/state_records.hpp"

namespace flowmpm {

// The checkpoint's name in a run's output directory.
inline constexpr const char* checkpoint_file_name = "checkpoint.bin";

// Writes `records` to `path` atomically; throws std::runtime_error naming
// the path on failure.
void write_checkpoint(const std::filesystem::path& path, const StateRecords& records);

// Reads a checkpoint; throws CaseError naming the path when the file cannot
// be read or is not a whole checkpoint.
StateRecords read_checkpoint(const std::filesystem::path& path);

}  // namespace flowmpm
