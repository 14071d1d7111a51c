#pragma once

namespace drytwin {

/// @brief Keeps the memory of large matrices in the process between uses instead of returning
/// it to the system at every free (glibc's malloc). The residual model's fits allocate and free
/// matrices of tens of megabytes thousands of times; by default each one is a fresh mmap whose
/// pages the kernel zeroes on first touch, and both cores then wait on the same page-fault lock.
/// Measured on `drytwin train` with the demo (2 cores): 43.7 s wall clock, 10.3 s of system time
/// and 1.38 million page faults before; 29.5 s, 1.7 s and 0.18 million after
/// (docs/speed.md). The resident size may stay up to 1 GB above what is in use. Call once, first
/// thing in main(); elsewhere than glibc it does nothing.
void tuneAllocatorForLargeMatrices();

} // namespace drytwin
