// One run owns an output directory at a time (docs/guide/output.md). A run takes
// the directory's lock before it touches anything in it: the file
// flowmpm.lock, held with flock(2), which the kernel releases when the
// process ends in any way (a killed run leaves no lock behind, at most a
// lock file that the next run takes over). A second run into the same
// directory is refused at once, naming the process that holds it, and
// changes nothing there.
#pragma once
#include <cstddef>
#include <filesystem>
#include <string>

#include "core/errors.hpp"
#include "io/results/summary_json.hpp"

namespace flowmpm {

// The output directory is held by another run (exit status 1, like any
// other reason the command cannot start; nothing was written).
class OutputInUse : public CaseError {
 public:
  using CaseError::CaseError;
};

class OutputLock {
 public:
  static constexpr const char* file_name = "flowmpm.lock";

  // Creates `directory` if needed and takes its lock, recording this
  // process's id, host, start time and `holder` (what runs: the case file)
  // in the lock file. Throws OutputInUse naming the directory and the
  // process that holds it, CaseError when the directory cannot be created
  // or written (a read-only file system, no permission).
  OutputLock(const std::filesystem::path& directory, const std::string& holder);
  // Removes the lock file, then releases the lock.
  ~OutputLock();
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

 private:
  std::filesystem::path path_;
  int fd_ = -1;
};

// Removes the temporary files that an earlier run, killed in the middle of
// an atomic write (io/results/atomic_file.hpp), left in `directory` and its steps/:
// NAME.tmp-PID-N.
// Only with the directory's lock held: then no other run is writing them.
// Returns how many were removed.
std::size_t remove_stale_temporaries(const std::filesystem::path& directory);

// Makes a locked output directory ready for a new run: removes stale
// temporaries, marks the directory with `running` as summary.json (status
// "running"), so that no earlier run's summary can label the new results,
// and removes the earlier run's results.xdmf, results.h5 and step files
// (steps/). They are unlinked, not truncated: a reader that has an old file
// open (h5py, ParaView) keeps reading it, and the new run writes new files.
void start_output(const std::filesystem::path& directory, const RunSummary& running);

// What `flowmpm check` can tell without touching anything: throws
// CaseError if `directory` cannot be created or written (its nearest
// existing ancestor is not a writable directory).
void check_output_directory(const std::filesystem::path& directory);

}  // namespace flowmpm
