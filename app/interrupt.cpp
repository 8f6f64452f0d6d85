#include "app/interrupt.hpp"

#include <unistd.h>

#include <csignal>
#include <cstring>

namespace flowmpm {
namespace {

std::atomic<bool> requested{false};
std::atomic<int> finishing{0};  // FinishBeforeExit objects alive
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free,
              "used from a signal handler");

void on_signal(int) {
  requested = true;
  if (finishing.load() > 0) return;
  // Only async-signal-safe calls here: write(2) and _exit(2).
  static const char message[] = "flowmpm: interrupted before anything was written; exiting\n";
  [[maybe_unused]] const ssize_t ignored = ::write(STDERR_FILENO, message, sizeof message - 1);
  ::_exit(130);
}

}  // namespace

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  ::sigaction(SIGINT, &action, nullptr);
  ::sigaction(SIGTERM, &action, nullptr);
}

std::atomic<bool>& interrupt_requested() { return requested; }

FinishBeforeExit::FinishBeforeExit() { ++finishing; }
FinishBeforeExit::~FinishBeforeExit() { --finishing; }

}  // namespace flowmpm
