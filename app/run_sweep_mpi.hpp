// A sweep over the ranks of an MPI job (`mpirun -n R flowmpm sweep --mpi
// SWEEP.toml`), built only with MPI (cmake -DFLOWMPM_MPI=ON, the default
// when CMake finds MPI). Rank 0 keeps sweep.csv and the progress lines and
// hands out the cases one at a time: a rank asks for the next case when it
// is free. Rank 0 runs cases too, on a thread of its own. Each rank runs its
// case on its own threads and writes its folder, as a local sweep does, so
// the output directory must be on a file system every rank sees. See
// docs/guide/cluster.md.
#pragma once
#include "app/run_sweep.hpp"

namespace flowmpm {

// MPI for the lifetime of the object: MPI_Init_thread (MPI_THREAD_FUNNELED:
// only the main thread calls MPI) and MPI_Finalize.
class MpiSession {
 public:
  MpiSession(int& argc, char**& argv);
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  ~MpiSession();
  int rank() const { return rank_; }
  int size() const { return size_; }

 private:
  int rank_ = 0, size_ = 1;
};

// Runs every case not already completed over the ranks of MPI_COMM_WORLD,
// each rank one case at a time on options.threads threads (options.jobs and
// options.shard are not used). Every rank calls it; rank 0 returns the
// sweep's summary, the others an empty one. On an interrupt (a signal to
// any rank, or mpirun ending the job because a rank died) the running cases
// stop after their current step and are left to run again, rank 0 logs
// what was left, and the job ends with MPI_Abort (exit status 130). If
// writing a file fails, the rank logs why and the job ends with exit status 2.
SweepSummary run_sweep_mpi(const Sweep& sweep, const SweepOptions& options, const MpiSession& mpi);

}  // namespace flowmpm
