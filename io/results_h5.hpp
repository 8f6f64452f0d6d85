// results.h5 (README "Results"): the run's metadata as attributes of the
// root group; /particle_index, the row numbers 0..n-1 written once (the
// XDMF topology's connectivity); and one group per output step,
// /steps/<step as 8 digits>, holding the particle fields of the snapshot
// (rows in particle id order), with "time" (s) and "step" as attributes.
// A step group is written in full, then marked complete (attribute
// "complete" = 1) and the file flushed: a reader (and the XDMF index) takes
// only complete steps, so a run that dies mid-step leaves no half step that
// looks whole.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/snapshot.hpp"

namespace flowmpm {

// The root group's attributes: what the file holds and how to read it.
struct ResultsMetadata {
  std::string program_version;  // flowmpm's version
  std::string commit;           // the source's git commit, "" when unknown
  std::string case_name, case_file;
  int dimension = 3;
  std::string stress_state;  // "3D", "plane strain", "plane stress", "uniaxial stress"
  std::string scheme, shape_function;
  std::vector<std::string> materials;  // names, by the index the `material` field holds
};

class ResultsH5 {
 public:
  // The format version written to the root group's "format_version".
  static constexpr int format_version = 2;

  // Creates (truncates) the file and writes the metadata; throws
  // std::runtime_error naming the path.
  ResultsH5(const std::filesystem::path& path, const ResultsMetadata& metadata);
  ~ResultsH5();
  ResultsH5(const ResultsH5&) = delete;
  ResultsH5& operator=(const ResultsH5&) = delete;

  // Writes one output step, marks it complete and flushes the file. Throws
  // std::invalid_argument when a field's size does not match the count, the
  // fields differ from the earlier steps' or there are more particles than
  // in the first step (nothing is then written), std::runtime_error naming
  // the file and dataset on HDF5 errors (the step is then incomplete).
  void write(const ParticleSnapshot& snapshot);

  // Name of the group of a step inside the file, e.g. "/steps/00000010".
  static std::string group_name(std::int64_t step);
  // The connectivity dataset, 0..n-1 (int32).
  static constexpr const char* particle_index = "/particle_index";

  struct WrittenStep {
    std::int64_t step;
    double time;
    std::size_t count;
  };
  // The complete steps, in the order written.
  const std::vector<WrittenStep>& written() const { return written_; }
  // The fields of every written step (those of the first).
  const std::vector<OutputField>& fields() const { return fields_; }
  // The length of /particle_index (0 before the first step).
  std::size_t index_length() const { return index_length_; }
  std::uintmax_t bytes_written() const { return bytes_; }

 private:
  long long file_;  // hid_t, kept opaque so that hdf5.h stays out of headers
  std::vector<OutputField> fields_;
  std::vector<WrittenStep> written_;
  std::size_t index_length_ = 0;
  std::uintmax_t bytes_ = 0;
  std::string path_;  // for error messages
};

}  // namespace flowmpm
