// The particle results (docs/guide/output.md): one HDF5 file per output step,
// steps/<step as 8 digits>.h5 beside results.h5, holding the particle fields
// of the snapshot (rows in particle id order) with "time" (s) and "step" as
// attributes of its root group; and results.h5, the index: the run's
// metadata as attributes of the root group, /particle_index (the row
// numbers 0..n-1, the XDMF topology's connectivity) and the group /steps
// whose members are external links to the step files' root groups, so that
// results.h5 reads as one file (/steps/00000010/position).
// Every file is written under a temporary name, flushed to disk and renamed
// into place (io/results/atomic_file.hpp): a step file is complete or absent after
// any failure (a killed process, a full disk, a power cut) and the files
// already written are never touched again. The index is rewritten at a
// bounded rate (io/results/results_index.hpp) and lists written steps only.
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
  // The case's bodies: their names and where their rows are. Body b's
  // particles are rows body_rows[b] to body_rows[b + 1] - 1 (bodies.size()
  // + 1 values): ids are given body by body.
  std::vector<std::string> bodies;
  std::vector<std::int64_t> body_rows;
};

class ResultsH5 {
 public:
  // The format version written to the root group's "format_version".
  static constexpr int format_version = 3;

  // Starts the results at `path` (results.h5): creates the directory steps/
  // beside it and writes an index without steps; throws std::runtime_error
  // naming the path.
  ResultsH5(const std::filesystem::path& path, const ResultsMetadata& metadata);
  // Where a run restarted from a checkpoint takes up existing results: its
  // step files up to `last_step`, `keep` of them, with the fields `fields`.
  // Step files after `last_step` were written after the checkpoint and are
  // removed.
  struct Continuation {
    std::size_t keep = 0;
    std::int64_t last_step = 0;
    std::vector<OutputField> fields;
  };
  // Throws std::runtime_error naming the file and what it lacks when the
  // results cannot be continued so; reads only.
  static void check_continuation(const std::filesystem::path& path, const Continuation& from);
  // Continues the results (check_continuation first): removes the step
  // files after `last_step` and rewrites the index.
  ResultsH5(const std::filesystem::path& path, const ResultsMetadata& metadata, const Continuation& from);

  // Writes one output step's file. Throws std::invalid_argument when a
  // field's size does not match the count, the fields differ from the
  // earlier steps', there are more particles than in the first step or the
  // step is not after the last one written (nothing is then written),
  // std::runtime_error naming the file and dataset on HDF5 errors or a full
  // disk (the step's file is then absent).
  void write(const ParticleSnapshot& snapshot);
  // Rewrites results.h5 with a link to each step written so far.
  void write_index() const;

  // A step's name: its number as 8 digits, e.g. "00000010" (the link's
  // name in /steps, the step file's stem).
  static std::string step_label(std::int64_t step);
  // The path of a step's group as read through results.h5, e.g.
  // "/steps/00000010".
  static std::string group_name(std::int64_t step);
  // A step's file relative to results.h5's directory, e.g. "steps/00000010.h5".
  static std::string step_file(std::int64_t step);
  // The connectivity dataset in results.h5, 0..n-1 (int32).
  static constexpr const char* particle_index = "/particle_index";

  struct WrittenStep {
    std::int64_t step;
    double time;
    std::size_t count;
  };
  // The steps written, in order.
  const std::vector<WrittenStep>& written() const { return written_; }
  // The fields of every written step (those of the first).
  const std::vector<OutputField>& fields() const { return fields_; }
  // The length of /particle_index (0 before the first step).
  std::size_t index_length() const { return index_length_; }
  // results.h5's path.
  const std::filesystem::path& path() const { return path_; }
  // The field data written to step files (bytes).
  std::uintmax_t bytes_written() const { return bytes_; }

 private:
  std::filesystem::path path_, directory_;  // results.h5 and the directory holding it
  ResultsMetadata metadata_;
  std::vector<OutputField> fields_;
  std::vector<WrittenStep> written_;
  std::size_t index_length_ = 0;
  std::uintmax_t bytes_ = 0;
};

}  // namespace flowmpm
