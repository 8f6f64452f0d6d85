// Wall-clock seconds for the run's timings (summary.json's *_seconds).
#pragma once
#include <chrono>

namespace flowmpm {

using WallClock = std::chrono::steady_clock;

inline double seconds_since(WallClock::time_point t0) {
  return std::chrono::duration<double>(WallClock::now() - t0).count();
}

// Adds the seconds of its own lifetime to `total`.
class TimeInto {
 public:
  explicit TimeInto(double& total) : total_(total), start_(WallClock::now()) {}
  ~TimeInto() { total_ += seconds_since(start_); }
  TimeInto(const TimeInto&) = delete;
  TimeInto& operator=(const TimeInto&) = delete;

 private:
  double& total_;
  WallClock::time_point start_;
};

}  // namespace flowmpm
