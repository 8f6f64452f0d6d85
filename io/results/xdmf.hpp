// results.xdmf: an XDMF 3 index of the results (a temporal collection of
// Polyvertex grids, one per output step, each reading its step's file) so
// that ParaView opens the particle time series directly, with its default
// reader and the legacy one.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "io/results/atomic_file.hpp"
#include "io/results/results_h5.hpp"

namespace flowmpm {

// The XDMF text for the steps written so far, handed to `sink` a step at a
// time; `h5_name` is results.h5's name relative to the XDMF file, which is
// in the same directory.
// Position is the grid's geometry: throws std::invalid_argument when it is
// not among the results' fields.
void xdmf_document(const std::string& h5_name, const ResultsH5& results, const TextSink& sink);
// The same text as one string.
std::string xdmf_document(const std::string& h5_name, const ResultsH5& results);

// Writes the XDMF text to `path` atomically, never holding it whole (it
// grows by about 2.4 kB per output step).
void write_xdmf(const std::filesystem::path& path, const std::string& h5_name,
                const ResultsH5& results);

}  // namespace flowmpm
