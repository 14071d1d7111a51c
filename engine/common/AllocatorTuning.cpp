#include "common/AllocatorTuning.h"

#include <cstdlib> // defines __GLIBC__ where the C library is glibc
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace drytwin {

void tuneAllocatorForLargeMatrices() {
#if defined(__GLIBC__)
    // The heap keeps up to 1 GB of freed memory and grows 256 MB at a time, and serves every
    // block, however large (by default blocks above 128 kB-32 MB are mmapped one by one; a
    // thread's arena still maps what does not fit its 64 MB heap).
    mallopt(M_MMAP_MAX, 0);
    mallopt(M_TRIM_THRESHOLD, 1024 * 1024 * 1024);
    mallopt(M_TOP_PAD, 256 * 1024 * 1024);
#endif
}

} // namespace drytwin
