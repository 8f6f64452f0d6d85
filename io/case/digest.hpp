// 64-bit FNV-1a digests: enough to tell two versions of a text apart (a
// case file and its overrides, a sweep's base case), not a cryptographic
// hash.
#pragma once
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace flowmpm {

inline constexpr std::uint64_t fnv1a_offset = 14695981039346656037ull;

// The FNV-1a hash of `bytes`, continuing from `h`.
inline std::uint64_t fnv1a(std::string_view bytes, std::uint64_t h = fnv1a_offset) {
  for (const char c : bytes) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
  return h;
}

// 16 hex digits.
inline std::string hex_digest(std::uint64_t h) {
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

}  // namespace flowmpm
