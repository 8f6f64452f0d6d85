#include "app/checkpointer.hpp"

#include "app/run_case_internal.hpp"
#include "app/stopwatch.hpp"
#include "io/results/checkpoint_file.hpp"

namespace flowmpm {

Checkpointer::Checkpointer(const Case& c, const RunOptions& options)
    : case_(c),
      write_(options.write_results),
      every_(c.output.checkpoint_every),
      path_(c.output.directory / checkpoint_file_name) {}

void Checkpointer::write(const SimulationBase& sim, const std::function<void(StateWriter&)>& visit_services,
                         double& seconds) const {
  TimeInto timer(seconds);
  StateRecords records;
  StateWriter write(records);
  write("case.digest", case_.digest);
  write("case.name", case_.name);
  write("case.file", case_.file.string());
  write("case.overrides", run_internal::overrides_text(case_));
  sim.save_state(records);
  visit_services(write);
  write_checkpoint(path_, records);
}

}  // namespace flowmpm
