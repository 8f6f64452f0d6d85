// CSV fields (RFC 4180): a field is quoted when it holds a comma, a quote, a
// line break, or leading or trailing spaces (which readers may strip), and
// quotes inside are doubled. One policy for every CSV file we write.
#pragma once
#include <string>
#include <string_view>

namespace flowmpm {

inline std::string csv_quoted(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

// A field as it is, or quoted where CSV needs it.
inline std::string csv_field(std::string_view text) {
  const bool plain = text.find_first_of(",\"\r\n") == std::string_view::npos &&
                     (text.empty() || (text.front() != ' ' && text.back() != ' '));
  return plain ? std::string(text) : csv_quoted(text);
}

}  // namespace flowmpm
