// Reading sweep.csv in the tests that run sweeps: its fields, its rows by
// column name, and the rows without the columns that may differ between
// runs of the same sweep.
#pragma once
#include <doctest/doctest.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "run_program.hpp"

namespace flowmpm::testing {

// RFC 4180 fields of CSV text, row by row.
inline std::vector<std::vector<std::string>> parse_csv(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> row;
  std::string field;
  bool quoted = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        field += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        field += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      row.push_back(field);
      field.clear();
    } else if (c == '\n') {
      row.push_back(field);
      rows.push_back(row);
      row.clear();
      field.clear();
    } else {
      field += c;
    }
  }
  return rows;
}

// sweep.csv as one map per row, column name to field.
inline std::vector<std::map<std::string, std::string>> table_of(const std::filesystem::path& csv) {
  const auto rows = parse_csv(read_text(csv));
  REQUIRE(!rows.empty());
  std::vector<std::map<std::string, std::string>> table;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    REQUIRE(rows[r].size() == rows[0].size());
    std::map<std::string, std::string> row;
    for (std::size_t c = 0; c < rows[0].size(); ++c) row[rows[0][c]] = rows[r][c];
    table.push_back(row);
  }
  return table;
}

// The table without the columns that say how fast a case ran and where:
// wall_seconds, particle_steps_per_second and rank. The rest is the same
// for every way of running a sweep.
inline std::vector<std::map<std::string, std::string>> results_of(const std::filesystem::path& csv) {
  auto table = table_of(csv);
  for (auto& row : table) {
    row.erase("wall_seconds");
    row.erase("particle_steps_per_second");
    row.erase("rank");
  }
  return table;
}

}  // namespace flowmpm::testing
