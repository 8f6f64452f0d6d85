// A materials header that includes the layer above it: check_layers.py must
// report it (tests/CMakeLists.txt, layer_order_detects_a_wrong_include).
#pragma once
#include "core/vec.hpp"
#include "discretisation/grid/grid.hpp"
