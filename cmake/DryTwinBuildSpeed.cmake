# Build speed on two cores (issue #44; measured translation unit by translation unit in
# docs/build-speed.md). Three things pay off, in this order:
#  1. Line tables instead of full debug information in RelWithDebInfo (-g1 for -g): writing the
#     DWARF of Eigen's and nlohmann::json's templates was 40 % of an engine file's compile time
#     (ResidualFit.cpp 20.7 s -> 12.0 s). Backtraces keep file:line; a debugger session wants
#     -DDRYTWIN_FULL_DEBUG_INFO=ON (or a Debug build).
#  2. lld (else gold) instead of ld.bfd: a test program links in 2.1 s of CPU instead of 7.0 s, and
#     there are some thirty programs.
#  3. libtorch's headers parsed once: the LSTM's files form one unity group (engine/CMakeLists.txt).
# Precompiled headers were tried and measured slower with GCC 12: loading a 136 MB header
# (standard library, Eigen, nlohmann::json) cost 1-3 s per file, more than parsing saved
# (ResidualFit.cpp 13.0 s without, 14.3 s with; CsvLines.cpp 0.6 s, 3.5 s; docs/build-speed.md).
option(DRYTWIN_FULL_DEBUG_INFO "RelWithDebInfo with full debug information (-g); off: line tables (-g1)" OFF)
option(DRYTWIN_FAST_LINKER "Link with lld, else gold, when the compiler accepts it" ON)

if(NOT DRYTWIN_FULL_DEBUG_INFO)
  foreach(lang C CXX)
    string(REGEX REPLACE "(^| )-g( |$)" "\\1-g1\\2" CMAKE_${lang}_FLAGS_RELWITHDEBINFO
                         "${CMAKE_${lang}_FLAGS_RELWITHDEBINFO}")
  endforeach()
endif()

if(DRYTWIN_FAST_LINKER)
  include(CheckLinkerFlag)
  check_linker_flag(CXX "-fuse-ld=lld" DRYTWIN_LINKER_LLD)
  if(DRYTWIN_LINKER_LLD)
    add_link_options(-fuse-ld=lld)
  else()
    check_linker_flag(CXX "-fuse-ld=gold" DRYTWIN_LINKER_GOLD)
    if(DRYTWIN_LINKER_GOLD)
      add_link_options(-fuse-ld=gold)
    endif()
  endif()
endif()
