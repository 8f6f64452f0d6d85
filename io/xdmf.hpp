// results.xdmf: an XDMF 3 index of results.h5 (a temporal collection of
// Polyvertex grids, one per output step) so that ParaView opens the particle
// time series directly, with its default reader and the legacy one.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "io/atomic_file.hpp"
#include "io/results_h5.hpp"

namespace flowmpm {

// The XDMF text for the steps written so far, handed to `sink` a step at a
// time; `h5_name` is the HDF5 file's name relative to the XDMF file.
// Position is the grid's geometry: throws std::invalid_argument when it is
// not among the results' fields.
void xdmf_document(const std::string& h5_name, const ResultsH5& results, const TextSink& sink);
// The same text as one string.
std::string xdmf_document(const std::string& h5_name, const ResultsH5& results);

// Writes the XDMF text to `path` atomically, never holding it whole (it
// grows by about 2.4 kB per output step).
void write_xdmf(const std::filesystem::path& path, const std::string& h5_name,
                const ResultsH5& results);

// Keeps results.xdmf in step with results.h5 at a bounded cost. The whole
// document is rewritten (atomically) after an output step only when the
// number of steps has doubled since the last rewrite or `interval` seconds
// have passed, and by finish(): the text written over a run is a few times
// its final size, so the cost of an output step does not grow with the run
// (rewriting at every step made it grow with the square of the run length).
// Between rewrites the index may lag results.h5 by up to `interval`.
class XdmfIndex {
 public:
  XdmfIndex(std::filesystem::path path, std::string h5_name, double interval_seconds = 2.0);
  // After an output step of `results`.
  void update(const ResultsH5& results);
  // Brings the index up to date (at the end of a run, or before it stops).
  void finish(const ResultsH5& results);
  // How many times the index was written.
  int rewrites() const { return rewrites_; }

 private:
  void rewrite(const ResultsH5& results);

  std::filesystem::path path_;
  std::string h5_name_;
  double interval_;
  std::size_t indexed_ = 0;  // steps in the last rewrite
  double last_rewrite_ = 0.0;  // steady clock, s
  int rewrites_ = 0;
};

}  // namespace flowmpm
