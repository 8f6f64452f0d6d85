#include "io/results/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>

namespace flowmpm {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const char* step,
                       const std::string& reason) {
  throw std::runtime_error("cannot write " + path.string() + ": " + step + ": " + reason);
}

// Writes all of `contents`, retrying short and interrupted writes; returns 0
// or the errno of the failure.
int write_all(int fd, std::string_view contents) {
  while (!contents.empty()) {
    const ssize_t n = ::write(fd, contents.data(), contents.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    contents.remove_prefix(static_cast<std::size_t>(n));
  }
  return 0;
}

// The temporary name beside `path`: NAME.tmp-PID-N (what
// remove_stale_temporaries, io/results/output_lock.hpp, recognises). The counter
// keeps names distinct between threads of one process.
std::filesystem::path temporary_path(const std::filesystem::path& path) {
  static std::atomic<unsigned> counter{0};
  std::filesystem::path tmp = path;
  tmp += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  return tmp;
}

// Flushes the file or directory at `path` to disk through a descriptor of
// its own (`flags`: O_DIRECTORY for a directory); returns 0 or the errno of
// the failure.
int flush_to_disk(const std::filesystem::path& path, int flags) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | flags);
  if (fd < 0) return errno;
  const int error = ::fsync(fd) != 0 ? errno : 0;
  ::close(fd);
  return error;
}

// Renames the written temporary file `tmp` to `path`, or, when `error` (an
// errno) says that writing it failed at `step`, removes it; throws naming
// `path` on any failure.
void commit(const std::filesystem::path& tmp, const std::filesystem::path& path, const char* step, int error) {
  std::string reason;
  if (error == 0) {
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (!ec) return;
    step = "rename failed";
    reason = ec.message();
  } else {
    reason = std::strerror(error);
  }
  std::error_code ignored;
  std::filesystem::remove(tmp, ignored);
  fail(path, step, reason);
}

}  // namespace

void write_file_atomically(const std::filesystem::path& path, std::string_view contents) {
  write_file_atomically(path, [&](const TextSink& sink) { sink(contents); });
}

void write_file_atomically(const std::filesystem::path& path, const std::function<void(const TextSink&)>& produce) {
  const std::filesystem::path tmp = temporary_path(path);
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) fail(path, "cannot create temporary file", std::strerror(errno));

  // Small pieces gathered into writes of about 64 kB, a larger piece (a
  // whole text given at once: a checkpoint) written as it is, not copied;
  // the first failure is kept and the rest of the text dropped.
  constexpr std::size_t gathered = 65536;
  const char* step = "write failed";
  int error = 0;
  std::string buffer;
  const auto write = [&](std::string_view text) {
    if (error == 0) error = write_all(fd, text);
  };
  const auto flush = [&] {
    write(buffer);
    buffer.clear();
  };
  try {
    produce([&](std::string_view piece) {
      if (piece.size() >= gathered) {
        flush();
        write(piece);
        return;
      }
      buffer += piece;
      if (buffer.size() >= gathered) flush();
    });
  } catch (...) {
    ::close(fd);
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw;
  }
  flush();
  if (error == 0 && ::fsync(fd) != 0) {
    error = errno;
    step = "fsync failed";
  }
  if (::close(fd) != 0 && error == 0) {
    error = errno;
    step = "close failed";
  }
  commit(tmp, path, step, error);
}

void write_file_atomically_by_name(const std::filesystem::path& path,
                                   const std::function<void(const std::filesystem::path& temporary)>& write) {
  const std::filesystem::path tmp = temporary_path(path);
  try {
    write(tmp);
  } catch (...) {
    // Emptied before it is removed: a writer that failed may hold it open
    // (HDF5 after a failed close), which would keep its blocks in use.
    std::error_code ignored;
    std::filesystem::resize_file(tmp, 0, ignored);
    std::filesystem::remove(tmp, ignored);
    throw;
  }
  // The library closed the file: its data is flushed to disk before the rename.
  commit(tmp, path, "flush to disk failed", flush_to_disk(tmp, 0));
}

void flush_directory(const std::filesystem::path& directory) {
  if (const int error = flush_to_disk(directory, O_DIRECTORY); error != 0) {
    throw std::runtime_error("cannot flush the directory " + directory.string() + " to disk: " +
                             std::strerror(error));
  }
}

}  // namespace flowmpm
