// The table of parameters that a registered extension (a material model, a
// reference solution, a body shape, a load) reads its own keys from. io
// implements it on a TOML table of the case file (io/case/case_reader.hpp); an
// extension never sees the file format. Every failure throws CaseError with
// a message naming the file, the line, the dotted key and what was expected.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "core/errors.hpp"
#include "core/time_function.hpp"

namespace flowmpm {

class ParameterTable {
 public:
  virtual ~ParameterTable() = default;

  virtual bool has(std::string_view key) const = 0;
  // A finite number (an integer is taken as a number).
  virtual double number(std::string_view key) = 0;
  virtual std::int64_t integer(std::string_view key) = 0;
  virtual std::string string(std::string_view key) = 0;
  // One of `allowed`; `fallback` when absent (then required when fallback is empty).
  virtual std::string choice(std::string_view key, const std::vector<std::string>& allowed,
                             std::string_view fallback = {}) = 0;
  // An array of exactly `count` finite numbers.
  virtual std::vector<double> numbers(std::string_view key, std::size_t count) = 0;
  // A number, or an array of [time in s, value] pairs with increasing times
  // (piecewise linear between them, constant outside); `what` names the
  // quantity and its unit for messages ("a temperature change in K").
  virtual TimeFunction time_function(std::string_view key, std::string_view what) = 0;
  // Calls read(sub) on the sub-table `key` (required), then fails on any
  // key of it that read() left unread.
  virtual void read_table(std::string_view key, const std::function<void(ParameterTable&)>& read) = 0;
  // The same for each table of the array of tables `key`, in order; none
  // when the key is absent.
  virtual void read_tables(std::string_view key, const std::function<void(ParameterTable&)>& read) = 0;
  // "file:line: dotted.key" of a key (of the table when the key is absent;
  // "file:line: table" for an empty key), for messages about it once the
  // case is read (e.g. a load that selects nothing when the system is built).
  virtual std::string where(std::string_view key) const = 0;

  // Throws CaseError naming the key, its line and what was expected.
  [[noreturn]] void fail(std::string_view key, std::string_view expected) const {
    throw CaseError(failure(key, expected));
  }
  // Throws CaseError about the table as a whole.
  [[noreturn]] void fail_table(std::string_view message) const { throw CaseError(table_failure(message)); }

  double number_or(std::string_view key, double fallback) { return has(key) ? number(key) : fallback; }
  std::int64_t integer_or(std::string_view key, std::int64_t fallback) { return has(key) ? integer(key) : fallback; }
  std::string string_or(std::string_view key, std::string fallback) {
    return has(key) ? string(key) : std::move(fallback);
  }
  // A number that must be > 0; `expected` describes it ("the bar length in m").
  double positive(std::string_view key, std::string_view expected) {
    const double value = number(key);
    require(value > 0.0, key, expected);
    return value;
  }
  // Fails with `expected` unless `ok` (a check of a value read from `key`).
  void require(bool ok, std::string_view key, std::string_view expected) const {
    if (!ok) fail(key, expected);
  }

 protected:
  // The complete messages of fail() and fail_table(), with the location.
  virtual std::string failure(std::string_view key, std::string_view expected) const = 0;
  virtual std::string table_failure(std::string_view message) const = 0;
};

// The index of the axis named by `key`: "x", "y" or "z", one of the first
// `dimension` axes.
inline int read_axis(ParameterTable& t, std::string_view key, int dimension) {
  const std::string name = t.string(key);
  for (int d = 0; d < dimension; ++d)
    if (name == std::string(1, "xyz"[d])) return d;
  t.fail(key, dimension == 1   ? "the axis \"x\""
              : dimension == 2 ? "an axis, \"x\" or \"y\""
                               : "an axis, \"x\", \"y\" or \"z\"");
}

}  // namespace flowmpm
