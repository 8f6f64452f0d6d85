// The two ways a run can fail, told apart by the exit status (docs/guide/running.md): bad input (1) and a solution that went wrong (2).
#pragma once
#include <stdexcept>

namespace flowmpm {

// A problem with the input (a case file, a sweep file, the command line);
// what() is the complete message for the user, naming where and what was
// expected.
class CaseError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The solution went wrong (a particle left the grid, a non-finite value, a
// blow-up); what() names the step and where.
class SimulationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace flowmpm
