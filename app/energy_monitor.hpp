// The run's energy balance (engine/energy_balance.hpp): its change since
// the start at each recorded step, against the largest energy present so
// far; the worst of these is summary.json's energy_error.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/diagnostics.hpp"

namespace flowmpm {

class EnergyMonitor {
 public:
  explicit EnergyMonitor(const Diagnostics& initial) : balance_at_start_(initial.energy_balance()) {}

  // The balance's change since the start at `d`, recorded.
  double error(const Diagnostics& d) {
    const double error = d.energy_balance() - balance_at_start_;
    scale_ = std::max({scale_, d.kinetic_energy + d.stored_energy + d.dissipated_energy, std::abs(d.work.gravity),
                       std::abs(d.work.boundary), std::abs(d.work.expansion), std::abs(d.work.load),
                       std::abs(d.work.contact)});
    worst_ = std::max(worst_, std::abs(error));
    return error;
  }
  // The worst change over the largest energy present; NaN without energy.
  double relative_error() const {
    return scale_ > 0.0 ? worst_ / scale_ : std::numeric_limits<double>::quiet_NaN();
  }

  // What a checkpoint carries (engine/state_records.hpp).
  template <class F>
  void visit_state(F&& f) {
    f("energy.balance_at_start", balance_at_start_);
    f("energy.scale", scale_);
    f("energy.worst_balance_error", worst_);
  }

 private:
  double balance_at_start_;
  double scale_ = 0.0, worst_ = 0.0;
};

}  // namespace flowmpm
