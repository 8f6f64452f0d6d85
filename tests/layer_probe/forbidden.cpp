// Compiled against the materials layer alone (tests/CMakeLists.txt): a header
// of the tasks layer, above it, must not be found. (tasks/stage.hpp needs
// nothing but the standard library, so only the layering can stop it.)
#include "tasks/stage.hpp"

const char* probe_forbidden() { return flowmpm::stage_name(flowmpm::Stage::remap); }
