// A sweep file (TOML): a base case and the keys to vary over it, expanded
// into the list of cases to run, each read and validated like a case file
// with --set overrides. See docs/guide/sweeps.md.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "io/case/case_file.hpp"

namespace flowmpm {

struct SweepCase {
  std::string id;                      // "007": the case's number, also its directory name
  std::vector<std::string> values;     // one per Sweep::keys: its TOML text, a string unquoted
  std::vector<std::string> overrides;  // "key=value", as from --set
  Case c;                              // the base case with the overrides applied
};

struct Sweep {
  std::filesystem::path file, base, output;
  std::string base_digest;        // of the base case file's text, to tell an edited base case
  std::vector<std::string> keys;  // the varied keys, in column order
  std::vector<SweepCase> cases;   // in run order
};

// Reads the sweep file, expands it and reads every case. Throws CaseError
// naming the file, line and key (or the case and its overrides); nothing
// is written.
Sweep read_sweep(const std::filesystem::path& file);

// A TOML value as the TOML text that reads back to it: "usl" (quoted), 0.001,
// [16, 16], { y = 0.0 }.
std::string toml_text(const toml::node& value);

}  // namespace flowmpm
