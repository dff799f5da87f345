#include "radiosity/core/interrupt.h"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstring>
#include <thread>

namespace rad {
namespace {

// Lock-free atomics are async-signal-safe; the handler touches nothing else.
std::atomic<int> gSignal{0};
std::atomic<int> gOutputSections{0};
std::atomic<bool> gInstalled{false};
static_assert(std::atomic<int>::is_always_lock_free);

void writeStderr(const char* text) {
  const ssize_t ignored = ::write(STDERR_FILENO, text, std::strlen(text));
  (void)ignored;
}

extern "C" void onSignal(int signal) {
  int expected = 0;
  if (!gSignal.compare_exchange_strong(expected, signal)) {
    // Second signal: the user insists. Nothing partial can be left outside an OutputSection;
    // inside one, the temporary files may remain (as with a kill -9).
    writeStderr("\nradiosity: interrupted again, exiting now\n");
    ::_exit(128 + expected);
  }
}

// Ends a run whose current stage does not poll the flag, once the grace period has passed.
void watchdog(double graceSeconds) {
  using Clock = std::chrono::steady_clock;
  Clock::time_point seen{};
  for (;;) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    const int signal = gSignal.load();
    if (signal == 0) {
      seen = {};
      continue;
    }
    if (seen == Clock::time_point{}) seen = Clock::now();
    const double waited = std::chrono::duration<double>(Clock::now() - seen).count();
    if (waited >= graceSeconds && gOutputSections.load() == 0) {
      writeStderr(signal == SIGTERM ? "radiosity: terminated (SIGTERM); no output written\n"
                                    : "radiosity: interrupted (Ctrl-C); no output written\n");
      ::_exit(128 + signal);
    }
  }
}

std::string describe(int signal) {
  if (signal == SIGINT) return "interrupted (Ctrl-C)";
  if (signal == SIGTERM) return "terminated (SIGTERM)";
  return "stopped by signal " + std::to_string(signal);
}

}  // namespace

Interrupted::Interrupted(int signal)
    : std::runtime_error(describe(signal) + "; no output written"), signal_(signal) {}

void installInterruptHandlers(double graceSeconds) {
  if (gInstalled.exchange(true)) return;
  struct sigaction action {};
  action.sa_handler = onSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  std::thread(watchdog, graceSeconds).detach();
}

int interruptSignal() { return gSignal.load(std::memory_order_relaxed); }
bool interruptRequested() { return interruptSignal() != 0; }

void throwIfInterrupted() {
  if (const int signal = interruptSignal()) throw Interrupted(signal);
}

void requestInterrupt(int signal) { gSignal.store(signal); }
void clearInterrupt() { gSignal.store(0); }

OutputSection::OutputSection() { gOutputSections.fetch_add(1); }
OutputSection::~OutputSection() { gOutputSections.fetch_sub(1); }

}  // namespace rad
