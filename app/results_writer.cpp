#include "app/results_writer.hpp"

#include <algorithm>
#include <cstdint>
#include <stdexcept>

#include <spdlog/fmt/fmt.h>

#include "app/run_case_internal.hpp"
#include "engine/simulation.hpp"

namespace flowmpm {

namespace {

// Where each body's rows are (ResultsMetadata::body_rows): the system makes
// one batch per body and gives ids body by body, in the spec's order
// (discretisation/build_system.hpp); checked, since the files promise it.
std::vector<std::int64_t> body_rows(const SimulationBase& sim, std::size_t body_count) {
  return with_dimension_and_shape(sim.dimension(), sim.shape(), [&]<int D, class Shape>() {
    const auto& system = dynamic_cast<const Simulation<D, Shape>&>(sim).system();
    std::vector<std::int64_t> low(body_count, INT64_MAX), high(body_count, -1), count(body_count, 0);
    for (const auto& b : system.batches) {
      for (const std::uint32_t id : b.id) {
        low[b.body] = std::min<std::int64_t>(low[b.body], id);
        high[b.body] = std::max<std::int64_t>(high[b.body], id);
      }
      count[b.body] += static_cast<std::int64_t>(b.size());
    }
    std::vector<std::int64_t> rows{0};
    for (std::size_t body = 0; body < body_count; ++body) {
      if (count[body] > 0 && (low[body] != rows.back() || high[body] - low[body] + 1 != count[body]))
        throw std::logic_error("particle ids are not given body by body");
      rows.push_back(rows.back() + count[body]);
    }
    return rows;
  });
}

}  // namespace

ResultsWriter::ResultsWriter(const Case& c, const RunOptions& options, const SimulationBase& sim,
                             std::int64_t planned_steps, std::vector<std::string> error_names)
    : case_(c),
      write_results_(options.write_results),
      every_(c.output.every > 0 ? c.output.every : std::max<std::int64_t>(1, planned_steps / 20)),
      body_count_(c.system.bodies.size()),
      reactions_(reaction_names(sim.diagnostics(c.system.bodies.size()))),
      error_names_(std::move(error_names)),
      components_(tensor_component_names(sim.stress_state() == StressState::axisymmetric)) {
  for (const auto& b : c.system.bodies) body_names_.push_back(b.name);
}

std::pair<ResultsH5::Continuation, TimeseriesCsv::Continuation> ResultsWriter::continuation(
    const SimulationBase& sim) const {
  ResultsH5::Continuation h5_from{static_cast<std::size_t>(output_steps_), last_written_, {}};
  for (const SnapshotField& f : sim.snapshot(case_.output.fields).fields) h5_from.fields.push_back(f.field);
  return {h5_from, TimeseriesCsv::Continuation{static_cast<std::size_t>(output_steps_), last_written_}};
}

void ResultsWriter::check_continuation(const SimulationBase& sim) const {
  const auto [h5_from, csv_from] = continuation(sim);
  const auto& dir = case_.output.directory;
  ResultsH5::check_continuation(dir / "results.h5", h5_from);
  TimeseriesCsv::kept_text(dir / "timeseries.csv", body_names_, reactions_, error_names_, csv_from, components_);
}

void ResultsWriter::open(const SimulationBase& sim, bool restart) {
  if (!write_results_) return;
  const auto& dir = case_.output.directory;
  ResultsMetadata metadata{FLOWMPM_VERSION, run_internal::source_commit(), case_.name, case_.file.string(),
                           sim.dimension(), stress_state_name(sim.stress_state()), case_.scheme->label,
                           sim.shape_function(), {}, body_names_, body_rows(sim, body_count_)};
  for (const NamedMaterial& m : case_.system.materials) metadata.materials.push_back(m.name);
  if (restart) {
    const auto [h5_from, csv_from] = continuation(sim);
    h5_.emplace(dir / "results.h5", metadata, h5_from);
    csv_.emplace(dir / "timeseries.csv", body_names_, reactions_, error_names_, csv_from, components_);
  } else {
    h5_.emplace(dir / "results.h5", metadata);
    csv_.emplace(dir / "timeseries.csv", body_names_, reactions_, error_names_, components_);
  }
  index_.emplace(dir / "results.xdmf");
  if (restart) index_->finish(*h5_);  // without the steps written after the checkpoint
}

void ResultsWriter::write(const SimulationBase& sim, EnergyMonitor& energy, const ReferenceSampler& reference,
                          double& seconds) {
  TimeInto timer(seconds);
  const Diagnostics row = sim.diagnostics(body_count_);
  const double error = energy.error(row);
  if (write_results_) {
    h5_->write(sim.snapshot(case_.output.fields));
    index_->update(*h5_);
    // The error norms so far: over the particles and the samples up to now.
    csv_->write(row, error, reference.errors());
  }
  ++output_steps_;
  last_written_ = sim.scalars().step;
}

std::string ResultsWriter::write_last_good(const ParticleSnapshot& last_good) {
  if (!write_results_) return {};
  if (last_good.count == 0 || last_good.step <= last_written_) {
    return fmt::format("; the last good state written is step {} in results.h5", last_written_);
  }
  h5_->write(last_good);
  return fmt::format("; the last good state (step {}, t = {:.6g} s) is the last step in results.h5", last_good.step,
                     last_good.time);
}

void ResultsWriter::finish() {
  if (write_results_) index_->finish(*h5_);
}

}  // namespace flowmpm
