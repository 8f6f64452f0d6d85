// Ctrl-C (SIGINT) and SIGTERM, for the whole program. The handlers are
// installed first thing, before anything is read. While nothing needs
// finishing (the case is read, validated and built, nothing written yet),
// an interrupt ends the program at once: one line on stderr, exit status
// 130. Once a run writes results, or a sweep runs, it holds a
// FinishBeforeExit, and an interrupt only sets the flag: the run stops after
// its current step and keeps what it wrote (docs/guide/running.md).
#pragma once
#include <atomic>

namespace flowmpm {

// Installs the handlers for SIGINT and SIGTERM.
void install_interrupt_handlers();

// Set by the handlers: stop after the current step.
std::atomic<bool>& interrupt_requested();

// While one is alive, an interrupt sets interrupt_requested() instead of
// ending the program.
class FinishBeforeExit {
 public:
  FinishBeforeExit();
  ~FinishBeforeExit();
  FinishBeforeExit(const FinishBeforeExit&) = delete;
  FinishBeforeExit& operator=(const FinishBeforeExit&) = delete;
};

}  // namespace flowmpm
