#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <string>

namespace rad {

// Progress of one long stage on stderr. On a terminal: a live line with percent, rate and time
// left, redrawn at most ~10 times a second. Otherwise (logs, CI): one summary line at the end.
// advance() is thread-safe and cheap enough to call per row.
class Progress {
 public:
  Progress(std::string label, uint64_t total, std::string unit);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  void advance(uint64_t n = 1);
  // For stages whose end is not a count (convergence): fraction in [0, 1] and a status text.
  void setFraction(double fraction, const std::string& status);
  void finish(const std::string& status = "");

  static bool stderrIsTerminal();

 private:
  void draw(bool final);
  using Clock = std::chrono::steady_clock;
  std::string label_, unit_, status_;
  uint64_t total_;
  std::atomic<uint64_t> done_{0};
  std::atomic<int64_t> lastDrawNs_{0};
  double fraction_ = -1;
  Clock::time_point start_;
  bool terminal_;
  bool finished_ = false;
};

}  // namespace rad
