#include "io/case/key_registry.hpp"

#include <mutex>
#include <regex>

namespace flowmpm {

namespace {
std::mutex registry_mutex;
std::set<std::string>& registry() {
  static std::set<std::string> keys;
  return keys;
}
}  // namespace

std::string key_pattern(std::string_view table_path, std::string_view key) {
  static const std::regex index(R"(\[\d+\])"), material(R"(^materials\.[^.]+)"), parts(R"((\.parts\[\])+)");
  std::string path(table_path);
  path = std::regex_replace(path, index, "[]");
  path = std::regex_replace(path, material, "materials.<name>");
  path = std::regex_replace(path, parts, "");
  if (path == "materials") return "materials.<name>";  // the table of a material the case names
  return path.empty() ? std::string(key) : path + "." + std::string(key);
}

void record_asked_key(std::string_view table_path, std::string_view key) {
  const std::string pattern = key_pattern(table_path, key);
  std::lock_guard lock(registry_mutex);
  registry().insert(pattern);
}

std::set<std::string> asked_keys() {
  std::lock_guard lock(registry_mutex);
  return registry();
}

}  // namespace flowmpm
