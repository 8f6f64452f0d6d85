// Files that are either complete or absent: written to a temporary name in
// the same directory, flushed to disk, then renamed into place (rename is
// atomic on POSIX file systems), so an interrupted run never leaves half a
// file.
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

// The same for a file that a library writes by name (HDF5): `write` creates,
// fills and closes the file at the temporary name it is given. An exception
// from `write` removes the temporary file, leaves `path` as it was and is
// passed on.
void write_file_atomically_by_name(const std::filesystem::path& path,
                                   const std::function<void(const std::filesystem::path& temporary)>& write);

// Flushes a directory's entries to disk (the names that renames gave its
// files), so that a file written later that names them (an index) cannot
// outlive them in a power cut; throws std::runtime_error naming it.
void flush_directory(const std::filesystem::path& directory);

}  // namespace flowmpm
