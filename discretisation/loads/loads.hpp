// The registry of loads, chosen by the `type` of a [[loads]] table
// (docs/reference/README.md). Each load type has
//   static constexpr const char* type_name;
//   static Load read(ParameterTable&, const LoadReadContext&);
//   template <int D, class Shape> void attach(LoadSite<D, Shape>&) const;
// `attach` adds what the step applies (external_loads.hpp) to the system
// being built, and fails with a CaseError where the load would act on
// nothing. Adding one is one new file and one line in the variant below
// (docs/ARCHITECTURE.md "A load, a body shape").
#pragma once
#include <variant>

#include "core/registry.hpp"
#include "discretisation/loads/load_body_force.hpp"
#include "discretisation/loads/load_nodal_force.hpp"
#include "discretisation/loads/load_pressure.hpp"
#include "discretisation/loads/load_traction.hpp"

namespace flowmpm {

using Load = std::variant<TractionLoad, PressureLoad, NodalForceLoad, BodyForceLoad>;
using Loads = Registry<Load>;

}  // namespace flowmpm
