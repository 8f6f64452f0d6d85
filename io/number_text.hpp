// A double as text with 17 significant digits, so that it reads back
// exactly (std::to_chars: no locale, "nan" and "inf" for non-finite values).
#pragma once
#include <charconv>
#include <string>

namespace flowmpm {

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

}  // namespace flowmpm
