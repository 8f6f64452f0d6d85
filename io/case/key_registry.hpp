// The reader's own registry of keys: every key a TableReader asks for,
// present in the file or not, under its table's pattern
// ("analysis.dimension", "bodies[].shape.radius",
// "materials.<name>.density"). What the reader asks is what it accepts
// (TableReader::reject_unknown_keys refuses any other key), so the key
// reference (docs/reference/) is checked against this registry, filled by
// reading the shipped cases (tests/test_key_reference.cpp).
#pragma once
#include <set>
#include <string>
#include <string_view>

namespace flowmpm {

// "bodies[].shape.parts[].radius" for key "radius" of table
// "bodies[2].shape.parts[0]": array indices become [], the name of a
// material becomes <name>; the keys of a combination's parts are those of
// the shape that holds them ("bodies[].shape.radius").
std::string key_pattern(std::string_view table_path, std::string_view key);

// Records that a reader asked for `key` of table `table_path`.
void record_asked_key(std::string_view table_path, std::string_view key);

// Every key pattern asked for so far in this process.
std::set<std::string> asked_keys();

}  // namespace flowmpm
