#pragma once

#include <stdexcept>
#include <string>

namespace rad {

// Ctrl-C (SIGINT) and SIGTERM during a long run. The handler only sets a flag: long loops call
// throwIfInterrupted() between steps, so the run unwinds and AtomicFile removes anything it had
// started to write. A stage with no check (one long parallel form-factor pass) is ended by a
// watchdog instead: if the flag is still unanswered after a grace period, the process exits
// with 128 + signal, which is safe because outputs are only opened at the very end, inside an
// OutputSection (during which the watchdog waits). A second signal exits at once.
class Interrupted : public std::runtime_error {
 public:
  explicit Interrupted(int signal);
  int signal() const { return signal_; }
  int exitCode() const { return 128 + signal_; }  // the shell's convention: 130 for SIGINT

 private:
  int signal_;
};

// Installs the SIGINT/SIGTERM handlers and starts the watchdog (once; later calls do nothing).
// graceSeconds: how long an unanswered interrupt may wait before the watchdog ends the process.
void installInterruptHandlers(double graceSeconds = 0.3);

// The signal received (SIGINT, SIGTERM), or 0.
int interruptSignal();
bool interruptRequested();
// Throws Interrupted when a signal arrived.
void throwIfInterrupted();

// For tests: behave as if `signal` had arrived; clearInterrupt() forgets it.
void requestInterrupt(int signal);
void clearInterrupt();

// While one exists the watchdog does not end the process (files are being written and renamed:
// they must either all appear or none). Nestable.
class OutputSection {
 public:
  OutputSection();
  ~OutputSection();
  OutputSection(const OutputSection&) = delete;
  OutputSection& operator=(const OutputSection&) = delete;
};

}  // namespace rad
