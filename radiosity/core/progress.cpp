#include "radiosity/core/progress.h"

#include <unistd.h>

#include <cstdio>
#include <mutex>

#include "radiosity/core/log.h"

namespace rad {
namespace {
std::mutex g_drawMutex;

std::string formatSeconds(double s) {
  char buf[32];
  if (s < 60)
    std::snprintf(buf, sizeof buf, "%.1fs", s);
  else
    std::snprintf(buf, sizeof buf, "%dm%02ds", int(s) / 60, int(s) % 60);
  return buf;
}
}  // namespace

bool Progress::stderrIsTerminal() { return isatty(STDERR_FILENO) == 1; }

Progress::Progress(std::string label, uint64_t total, std::string unit)
    : label_(std::move(label)),
      unit_(std::move(unit)),
      total_(total),
      start_(Clock::now()),
      terminal_(stderrIsTerminal() && logLevel() >= LogLevel::Info) {}

Progress::~Progress() {
  if (!finished_) finish();
}

void Progress::advance(uint64_t n) {
  done_ += n;
  if (!terminal_) return;
  const int64_t now =
      std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now().time_since_epoch()).count();
  int64_t last = lastDrawNs_.load();
  if (now - last < 100000000) return;  // 10 Hz
  if (lastDrawNs_.compare_exchange_strong(last, now)) draw(false);
}

void Progress::setFraction(double fraction, const std::string& status) {
  {
    std::lock_guard<std::mutex> lock(g_drawMutex);
    fraction_ = fraction;
    status_ = status;
  }
  advance(0);
}

void Progress::finish(const std::string& status) {
  if (finished_) return;
  finished_ = true;
  if (!status.empty()) status_ = status;
  if (logLevel() >= LogLevel::Info) draw(true);
}

void Progress::draw(bool final) {
  std::lock_guard<std::mutex> lock(g_drawMutex);
  const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
  const uint64_t done = done_.load();
  double fraction = fraction_ >= 0 ? fraction_ : (total_ ? double(done) / double(total_) : 1.0);
  if (final && fraction_ < 0) fraction = 1.0;
  char line[512];
  if (final) {
    std::snprintf(line, sizeof line, "%s: %llu %s in %s (%.3g %s/s)%s%s", label_.c_str(),
                  (unsigned long long)done, unit_.c_str(), formatSeconds(elapsed).c_str(),
                  elapsed > 0 ? done / elapsed : 0.0, unit_.c_str(), status_.empty() ? "" : ", ",
                  status_.c_str());
    std::fprintf(stderr, terminal_ ? "\r\033[K%s\n" : "%s\n", line);
  } else {
    const double rate = elapsed > 0 ? done / elapsed : 0.0;
    const double left = fraction > 0 ? elapsed * (1 - fraction) / fraction : 0.0;
    std::snprintf(line, sizeof line, "%s: %5.1f%%  %.3g %s/s  %s left  %s", label_.c_str(),
                  100 * fraction, rate, unit_.c_str(), formatSeconds(left).c_str(),
                  status_.c_str());
    std::fprintf(stderr, "\r\033[K%s", line);
  }
  std::fflush(stderr);
}

}  // namespace rad
