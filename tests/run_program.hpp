// Shared by the tests that run the flowmpm binary as a separate process:
// a scratch directory, running the program, and reading what it wrote.
#pragma once
#include <doctest/doctest.h>
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

extern char** environ;  // the environment start_program passes on

namespace flowmpm::testing {

// A fresh directory, removed with everything in it at the end of the test.
struct TempDir {
  std::filesystem::path path;
  explicit TempDir(const std::string& prefix = "flowmpm_test") {
    static std::atomic<int> counter{0};
    path = std::filesystem::temp_directory_path() /
           (prefix + "_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
};

struct Result {
  int status = -1;     // exit status; 128 + signal number if killed by a signal
  std::string output;  // stdout and stderr together
  double peak_resident_bytes = 0.0;  // the program's peak resident size (ru_maxrss)
};

// A program started by start_program, still running.
struct Running {
  pid_t pid = -1;
  int output = -1;  // read end of its stdout and stderr
};

// Starts `argv` (argv[0] a path) in the working directory `cwd`, with
// `environment` ("NAME=value") added to ours; stdout and stderr go to a pipe.
inline Running start_program(const std::vector<std::string>& argv, const std::filesystem::path& cwd,
                             const std::vector<std::string>& environment = {}) {
  // Everything the child needs is prepared before fork().
  std::vector<std::string> storage(argv), env_storage(environment);
  std::vector<char*> args, env;
  for (std::string& s : storage) args.push_back(s.data());
  args.push_back(nullptr);
  for (std::string& s : env_storage) env.push_back(s.data());
  for (char** e = environ; *e; ++e) env.push_back(*e);
  env.push_back(nullptr);
  const std::string dir = cwd.string();

  int fds[2];
  if (::pipe(fds) != 0) {
    FAIL("pipe() failed");
    return {};
  }
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    FAIL("fork() failed");
    return {};
  }
  if (pid == 0) {
    ::dup2(fds[1], STDOUT_FILENO);
    ::dup2(fds[1], STDERR_FILENO);
    ::close(fds[0]);
    ::close(fds[1]);
    if (::chdir(dir.c_str()) != 0) ::_exit(126);
    ::execve(args[0], args.data(), env.data());
    ::_exit(127);
  }
  ::close(fds[1]);
  return {pid, fds[0]};
}

// Reads the program's output until it closes it, and waits for it to end.
inline Result wait_for(const Running& program) {
  Result result;
  char buffer[4096];
  for (;;) {
    const ssize_t n = ::read(program.output, buffer, sizeof buffer);
    if (n > 0) {
      result.output.append(buffer, static_cast<std::size_t>(n));
    } else if (n == 0 || errno != EINTR) {
      break;
    }
  }
  ::close(program.output);
  int status = 0;
  struct rusage usage {};
  while (::wait4(program.pid, &status, 0, &usage) < 0 && errno == EINTR) {
  }
  result.peak_resident_bytes = static_cast<double>(usage.ru_maxrss) * 1024.0;  // ru_maxrss is in kB
  if (WIFEXITED(status)) {
    result.status = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    result.status = 128 + WTERMSIG(status);
  }
  return result;
}

// Runs the flowmpm binary with `args` in the working directory `cwd`.
inline Result run_flowmpm(const std::vector<std::string>& args, const std::filesystem::path& cwd,
                          const std::vector<std::string>& environment = {}) {
  std::vector<std::string> argv{FLOWMPM_EXECUTABLE};
  argv.insert(argv.end(), args.begin(), args.end());
  return wait_for(start_program(argv, cwd, environment));
}

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  REQUIRE(out.good());
}

inline bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

inline std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

inline std::vector<std::string> non_empty_lines(const std::string& text) {
  std::vector<std::string> lines;
  for (const std::string& line : lines_of(text)) {
    if (line.find_first_not_of(" \t\r") != std::string::npos) lines.push_back(line);
  }
  return lines;
}

// The names in `dir`, sorted.
inline std::vector<std::string> files_in(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace flowmpm::testing
