// Keeps the two indexes of the results, results.h5 and results.xdmf (io/
// results_h5.hpp, io/results/xdmf.hpp), in step with the step files at a bounded
// cost. Both are rewritten (atomically) after an output step only when the
// number of steps has doubled since the last rewrite or `interval` seconds
// have passed, and by finish(): the index text written over a run is a few
// times its final size, so the cost of an output step does not grow with
// the run (rewriting at every step made it grow with the square of the run
// length). Between rewrites the indexes may lag the step files by up to
// `interval`; they never name a step whose file is not complete.
#pragma once
#include <filesystem>
#include <string>

#include "io/results/results_h5.hpp"

namespace flowmpm {

class ResultsIndex {
 public:
  // `xdmf_path` is results.xdmf, in the directory of results.h5.
  explicit ResultsIndex(std::filesystem::path xdmf_path, double interval_seconds = 2.0);
  // After an output step of `results`.
  void update(const ResultsH5& results);
  // Brings the indexes up to date (at the end of a run, or before it stops).
  void finish(const ResultsH5& results);
  // How many times the indexes were written.
  int rewrites() const { return rewrites_; }

 private:
  void rewrite(const ResultsH5& results);

  std::filesystem::path xdmf_path_;
  double interval_;
  std::size_t indexed_ = 0;    // steps in the last rewrite
  double last_rewrite_ = 0.0;  // steady clock, s
  int rewrites_ = 0;
};

}  // namespace flowmpm
