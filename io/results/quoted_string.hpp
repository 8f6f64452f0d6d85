// A string in double quotes with the escapes that JSON strings and TOML
// basic strings share: \" \\ \b \f \n \r \t, and \u00XX for the other
// control characters (and DEL, which TOML requires escaped).
#pragma once
#include <cstdio>
#include <string>
#include <string_view>

namespace flowmpm {

inline std::string quoted_string(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\b': out += "\\b"; break;
      case '\f': out += "\\f"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
          char escape[8];
          std::snprintf(escape, sizeof escape, "\\u%04x", static_cast<unsigned>(c));
          out += escape;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

}  // namespace flowmpm
