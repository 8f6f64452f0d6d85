// A progress line every few seconds of a run: step, share of the end time,
// dt, the step rate and the time left at this session's pace.
#pragma once
#include <spdlog/spdlog.h>

#include "app/stopwatch.hpp"
#include "engine/simulation_base.hpp"

namespace flowmpm {

class ProgressReporter {
 public:
  // `every_seconds` between lines, for a run to `end_time` (s).
  ProgressReporter(double every_seconds, double end_time) : every_(every_seconds), end_time_(end_time) {}

  // The loop starts (or resumes) at the simulation's time.
  void start(const SimulationBase& sim) {
    start_ = last_ = WallClock::now();
    start_time_ = sim.scalars().t;
  }

  void after_step(spdlog::logger& log, const SimulationBase& sim, std::size_t particles, double step_loop_seconds) {
    if (seconds_since(last_) < every_) return;
    last_ = WallClock::now();
    const SystemScalars& s = sim.scalars();
    const double rate = static_cast<double>(particles) * static_cast<double>(s.step) / step_loop_seconds;
    // The ETA from this session's pace (a restart begins part way).
    const double eta = seconds_since(start_) * (end_time_ - s.t) / (s.t - start_time_);
    log.info("step {} ({:.0f}%), t = {:.6g} s, dt = {:.3g} s, {:.3g} particle-steps/s, ETA {:.0f} s", s.step,
             100.0 * s.t / end_time_, s.t, s.dt, rate, eta);
  }

 private:
  double every_, end_time_;
  WallClock::time_point start_{}, last_{};
  double start_time_ = 0.0;
};

}  // namespace flowmpm
