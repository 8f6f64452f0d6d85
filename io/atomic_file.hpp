// Files that are either complete or absent: written to a temporary name in
// the same directory, flushed, then renamed into place (rename is atomic on
// POSIX file systems), so an interrupted run never leaves half a file.
#pragma once
#include <filesystem>
#include <string_view>

namespace flowmpm {

// Writes `contents` to `path` atomically; throws std::runtime_error naming
// the path on failure.
void write_file_atomically(const std::filesystem::path& path, std::string_view contents);

}  // namespace flowmpm
