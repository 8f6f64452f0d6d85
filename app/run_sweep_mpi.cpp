#include "app/run_sweep_mpi.hpp"

#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <exception>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <spdlog/spdlog.h>
#include <tbb/task_arena.h>

namespace flowmpm {
namespace {

// A rank sends its row (the text of its sweep_row.txt; empty when it asks
// for its first case) with row_tag; rank 0 answers with the number of the
// next case, or -1 for "no more", with case_tag.
constexpr int row_tag = 1;
constexpr int case_tag = 2;
constexpr long no_more_cases = -1;

// How long rank 0 sleeps between looks for a message: it polls instead of
// blocking because a blocked MPI receive spins a core, which the rank's own
// case needs.
constexpr auto poll_interval = std::chrono::milliseconds(2);

bool is_set(const std::atomic<bool>* flag) { return flag && flag->load(); }

// Ends the whole job: an interrupt, or a rank that cannot write its files.
[[noreturn]] void end_job(int status) {
  spdlog::default_logger()->flush();
  MPI_Abort(MPI_COMM_WORLD, status);
  std::terminate();  // MPI_Abort does not return
}

// "3 ranks on 2 hosts, 2 to 4 threads each": gathered on rank 0.
std::string layout(int threads, const MpiSession& mpi) {
  char host[MPI_MAX_PROCESSOR_NAME] = {};
  int length = 0;
  MPI_Get_processor_name(host, &length);
  std::vector<int> all_threads(static_cast<std::size_t>(mpi.size()));
  std::vector<char> hosts(static_cast<std::size_t>(mpi.size()) * MPI_MAX_PROCESSOR_NAME);
  MPI_Gather(&threads, 1, MPI_INT, all_threads.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  MPI_Gather(host, MPI_MAX_PROCESSOR_NAME, MPI_CHAR, hosts.data(), MPI_MAX_PROCESSOR_NAME, MPI_CHAR, 0,
             MPI_COMM_WORLD);
  if (mpi.rank() != 0) return {};
  std::set<std::string> names;
  for (int r = 0; r < mpi.size(); ++r) names.insert(hosts.data() + static_cast<std::size_t>(r) * MPI_MAX_PROCESSOR_NAME);
  const auto [low, high] = std::minmax_element(all_threads.begin(), all_threads.end());
  const std::string count = *low == *high ? std::to_string(*low) : std::to_string(*low) + " to " + std::to_string(*high);
  return "one at a time on each of " + std::to_string(mpi.size()) + " rank" + (mpi.size() == 1 ? "" : "s") + " on " +
         std::to_string(names.size()) + " host" + (names.size() == 1 ? "" : "s") + ", " + count + " thread" +
         (*high == 1 ? "" : "s") + " each";
}

// Rank 0: keeps the table, hands out the cases and runs cases itself on a
// second thread.
SweepSummary coordinate(const Sweep& sweep, const SweepOptions& options, const MpiSession& mpi,
                        const std::shared_ptr<spdlog::logger>& log) {
  const auto interrupted = [&] { return is_set(options.interrupt); };
  SweepTable table(sweep, SweepShard{}, log);
  const std::vector<std::size_t>& todo = table.todo();
  table.start(layout(options.threads, mpi));

  std::mutex mutex;  // guards next, running, error
  std::size_t next = 0;
  std::vector<long> running(static_cast<std::size_t>(mpi.size()), no_more_cases);  // the case on each rank
  std::exception_ptr error;
  // The next case for `rank`, or no_more_cases.
  const auto take = [&](int rank) {
    const std::lock_guard lock(mutex);
    const bool more = next < todo.size() && !error && !interrupted();
    running[static_cast<std::size_t>(rank)] = more ? static_cast<long>(todo[next++]) : no_more_cases;
    return running[static_cast<std::size_t>(rank)];
  };

  std::thread local([&] {
    tbb::task_arena arena(options.threads);
    try {
      for (long i; (i = take(0)) != no_more_cases;) {
        const auto row = run_sweep_case(sweep, static_cast<std::size_t>(i), arena, options.threads,
                                        options.interrupt, 0);
        if (!row) return;  // interrupted: left to run again
        table.record(static_cast<std::size_t>(i), *row);
      }
    } catch (...) {
      const std::lock_guard lock(mutex);
      if (!error) error = std::current_exception();
    }
  });

  try {
    for (int asking = mpi.size() - 1; asking > 0 && !interrupted();) {
      int arrived = 0;
      MPI_Status status;
      MPI_Iprobe(MPI_ANY_SOURCE, row_tag, MPI_COMM_WORLD, &arrived, &status);
      if (!arrived) {
        std::this_thread::sleep_for(poll_interval);
        continue;
      }
      int length = 0;
      MPI_Get_count(&status, MPI_CHAR, &length);
      std::string text(static_cast<std::size_t>(length), '\0');
      const int rank = status.MPI_SOURCE;
      MPI_Recv(text.data(), length, MPI_CHAR, rank, row_tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      const long done = running[static_cast<std::size_t>(rank)];
      if (done != no_more_cases) {
        const std::size_t i = static_cast<std::size_t>(done);
        const auto row = parse_sweep_row(text, sweep, i);
        if (!row) throw std::runtime_error("rank " + std::to_string(rank) + " sent no readable row for case " +
                                           sweep.cases[i].id + ":\n" + text);
        table.record(i, *row);
      }
      const long i = take(rank);
      if (i == no_more_cases) --asking;
      MPI_Send(&i, 1, MPI_LONG, rank, case_tag, MPI_COMM_WORLD);
    }
  } catch (...) {
    const std::lock_guard lock(mutex);
    if (!error) error = std::current_exception();
  }
  local.join();
  if (error) {
    try {
      std::rethrow_exception(error);
    } catch (const std::exception& e) {
      log->error("sweep: {}", e.what());
    }
    end_job(2);
  }
  if (interrupted()) {
    std::string left;
    for (int r = 0; r < mpi.size(); ++r) {
      const long i = running[static_cast<std::size_t>(r)];
      if (i == no_more_cases) continue;
      left += (left.empty() ? "" : ", ") + sweep.cases[static_cast<std::size_t>(i)].id + " (rank " +
              std::to_string(r) + ")";
    }
    log->warn("sweep: stopped by a signal (Ctrl-C, the scheduler, or mpirun ending the job because a rank "
              "died); left to run again: {}; run the same command again to resume",
              left.empty() ? "none" : left);
    table.finish(true);
    end_job(130);
  }
  return table.finish(false);
}

// Ranks 1 and up: ask for a case, run it, send its row, until told to stop.
void work(const Sweep& sweep, const SweepOptions& options, const MpiSession& mpi) {
  layout(options.threads, mpi);
  tbb::task_arena arena(options.threads);
  std::string text;  // the row of the case just run; empty at first
  for (;;) {
    MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, 0, row_tag, MPI_COMM_WORLD);
    long i = no_more_cases;
    MPI_Recv(&i, 1, MPI_LONG, 0, case_tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (i == no_more_cases) return;
    try {
      const auto row = run_sweep_case(sweep, static_cast<std::size_t>(i), arena, options.threads, options.interrupt,
                                      mpi.rank());
      if (!row) end_job(130);  // interrupted: left to run again
      text = sweep_row_text(sweep, static_cast<std::size_t>(i), *row);
    } catch (const std::exception& e) {
      spdlog::error("sweep: {}", e.what());
      end_job(2);
    }
  }
}

}  // namespace

MpiSession::MpiSession(int& argc, char**& argv) {
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() { MPI_Finalize(); }

SweepSummary run_sweep_mpi(const Sweep& sweep, const SweepOptions& options, const MpiSession& mpi) {
  // The cases log to their own run.log only, as in a local sweep; a
  // worker's own lines (errors) name its rank.
  const auto log = sweep_logger();
  if (mpi.rank() == 0) return coordinate(sweep, options, mpi, log);
  spdlog::set_pattern("[%H:%M:%S.%e] [rank " + std::to_string(mpi.rank()) + "] %^%l%$ %v");
  work(sweep, options, mpi);
  return {};
}

}  // namespace flowmpm
