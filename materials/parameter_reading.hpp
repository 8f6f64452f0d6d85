// Reading helpers shared by the models' parameter readers.
#pragma once
#include <string_view>

#include "engine/time_function.hpp"

namespace flowmpm {

class TableReader;

// A uniform value given as a number, or as a function of time: an array of
// [time (s), value] pairs with increasing times, piecewise linear between
// them and constant outside. `what` names the quantity and its unit for
// messages ("a temperature change in K").
TimeFunction read_time_function(TableReader& t, std::string_view key, std::string_view what);

}  // namespace flowmpm
