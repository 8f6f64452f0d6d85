#include <memory>

#include "discretisation/shapes/shape_functions.hpp"
#include "engine/simulation.hpp"

namespace flowmpm {

std::unique_ptr<SimulationBase> make_simulation(const SystemSpec& spec, const Wiring& wiring, double fixed_dt,
                                                std::function<void(Stage)> observer) {
  return with_dimension_and_shape(spec.dimension, spec.shape_function,
                                  [&]<int D, class Shape>() -> std::unique_ptr<SimulationBase> {
                                    return std::make_unique<Simulation<D, Shape>>(spec, wiring, fixed_dt,
                                                                                  std::move(observer));
                                  });
}

}  // namespace flowmpm
