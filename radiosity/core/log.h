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

// A number for a message: 3 significant digits ("0.0123", "1.5e+06").
std::string formatNumber(double value);

}  // namespace rad
