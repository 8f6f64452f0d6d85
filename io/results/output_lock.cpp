#include "io/results/output_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <regex>
#include <stdexcept>
#include <system_error>

namespace flowmpm {
namespace {

std::string advice() { return "; set output.directory or --output"; }

[[noreturn]] void cannot(const std::filesystem::path& directory, const std::string& what, int error) {
  throw CaseError("output directory " + directory.string() + ": " + what + " (" + std::strerror(error) + ")" +
                  advice());
}

// The lock file's text: who holds the directory.
std::string holder_text(const std::string& holder) {
  char host[256] = "?";
  ::gethostname(host, sizeof host - 1);
  const std::time_t now = std::time(nullptr);
  char started[64] = "?";
  std::strftime(started, sizeof started, "%Y-%m-%d %H:%M:%S", std::localtime(&now));
  return "process " + std::to_string(::getpid()) + " on " + host + ", " + holder + ", started " + started + "\n";
}

std::string read_all(int fd) {
  std::string text;
  char buffer[512];
  ::lseek(fd, 0, SEEK_SET);
  for (ssize_t n; (n = ::read(fd, buffer, sizeof buffer)) > 0;) text.append(buffer, static_cast<std::size_t>(n));
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  return text;
}

}  // namespace

OutputLock::OutputLock(const std::filesystem::path& directory, const std::string& holder)
    : path_(directory / file_name) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) cannot(directory, "cannot create it", error.value());
  // The lock file may be removed by the run that held it between our open
  // and our flock: then we hold a lock on a file nobody else sees, and try
  // again with the file that is now there.
  for (;;) {
    const int fd = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) cannot(directory, "cannot write in it", errno);
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int e = errno;
      if (e == EINTR) {
        ::close(fd);
        continue;
      }
      if (e != EWOULDBLOCK) {
        ::close(fd);
        cannot(directory, "cannot lock " + path_.string(), e);
      }
      std::string who = read_all(fd);
      ::close(fd);
      if (who.empty()) who = "a process that has not written its id yet";
      throw OutputInUse("output directory " + directory.string() + " is in use by another flowmpm run (" + who +
                        "); wait for it to end, or choose another directory (output.directory or --output)");
    }
    struct stat held {}, named {};
    if (::fstat(fd, &held) == 0 && ::stat(path_.c_str(), &named) == 0 && held.st_ino == named.st_ino &&
        held.st_dev == named.st_dev) {
      fd_ = fd;
      break;
    }
    ::close(fd);
  }
  const std::string text = holder_text(holder);
  if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, text.data(), text.size(), 0) != static_cast<ssize_t>(text.size())) {
    const int e = errno;
    ::unlink(path_.c_str());
    ::close(fd_);
    cannot(directory, "cannot write " + path_.string(), e);
  }
}

OutputLock::~OutputLock() {
  // Unlinked while still held, so that no other run takes the lock of a
  // file about to disappear.
  ::unlink(path_.c_str());
  ::close(fd_);
}

std::size_t remove_stale_temporaries(const std::filesystem::path& directory) {
  // write_file_atomically's names: the target, ".tmp-", the writer's pid and a counter.
  static const std::regex temporary(R"(.+\.tmp-[0-9]+-[0-9]+)");
  std::size_t removed = 0;
  std::error_code error;
  for (const std::filesystem::path& folder : {directory, directory / "steps"}) {
    for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
      const std::string name = entry.path().filename().string();
      if (!std::regex_match(name, temporary) || !entry.is_regular_file(error)) continue;
      if (std::filesystem::remove(entry.path(), error)) ++removed;
    }
  }
  return removed;
}

void start_output(const std::filesystem::path& directory, const RunSummary& running) {
  remove_stale_temporaries(directory);
  write_summary(directory / "summary.json", running);
  for (const char* name : {"results.xdmf", "results.h5", "steps"}) {
    std::error_code error;
    std::filesystem::remove_all(directory / name, error);
    if (error) {
      throw std::runtime_error("cannot remove the earlier run's " + (directory / name).string() + ": " +
                               error.message());
    }
  }
}

void check_output_directory(const std::filesystem::path& directory) {
  std::filesystem::path existing = directory.empty() ? "." : directory;
  std::error_code error;
  while (!std::filesystem::exists(existing, error)) {
    const std::filesystem::path parent = existing.has_parent_path() ? existing.parent_path() : ".";
    if (parent == existing) break;
    existing = parent;
  }
  if (!std::filesystem::is_directory(existing, error)) {
    throw CaseError("output directory " + directory.string() + ": " + existing.string() + " is not a directory" +
                    advice());
  }
  if (::access(existing.c_str(), W_OK | X_OK) != 0) {
    cannot(directory, existing == directory ? "cannot write in it" : "cannot create it in " + existing.string(),
           errno);
  }
}

}  // namespace flowmpm
