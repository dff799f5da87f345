#pragma once

#include <string>

namespace rad {

enum class LogLevel { Quiet = 0, Info = 1, Debug = 2 };

// Messages for people go to stderr; stdout stays free for machine-readable output.
void setLogLevel(LogLevel level);
LogLevel logLevel();
void logInfo(const std::string& message);
void logWarning(const std::string& message);
void logDebug(const std::string& message);

}  // namespace rad
