// The analytical solution a case is measured against, chosen by its
// [reference] table: it may set initial conditions, is sampled during the
// run, and reports named error norms for summary.json and sweeps.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <variant>

#include "engine/reference/axial_vibration.hpp"
#include "engine/reference/column_self_weight.hpp"
#include "engine/reference/elastic_wave.hpp"
#include "engine/reference/uniaxial_stress.hpp"

namespace flowmpm {

class Reference {
 public:
  explicit Reference(const ReferenceSpec& spec) : solution_(make(spec)) {}

  template <int D, class Shape>
  void initialise(Model<D, Shape>& model, double end_time) {
    std::visit([&](auto& s) { s.initialise(model, end_time); }, solution_);
  }
  template <int D, class Shape>
  void sample(const Model<D, Shape>& model) {
    std::visit([&](auto& s) { s.sample(model); }, solution_);
  }
  std::map<std::string, double> errors() const {
    return std::visit([](const auto& s) { return s.errors(); }, solution_);
  }

 private:
  using Solution = std::variant<AxialVibration, ElasticWave, UniaxialStress, ColumnSelfWeight>;
  static Solution make(const ReferenceSpec& r) {
    if (r.type == "axial_vibration") return AxialVibration(r);
    if (r.type == "elastic_wave") return ElasticWave(r);
    if (r.type == "uniaxial_stress") return UniaxialStress(r);
    return ColumnSelfWeight(r);
  }
  Solution solution_;
};

}  // namespace flowmpm
