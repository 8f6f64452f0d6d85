#include "io/results/results_index.hpp"

#include <chrono>
#include <utility>

#include "io/results/xdmf.hpp"

namespace flowmpm {
namespace {

double steady_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

ResultsIndex::ResultsIndex(std::filesystem::path xdmf_path, double interval_seconds)
    : xdmf_path_(std::move(xdmf_path)), interval_(interval_seconds) {}

void ResultsIndex::update(const ResultsH5& results) {
  const std::size_t steps = results.written().size();
  if (steps >= 2 * indexed_ || steady_seconds() - last_rewrite_ >= interval_) rewrite(results);
}

void ResultsIndex::finish(const ResultsH5& results) {
  if (results.written().size() != indexed_) rewrite(results);
}

void ResultsIndex::rewrite(const ResultsH5& results) {
  results.write_index();
  write_xdmf(xdmf_path_, results.path().filename().string(), results);
  indexed_ = results.written().size();
  last_rewrite_ = steady_seconds();
  ++rewrites_;
}

}  // namespace flowmpm
