// A core header that includes only core: allowed.
#pragma once
#include "core/voigt.hpp"
