// results.h5: one group per output step, /steps/<step as 8 digits>, holding
// the particle fields of the snapshot (the case's output.fields), with
// "time" (s) and "step" as attributes of the group. The file is flushed after every output step so
// that an interrupted run keeps every step written before it.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/snapshot.hpp"

namespace flowmpm {

class ResultsH5 {
 public:
  // Creates (truncates) the file; throws std::runtime_error naming the path.
  explicit ResultsH5(const std::filesystem::path& path);
  ~ResultsH5();
  ResultsH5(const ResultsH5&) = delete;
  ResultsH5& operator=(const ResultsH5&) = delete;

  // Writes one output step and flushes the file. Throws std::invalid_argument
  // when a field's size does not match the count or the fields differ from
  // the earlier steps' (nothing is then written), std::runtime_error naming
  // the file and dataset on HDF5 errors.
  void write(const ParticleSnapshot& snapshot);

  // Name of the group of a step inside the file, e.g. "/steps/00000010".
  static std::string group_name(std::int64_t step);

  struct WrittenStep {
    std::int64_t step;
    double time;
    std::size_t count;
  };
  const std::vector<WrittenStep>& written() const { return written_; }
  // The fields of every written step (those of the first).
  const std::vector<OutputField>& fields() const { return fields_; }
  std::uintmax_t bytes_written() const { return bytes_; }

 private:
  long long file_;  // hid_t, kept opaque so that hdf5.h stays out of headers
  std::vector<OutputField> fields_;
  std::vector<WrittenStep> written_;
  std::uintmax_t bytes_ = 0;
  std::string path_;  // for error messages
};

}  // namespace flowmpm
