// A named internal variable that a model offers for output (results.h5,
// ParaView): a model may declare
//   static constexpr std::array<StateVariable, N> state_variables;
//   void state_values(const State&, double* out) const;  // N values, in order
// and the engine writes them when a case asks for them by name
// (output.fields), with 0 for particles of models that do not have them.
#pragma once

namespace flowmpm {

struct StateVariable {
  const char* name;
  const char* units;
};

// Whether model M declares state variables.
template <class M>
concept HasStateVariables = requires { M::state_variables; };

}  // namespace flowmpm
