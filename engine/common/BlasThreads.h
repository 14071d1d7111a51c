#pragma once

#include <string>

namespace drytwin {

/// @brief Makes OpenBLAS compute in the calling thread only, once per process. DryTwin runs its
/// own work side by side (a training session's MPC beside a job on the engine thread, the
/// closed-loop controllers beside each other), so BLAS must be safe to call from several threads
/// at once, which only a threaded OpenBLAS build is (Debian's libopenblas0-pthread, which
/// scripts/install-deps.sh installs); one thread per caller keeps it from starting threads of its
/// own on top of DryTwin's. Without OpenBLAS (the reference BLAS) it does nothing. Thread-safe.
void blasInCallingThread();

/// @brief Why the BLAS this process loaded cannot be called from two threads at once (OpenBLAS
/// built without threads: Debian's libopenblas0-serial crashed inside Ipopt while the LSTM trained
/// on another thread), with what to install instead; "" when it can.
std::string blasConcurrencyProblem();

} // namespace drytwin
