#pragma once

namespace drytwin {

/// @brief Keeps the memory of large matrices in the process between uses instead of returning
/// it to the system at every free (glibc's malloc). The residual model's fits allocate and free
/// matrices of tens of megabytes thousands of times; by default each one is a fresh mmap whose
/// pages the kernel zeroes on first touch, and both cores then wait on the same page-fault lock.
/// Measured on the demo (2 cores): `drytwin train` 46 s wall clock, 10.9 s of system time and
/// 1.36 million page faults before, 29 s, 3.2 s and 0.40 million with the heap kept;
/// `drytwin ablation` 57 s, 24.8 s, 3.25 million with the heap kept, 38 s, 6.6 s and 0.81 million
/// with no block mmapped (docs/speed.md). The resident size may stay up to 1 GB above what is in use. Call
/// once, first thing in main(); elsewhere than glibc it does nothing.
void tuneAllocatorForLargeMatrices();

} // namespace drytwin
