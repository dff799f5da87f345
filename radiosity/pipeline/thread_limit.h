#pragma once

// --threads: how many worker threads a command runs on. The one place its value is read
// (0: every hardware thread).
#include <tbb/global_control.h>
#include <tbb/info.h>

#include <cstddef>

namespace rad {

inline int threadCount(int requested) {
  return requested > 0 ? requested : tbb::info::default_concurrency();
}

// Caps TBB's parallelism at threadCount(requested) for as long as it lives: every parallel stage
// started meanwhile (the solve, the gather, rasterising, EXR compression) keeps to it.
class ThreadLimit {
 public:
  explicit ThreadLimit(int requested)
      : threads_(threadCount(requested)),
        control_(tbb::global_control::max_allowed_parallelism, static_cast<size_t>(threads_)) {}
  int threads() const { return threads_; }

 private:
  int threads_;
  tbb::global_control control_;
};

}  // namespace rad
