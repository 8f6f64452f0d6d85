// Compiled against the materials layer alone (tests/CMakeLists.txt): its own
// headers and those of core are visible.
#include "core/vec.hpp"
#include "materials/lame.hpp"

double probe_allowed() { return flowmpm::lame_mu(1.0, 0.25); }
