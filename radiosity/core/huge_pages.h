#pragma once

#include <cstddef>

namespace rad {

// Asks the kernel to back [data, data + bytes) with huge pages where it can (Linux
// madvise(MADV_HUGEPAGE), for systems where transparent huge pages are "madvise"). For arrays of
// hundreds of megabytes filled once: each first touch of a 4 KiB page is a fault, and on
// virtual machines faults are dear. Only a hint: nothing happens where it is refused.
void adviseHugePages(void* data, size_t bytes);

}  // namespace rad
