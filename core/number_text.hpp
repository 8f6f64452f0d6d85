// Numbers as text: exactly, for files that are read back (every double
// round-trips), and readably, for messages and logs.
#pragma once
#include <charconv>
#include <string>

namespace flowmpm {

// 17 significant digits, so that the text reads back to the same double
// (std::to_chars: no locale; "nan" and "inf" for non-finite values).
inline void append_exact(std::string& out, double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, 17);
  out.append(buffer, result.ptr);
}

inline std::string exact_text(double value) {
  std::string out;
  append_exact(out, value);
  return out;
}

// 6 significant digits, for people: 0.03, 4e-05, 1.5e+09.
inline std::string readable_text(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, 6);
  return std::string(buffer, result.ptr);
}

}  // namespace flowmpm
