// checkpoint.bin in the output directory
// (docs/guide/checkpoint_restart.md): every output.checkpoint_every steps but the last, and when a
// run is interrupted. It holds the case's identity (its digest, name, file
// and --set options), the simulation's carried state and what each of the
// run's services carries (`visit_services`), so that a restart continues
// the run bit for bit.
#pragma once
#include <cstdint>
#include <filesystem>
#include <functional>

#include "app/run_case.hpp"
#include "engine/simulation_base.hpp"
#include "engine/state_records.hpp"

namespace flowmpm {

class Checkpointer {
 public:
  Checkpointer(const Case& c, const RunOptions& options);

  const std::filesystem::path& path() const { return path_; }
  bool due(std::int64_t step, bool last) const { return write_ && every_ > 0 && step % every_ == 0 && !last; }
  // Writes the checkpoint, timed into `seconds`.
  void write(const SimulationBase& sim, const std::function<void(StateWriter&)>& visit_services,
             double& seconds) const;

 private:
  const Case& case_;
  bool write_;
  std::int64_t every_;
  std::filesystem::path path_;
};

}  // namespace flowmpm
