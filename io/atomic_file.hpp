// Files that are either complete or absent: written to a temporary name in
// the same directory, flushed, then renamed into place (rename is atomic on
// POSIX file systems), so an interrupted run never leaves half a file.
#pragma once
#include <filesystem>
#include <functional>
#include <string_view>

namespace flowmpm {

// Writes `contents` to `path` atomically; throws std::runtime_error naming
// the path on failure.
void write_file_atomically(const std::filesystem::path& path, std::string_view contents);

// Receives a file's text piece by piece.
using TextSink = std::function<void(std::string_view)>;

// The same for a text that `produce` hands to its sink piece by piece, so
// that a long file is never held in memory whole. An exception from
// `produce` leaves `path` as it was and is passed on.
void write_file_atomically(const std::filesystem::path& path, const std::function<void(const TextSink&)>& produce);

}  // namespace flowmpm
