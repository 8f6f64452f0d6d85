// The one owner of the time step: the limits of every physics a scene has
// (engine/stable_time_step.hpp: the wave limit of the scheme and shape
// function, the springs of imperfect interfaces, the explicit diffusion
// limit with transport), the check of a
// fixed dt or a CFL number against them, the first and every later
// automatic dt, and the end of the run. The case reader, `flowmpm check`,
// runs, sweeps and restarts all ask it. A new limit joins TimeStepLimit and
// is honoured here (the interfaces' springs did).
#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include "discretisation/system_spec.hpp"
#include "engine/schemes.hpp"
#include "engine/stable_time_step.hpp"

namespace flowmpm {

// Steps a run may take: a count that cannot overflow (the step is a 64-bit
// integer, times are step * dt) and that a run can finish (at 1 us per step,
// about three hours).
constexpr std::int64_t max_steps = 10'000'000'000;
constexpr const char* max_steps_text = "10^10";

// The analysis keys that choose the time step, as read.
struct TimeControl {
  bool automatic = false;     // dt = "auto": dt = cfl h_min / (c_max + |v|_max), every step
  double dt = 0.0;            // s, a fixed step
  std::optional<double> cfl;  // with automatic; default min(0.5, 0.8 f)
  std::int64_t steps = 0;     // with a fixed step: how many
  double end_time = 0.0;      // s
};

// What is wrong with a case's time step: the analysis key and what was
// expected, for a message that names the file and the line.
struct TimeStepProblem {
  std::string key;
  std::string expected;
};

class TimeStep {
 public:
  TimeStep() = default;
  // The scene's limits and the choice checked against them (problem()).
  TimeStep(const SystemSpec& spec, const Scheme& scheme, const TimeControl& control);

  // The first problem with the choice, none when it is stable.
  const std::optional<TimeStepProblem>& problem() const { return problem_; }

  bool automatic() const { return control_.automatic; }
  double cfl() const { return cfl_; }                 // with automatic
  double end_time() const { return control_.end_time; }  // s
  std::int64_t fixed_steps() const { return control_.steps; }  // 0 when automatic
  // The fixed step, or the first automatic one (the particles at rest), s.
  double first_dt() const { return first_dt_; }
  // The fixed step when it stays fixed, 0 when each step is chosen.
  double fixed_dt() const { return control_.automatic ? 0.0 : control_.dt; }
  // The steps the run is planned for (the automatic ones at the first dt).
  std::int64_t planned_steps() const;
  // The step from time t on, with the particles' largest speed so far: the
  // fixed one, or the CFL step with that speed added to the wave speed,
  // joined by the same fraction of the interface and the diffusion limits,
  // never past end_time.
  double next_dt(double t, double max_speed_sq) const;
  // Whether a run at this step and time has reached its end.
  bool done(std::int64_t step, double t) const;

  const TimeStepLimit& limits() const { return limits_; }
  // The fastest wave speed, h_min over the crossing time (m/s).
  double fastest_wave_speed() const { return c_max_; }
  // "0.9 h/c = 1e-05 s for USL with linear shape functions at 2 particles
  // per cell (h/c = ...: smallest cell over the P-wave speed of material "m")".
  const std::string& wave_limit_text() const { return wave_limit_text_; }

 private:
  TimeControl control_;
  TimeStepLimit limits_;
  double h_min_ = 0.0, c_max_ = 0.0, cfl_ = 0.0, first_dt_ = 0.0, diffusion_dt_ = 0.0, interface_dt_ = 0.0;
  std::string wave_limit_text_;
  std::optional<TimeStepProblem> problem_;
};

}  // namespace flowmpm
