#include "materials/parameter_reading.hpp"

#include <cmath>
#include <string>

#include "io/case_reader.hpp"

namespace flowmpm {

TimeFunction read_time_function(TableReader& t, std::string_view key, std::string_view what) {
  const toml::node* n = t.node(key);
  if (n && n->is_number()) return TimeFunction{{{0.0, t.number(key)}}};
  const std::string expected =
      std::string(what) + ", or an array of [time in s, value] pairs with increasing times";
  const toml::array* points = n ? n->as_array() : nullptr;
  if (!points || points->empty()) t.fail(key, expected);
  TimeFunction f;
  for (const toml::node& p : *points) {
    const toml::array* pair = p.as_array();
    if (!pair || pair->size() != 2 || !pair->get(0)->is_number() || !pair->get(1)->is_number()) {
      t.fail(key, expected);
    }
    const double time = *pair->get(0)->value<double>();
    const double value = *pair->get(1)->value<double>();
    if (!std::isfinite(time) || !std::isfinite(value)) t.fail(key, expected);
    if (!f.points.empty() && time <= f.points.back().first) t.fail(key, expected);
    f.points.emplace_back(time, value);
  }
  return f;
}

}  // namespace flowmpm
