// Typed, validated reading of one TOML table of a case file: the
// ParameterTable that the case reader and every registered extension (a
// material, a reference, ...) read from. Every value is read through a
// TableReader, which remembers which keys were used, so that a key nobody
// read (a typo such as `shceme`) is an error, never silently ignored. Every
// error names the file, the line, the dotted key and what was expected.
#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "core/errors.hpp"
#include "core/parameter_table.hpp"

namespace flowmpm {

// "file:line" of a node (its own source when it came from --set).
std::string source_of(const toml::node& node, const std::string& fallback_file);

class TableReader : public ParameterTable {
 public:
  // `path` is the dotted name of the table ("analysis", "bodies[1]"), empty
  // for the document root.
  // `overrides` maps dotted keys set from the command line to the --set
  // text that set them, so that messages point there and not at the file.
  TableReader(const toml::table& table, std::string path, std::string file,
              std::shared_ptr<const std::map<std::string, std::string>> overrides = {});

  // ParameterTable
  bool has(std::string_view key) const override;
  double number(std::string_view key) override;
  std::int64_t integer(std::string_view key) override;
  std::string string(std::string_view key) override;
  std::string choice(std::string_view key, const std::vector<std::string>& allowed,
                     std::string_view fallback = {}) override;
  std::vector<double> numbers(std::string_view key, std::size_t count) override;
  TimeFunction time_function(std::string_view key, std::string_view what) override;
  void read_table(std::string_view key, const std::function<void(ParameterTable&)>& read) override;
  void read_tables(std::string_view key, const std::function<void(ParameterTable&)>& read) override;
  std::string where(std::string_view key) const override;

  std::vector<std::string> strings(std::string_view key);

  TableReader table(std::string_view key);
  // The tables of an array of tables, e.g. [[bodies]]; empty when absent.
  std::vector<TableReader> tables(std::string_view key);
  // The raw node of a key (for values of several shapes); marks it used.
  const toml::node* node(std::string_view key);

  // Fails on the first key of this table that was never read, suggesting
  // the nearest key the table understands.
  void reject_unknown_keys() const;

  std::string dotted(std::string_view key) const;
  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }

 protected:
  std::string failure(std::string_view key, std::string_view expected) const override;
  std::string table_failure(std::string_view message) const override;

 private:
  // Notes `key` as one this table understands (for "did you mean") and in
  // the reader's registry of keys (io/case/key_registry.hpp).
  void ask(std::string_view key) const;
  const toml::node& required(std::string_view key);
  // "file:line" of a node, or the --set that gave it.
  std::string location(const toml::node& node, std::string_view key) const;
  std::string failure_at(const toml::node& node, std::string_view key, std::string_view expected) const;
  [[noreturn]] void fail_at(const toml::node& node, std::string_view key, std::string_view expected) const;

  const toml::table* table_;
  std::string path_, file_;
  std::shared_ptr<const std::map<std::string, std::string>> overrides_;
  std::set<std::string, std::less<>> used_;
  // Every key the program asked for, present or not: the keys this table
  // understands, for "did you mean" in reject_unknown_keys().
  mutable std::set<std::string, std::less<>> known_;
};

}  // namespace flowmpm
