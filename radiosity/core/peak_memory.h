#pragma once

#include <sys/resource.h>

#include <cstdint>

namespace rad {

// The process's peak resident memory so far, in bytes (Linux reports ru_maxrss in KiB): what the
// scale benchmarks and summary.json quote as peak memory.
inline int64_t peakMemoryBytes() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) return 0;
  return static_cast<int64_t>(usage.ru_maxrss) * 1024;
}

}  // namespace rad
