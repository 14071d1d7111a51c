# Run speed (issue #44). DryTwin is built from source on the machine that runs it, so the
# compiler may use every instruction that machine has: Eigen's matrix products, which the
# residual model's fits spend most of their time in, then use AVX2/AVX-512 and FMA instead of
# SSE2. Measured on the project's 2-core machine: X^T X of 42,000 x 250 in 0.47 s instead of
# 1.78 s (docs/build-speed.md). A binary built this way may not start on an older processor:
# for a build to be copied to other machines, configure with -DDRYTWIN_NATIVE_ARCH=OFF.
option(DRYTWIN_NATIVE_ARCH "Compile for the build machine's processor (-march=native)" ON)

if(DRYTWIN_NATIVE_ARCH)
  include(CheckCXXCompilerFlag)
  check_cxx_compiler_flag("-march=native" DRYTWIN_COMPILER_MARCH_NATIVE)
  if(DRYTWIN_COMPILER_MARCH_NATIVE)
    add_compile_options(-march=native)
    # GCC 12 warns "'__Y' may be used uninitialized" inside its own avx512fintrin.h/avxintrin.h
    # for Eigen's vectorised expressions, hundreds of times per build: a false positive of that
    # compiler (fixed in GCC 13), not a defect in DryTwin or Eigen.
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
      add_compile_options(-Wno-maybe-uninitialized)
    endif()
  endif()
endif()
