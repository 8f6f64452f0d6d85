#include "verification/reference.hpp"

#include "discretisation/shapes/shape_functions.hpp"
#include "engine/simulation.hpp"

namespace flowmpm {

namespace {
// Calls f(system) with the typed system of `simulation`.
template <class Simulation, class F>
void with_system(Simulation& simulation, F&& f) {
  with_dimension_and_shape(simulation.dimension(), simulation.shape(), [&]<int D, class Shape>() {
    using Typed = std::conditional_t<std::is_const_v<Simulation>, const flowmpm::Simulation<D, Shape>,
                                     flowmpm::Simulation<D, Shape>>;
    f(dynamic_cast<Typed&>(simulation).system());
  });
}
}  // namespace

void Reference::initialise(SimulationBase& simulation) const {
  with_system(simulation, [&](auto& system) { initialise(system); });
}

void Reference::sample(const SimulationBase& simulation) {
  with_system(simulation, [&](const auto& system) { sample(system); });
}

}  // namespace flowmpm
