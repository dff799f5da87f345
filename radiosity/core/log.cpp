#include "radiosity/core/log.h"

#include <atomic>
#include <cstdio>
#include <mutex>
#include <sstream>

namespace rad {
namespace {
std::atomic<LogLevel> g_level{LogLevel::Info};
std::mutex g_mutex;

void emit(const char* prefix, const std::string& message) {
  std::lock_guard<std::mutex> lock(g_mutex);
  std::fprintf(stderr, "%s%s\n", prefix, message.c_str());
  std::fflush(stderr);
}
}  // namespace

void setLogLevel(LogLevel level) { g_level = level; }
LogLevel logLevel() { return g_level; }
void logInfo(const std::string& m) {
  if (g_level >= LogLevel::Info) emit("", m);
}
void logWarning(const std::string& m) { emit("warning: ", m); }
void logDebug(const std::string& m) {
  if (g_level >= LogLevel::Debug) emit("debug: ", m);
}

std::string formatNumber(double value) {
  std::ostringstream s;
  s.precision(3);
  s << value;
  return s.str();
}

}  // namespace rad
