// The radiosity executable's global operator new: allocations of 4 MiB and more (the form-factor
// tables, the lightmap pages, the meshes' and the scene's arrays) are advised onto 2 MiB pages
// before anything touches them. Each first touch of a 4 KiB page is a fault the kernel must serve
// and clear, and on virtual machines faults are dear: on Sponza a Gauss-Seidel solve is 1.31x and
// `bake --solution` 1.33x faster with the hint, a progressive solve the same, peak memory within
// 2% (`python3 bench/huge_pages.py`, docs/benchmarks.md "Huge pages"). Only a hint: with
// transparent huge pages "never" nothing changes, with "always" it is the kernel's default anyway.
// The memory is still malloc's, freed by the default operator delete (free). Left to the
// sanitizers' own allocators in their builds.
#include <cstdlib>
#include <new>
#include <string_view>

#include "radiosity/core/huge_pages.h"

// GCC names the sanitizers by macros, clang by __has_feature.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define RAD_SANITIZED_ALLOCATOR 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || \
    __has_feature(memory_sanitizer)
#define RAD_SANITIZED_ALLOCATOR 1
#endif
#endif

#ifndef RAD_SANITIZED_ALLOCATOR

namespace {

constexpr std::size_t kHugePageAllocation = std::size_t{4} << 20;

// RADIOSITY_HUGE_PAGES=0 leaves every allocation on the kernel's default pages: to measure what
// the hint gives (bench/huge_pages.py), or where the kernel's compaction for huge pages stalls.
bool hugePagesWanted() {
  static const bool wanted = [] {
    const char* setting = std::getenv("RADIOSITY_HUGE_PAGES");
    return !(setting && std::string_view(setting) == "0");
  }();
  return wanted;
}

void* allocate(std::size_t bytes) {
  if (bytes == 0) bytes = 1;
  for (;;) {
    if (void* p = std::malloc(bytes)) {
      if (bytes >= kHugePageAllocation && hugePagesWanted()) rad::adviseHugePages(p, bytes);
      return p;
    }
    const std::new_handler handler = std::get_new_handler();
    if (!handler) throw std::bad_alloc();
    handler();
  }
}

}  // namespace

void* operator new(std::size_t bytes) { return allocate(bytes); }
void* operator new[](std::size_t bytes) { return allocate(bytes); }

#endif
