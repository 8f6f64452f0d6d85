// The run's results in its output directory: an output step (a step file
// and its results.h5/results.xdmf index entries, a timeseries.csv row) at
// the start, every output.every steps (about 20 over the run without it)
// and at the end, each continued after a checkpoint. Without write_results
// it writes nothing but still records the energy balance of each output
// step (summary.json's energy_error).
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/energy_monitor.hpp"
#include "app/reference_sampler.hpp"
#include "app/run_case.hpp"
#include "engine/simulation_base.hpp"
#include "io/results/results_h5.hpp"
#include "io/results/results_index.hpp"
#include "io/results/timeseries_csv.hpp"

namespace flowmpm {

class ResultsWriter {
 public:
  // `error_names`: the reference's error norms, columns of timeseries.csv.
  ResultsWriter(const Case& c, const RunOptions& options, const SimulationBase& sim, std::int64_t planned_steps,
                std::vector<std::string> error_names);

  // A restart: throws std::runtime_error naming the file when the results
  // written before the checkpoint cannot be continued. Reads only.
  void check_continuation(const SimulationBase& sim) const;
  // Opens the writers: afresh, or continuing the results after the
  // checkpoint's last output step.
  void open(const SimulationBase& sim, bool restart);

  bool due(std::int64_t step, bool last) const { return step % every_ == 0 || last; }
  // One output step of the simulation's state, timed into `seconds`.
  void write(const SimulationBase& sim, EnergyMonitor& energy, const ReferenceSampler& reference, double& seconds);
  std::int64_t last_written() const { return last_written_; }
  // After a blow-up: writes the last good state if it is after the last
  // output step; says which state the results end with.
  std::string write_last_good(const ParticleSnapshot& last_good);
  // The index with every step written.
  void finish();

  // What a checkpoint carries: the output steps written and the last one's step.
  template <class F>
  void visit_state(F&& f) {
    f("run.output_steps", output_steps_);
    f("run.last_written", last_written_);
  }

 private:
  std::pair<ResultsH5::Continuation, TimeseriesCsv::Continuation> continuation(const SimulationBase& sim) const;

  const Case& case_;
  bool write_results_;
  std::int64_t every_;
  std::size_t body_count_;
  std::vector<std::string> body_names_, reactions_, error_names_;
  TensorComponentNames components_;  // timeseries.csv's names of the stress and strain components
  std::int64_t output_steps_ = 0, last_written_ = -1;
  std::optional<ResultsH5> h5_;
  std::optional<ResultsIndex> index_;
  std::optional<TimeseriesCsv> csv_;
};

}  // namespace flowmpm
