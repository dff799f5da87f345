#pragma once

#include <chrono>

namespace rad {

// Wall seconds since `start` on the steady clock: the stage times of summary.json and the logs.
inline double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace rad
