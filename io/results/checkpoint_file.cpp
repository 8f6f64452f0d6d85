#include "io/results/checkpoint_file.hpp"

#include <bit>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string_view>

#include "core/errors.hpp"
#include "io/results/atomic_file.hpp"
#include "io/case/digest.hpp"

namespace flowmpm {
namespace {

static_assert(std::endian::native == std::endian::little, "checkpoints are written little-endian");

constexpr std::string_view magic = "flowmpm checkpoint 1\n";

template <class T>
void append(std::string& out, T value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

// Reads from a byte range, failing (false) past its end.
struct Cursor {
  std::string_view rest;
  template <class T>
  bool take(T& value) {
    if (rest.size() < sizeof value) return false;
    std::memcpy(&value, rest.data(), sizeof value);
    rest.remove_prefix(sizeof value);
    return true;
  }
  bool take(std::size_t n, std::string_view& bytes) {
    if (rest.size() < n) return false;
    bytes = rest.substr(0, n);
    rest.remove_prefix(n);
    return true;
  }
};

}  // namespace

void write_checkpoint(const std::filesystem::path& path, const StateRecords& records) {
  std::string out(magic);
  for (const auto& [name, value] : records) {
    append(out, static_cast<std::uint32_t>(name.size()));
    out += name;
    append(out, static_cast<std::uint64_t>(value.size()));
    out += value;
  }
  append(out, fnv1a(out));
  write_file_atomically(path, out);
}

StateRecords read_checkpoint(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  std::string text(in.is_open() ? static_cast<std::size_t>(in.tellg()) : 0, '\0');
  if (!in.is_open() || !in.seekg(0).read(text.data(), static_cast<std::streamsize>(text.size()))) {
    throw CaseError(path.string() + ": cannot read the checkpoint");
  }
  const auto damaged = [&](const std::string& why) {
    return CaseError(path.string() + ": a damaged checkpoint (" + why + ")");
  };
  if (text.compare(0, magic.size(), magic) != 0) throw damaged("it does not begin as a flowmpm checkpoint does");
  if (text.size() < magic.size() + sizeof(std::uint64_t)) throw damaged("cut short: it has no digest");
  const std::string_view body(text.data(), text.size() - sizeof(std::uint64_t));
  std::uint64_t digest = 0;
  std::memcpy(&digest, text.data() + body.size(), sizeof digest);
  if (fnv1a(body) != digest) throw damaged("cut short or overwritten: its contents do not match its digest");
  StateRecords records;
  Cursor cursor{body.substr(magic.size())};
  while (!cursor.rest.empty()) {
    std::uint32_t name_size = 0;
    std::uint64_t value_size = 0;
    std::string_view name, value;
    if (!cursor.take(name_size) || !cursor.take(name_size, name) || !cursor.take(value_size) ||
        !cursor.take(value_size, value)) {
      throw damaged("a record runs past its end");
    }
    records.emplace(name, value);
  }
  return records;
}

}  // namespace flowmpm
