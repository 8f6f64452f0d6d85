// Limits on what a case may ask for beyond each key's own range (README
// "Case files"): how many steps, and which names and paths are accepted.
#pragma once
#include <cstdint>
#include <string_view>

namespace flowmpm {

// Steps a run may take: a count that cannot overflow (the step is a 64-bit
// integer, times are step * dt) and that a run can finish (at 1 us per step,
// about three hours).
constexpr std::int64_t max_steps = 10'000'000'000;
constexpr const char* max_steps_text = "10^10";

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
