# Build speed on two cores (issue #44; measured translation unit by translation unit in
# docs/build-speed.md). Three things pay off, in this order:
#  1. Line tables instead of full debug information in RelWithDebInfo (-g1 for -g): writing the
#     DWARF of Eigen's and nlohmann::json's templates was 40 % of an engine file's compile time
#     (ResidualFit.cpp 20.7 s -> 12.0 s). Backtraces keep file:line; a debugger session wants
#     -DDRYTWIN_FULL_DEBUG_INFO=ON (or a Debug build).
#  2. lld (else gold) instead of ld.bfd: a test program links in 2.1 s of CPU instead of 7.0 s, and
#     there are some thirty programs.
#  3. Precompiled headers of what nearly every file of a target parses anyway (the standard
#     library, Eigen, nlohmann::json; Qt and Qwt in the widgets): 4-6 s of front end per engine
#     file, most of it these headers.
option(DRYTWIN_FULL_DEBUG_INFO "RelWithDebInfo with full debug information (-g); off: line tables (-g1)" OFF)
option(DRYTWIN_FAST_LINKER "Link with lld, else gold, when the compiler accepts it" ON)
option(DRYTWIN_PRECOMPILED_HEADERS "Precompiled headers for the engine, the widgets, the CLI and the tests" ON)

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

# The headers every engine file's translation unit parses (counted over engine/: <vector> in 65
# files, Eigen through the model headers in most of the rest).
set(DRYTWIN_ENGINE_PCH <algorithm> <cmath> <limits> <map> <memory> <optional> <string> <string_view>
    <vector> <Eigen/Dense> <nlohmann/json.hpp>)

# drytwin_use_precompiled_headers(target header...): a no-op when the option is off, so that a
# build without them proves every file includes what it uses.
function(drytwin_use_precompiled_headers target)
  if(DRYTWIN_PRECOMPILED_HEADERS)
    target_precompile_headers(${target} PRIVATE ${ARGN})
  endif()
endfunction()
