// The reference solution of a case, sampled during the run
// (verification/reference.hpp): at the start, every sample_every steps and
// at the end; its error norms go to timeseries.csv and summary.json.
#pragma once
#include <algorithm>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "app/stopwatch.hpp"
#include "verification/reference.hpp"

namespace flowmpm {

class ReferenceSampler {
 public:
  // Initialises the reference on the simulation (with its own checks).
  ReferenceSampler(const std::optional<Reference>& reference, SimulationBase& sim, std::int64_t planned_steps)
      : reference_(reference) {
    if (!reference_) return;
    reference_->initialise(sim);
    if (reference_->samples() > 0) every_ = std::max<std::int64_t>(1, planned_steps / reference_->samples());
  }

  bool present() const { return reference_.has_value(); }
  const Reference& reference() const { return *reference_; }
  std::int64_t every() const { return every_; }

  void sample(const SimulationBase& sim, double& seconds) {
    TimeInto timer(seconds);
    reference_->sample(sim);
  }
  void after_step(const SimulationBase& sim, bool last, double& seconds) {
    if (reference_ && (sim.scalars().step % every_ == 0 || last)) sample(sim, seconds);
  }

  // The error norms' names and, over the samples so far, their values.
  std::vector<std::string> error_names() const {
    std::vector<std::string> names;
    if (reference_)
      for (const auto& [name, value] : reference_->errors()) names.push_back(name);
    return names;
  }
  std::vector<double> errors() const {
    std::vector<double> values;
    if (reference_)
      for (const auto& [name, value] : reference_->errors()) values.push_back(value);
    return values;
  }

  // What a checkpoint carries: the sums of the samples.
  template <class F>
  void visit_state(F&& f) {
    if (reference_) reference_->visit_state([&](const std::string& name, auto& value) { f("reference." + name, value); });
  }

 private:
  std::optional<Reference> reference_;
  std::int64_t every_ = 1;
};

}  // namespace flowmpm
