#pragma once

#include <cstddef>

namespace rad {

// Asks the kernel to back [data, data + bytes) with huge pages where it can (Linux
// madvise(MADV_HUGEPAGE), for systems where transparent huge pages are "madvise"). For arrays of
// hundreds of megabytes filled once: each first touch of a 4 KiB page is a fault, and on
// virtual machines faults are dear. Only a hint: nothing happens where it is refused.
void adviseHugePages(void* data, size_t bytes);

// Has the kernel fault in [data, data + bytes) for writing now, without changing what is there
// (madvise(MADV_POPULATE_WRITE), Linux 5.14+): run on another thread while one thread fills the
// range, the clearing of its fresh pages (most of the cost of filling hundreds of megabytes on a
// virtual machine) is shared between the two. Safe beside writers; nothing happens where it is
// not supported.
void populatePages(void* data, size_t bytes);

}  // namespace rad
