#include "radiosity/core/huge_pages.h"

#include <sys/mman.h>

#include <cstdint>

namespace rad {
namespace {

// madvise over the whole `alignment`-sized pages inside [data, data + bytes): madvise wants an
// aligned start. A hint: its refusal is ignored.
[[maybe_unused]] void adviseInside(void* data, size_t bytes, uintptr_t alignment, int advice) {
  const auto begin = reinterpret_cast<uintptr_t>(data);
  const uintptr_t first = (begin + alignment - 1) & ~(alignment - 1);
  const uintptr_t last = (begin + bytes) & ~(alignment - 1);
  if (last > first) madvise(reinterpret_cast<void*>(first), last - first, advice);
}

}  // namespace

void adviseHugePages(void* data, size_t bytes) {
#ifdef MADV_HUGEPAGE
  adviseInside(data, bytes, uintptr_t{2} << 20, MADV_HUGEPAGE);
#else
  (void)data;
  (void)bytes;
#endif
}

void populatePages(void* data, size_t bytes) {
#ifdef MADV_POPULATE_WRITE
  adviseInside(data, bytes, 4096, MADV_POPULATE_WRITE);
#else
  (void)data;
  (void)bytes;
#endif
}

}  // namespace rad
