// results.xdmf: an XDMF 3 index of results.h5 (a temporal collection of
// Polyvertex grids, one per output step) so that ParaView opens the particle
// time series directly. Rewritten atomically after every output step.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "io/results_h5.hpp"

namespace flowmpm {

// The XDMF text for the steps written so far; `h5_name` is the HDF5 file's
// name relative to the XDMF file. Position is the grid's geometry: throws
// std::invalid_argument when it is not among the results' fields.
std::string xdmf_document(const std::string& h5_name, const ResultsH5& results);

// Writes xdmf_document(...) to `path` atomically.
void write_xdmf(const std::filesystem::path& path, const std::string& h5_name,
                const ResultsH5& results);

}  // namespace flowmpm
