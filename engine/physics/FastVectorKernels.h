#pragma once

#include <sundials/sundials_nvector.h>

namespace drytwin::physics {

/// @brief Replaces the vector operations of a serial N_Vector (and of every vector later cloned
/// from it: CVODE's internal vectors, sensitivity vectors) by optimised kernels.
///
/// Why hand-written: Debian 12's libsundials (6.4.1) is compiled without optimisation — its
/// N_VLinearSum_Serial and N_VWSqrSumLocal_Serial spill every loop variable to the stack
/// (checked with objdump) and run at ~3 ns per element, six times slower than the same loop
/// compiled with -O2. On the batched parcel systems CVODE spends most of its time in these
/// operations, so the PBM was bound by them. SUNDIALS documents the ops table of an N_Vector as
/// the place to supply one's own implementations; the kernels here are Eigen array expressions
/// (vectorised) over the serial data, with the semantics of the SUNDIALS manual (§9.2).
/// The vector must have been created by N_VNew_Serial (or N_VMake_Serial).
void useFastVectorKernels(N_Vector v);

} // namespace drytwin::physics
