// Limits on what a case may ask for beyond each key's own range (docs/reference/README.md): which names and paths are accepted. How many steps a run
// may take is the time step's (engine/time_step.hpp: max_steps).
#pragma once
#include <string_view>

#include "engine/time_step.hpp"

namespace flowmpm {

// A name that is one path component: not empty, not "." or "..", no "/" or
// "\", no control character (a case's name is its default output directory
// under results/).
inline bool is_plain_name(std::string_view name) {
  if (name.empty() || name == "." || name == "..") return false;
  for (const char c : name)
    if (c == '/' || c == '\\' || static_cast<unsigned char>(c) < 0x20 || c == 0x7f) return false;
  return true;
}

// A path without control characters (a NUL would cut it short where the
// operating system reads it).
inline bool is_clean_path(std::string_view path) {
  if (path.empty()) return false;
  for (const char c : path)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) return false;
  return true;
}

}  // namespace flowmpm
