# Build speed on two cores (issue #44; measured translation unit by translation unit in
# docs/build-speed.md). Three things pay off, in this order:
#  1. Line tables instead of full debug information in RelWithDebInfo (-g1 for -g): writing the
#     DWARF of Eigen's and nlohmann::json's templates was 40 % of an engine file's compile time
#     (ResidualFit.cpp 20.7 s -> 12.0 s). Backtraces keep file:line; a debugger session wants
#     -DDRYTWIN_FULL_DEBUG_INFO=ON (or a Debug build).
#  2. lld (else gold) instead of ld.bfd: a test program links in 2.1 s of CPU instead of 7.0 s, and
#     there are some thirty programs.
#  3. Headers parsed once per folder, not once per file: the files of one folder compile in unity
#     groups (drytwin_unity_groups_by_folder below); libtorch's headers once for the LSTM's files.
#     The engine: 317 s -> 217 s wall clock on two cores (docs/build-speed.md).
# Precompiled headers were tried and measured slower with GCC 12: loading a 136 MB header
# (standard library, Eigen, nlohmann::json) cost 1-3 s per file, more than parsing saved
# (ResidualFit.cpp 13.0 s without, 14.3 s with; CsvLines.cpp 0.6 s, 3.5 s; docs/build-speed.md).
# The test programs are the exception and have one (tests/CMakeLists.txt).
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

option(DRYTWIN_UNITY_BY_FOLDER "Compile the files of one folder in unity groups (engine, widgets, CLI)" ON)
set(DRYTWIN_UNITY_FILES 6 CACHE STRING "Most files in one unity group")

# drytwin_unity_groups_by_folder(TARGET <target> BASE <dir> SOURCES <files...> [ALONE <files...>])
# Puts up to DRYTWIN_UNITY_FILES files of one folder (relative to BASE) into one unity group of
# TARGET, which must use UNITY_BUILD_MODE GROUP. The files of one folder share most of their
# headers (Eigen, nlohmann::json, Qt, the folder's own), which a two-core build otherwise parses
# once per file. ALONE files stay their own translation unit: the heaviest ones (their cost is
# template instantiation, not parsing), so that both cores stay busy. CMake never groups a file
# with its own compile options. A file's anonymous-namespace names must then be unique in its
# folder; the build says so at once when they are not.
function(drytwin_unity_groups_by_folder)
  cmake_parse_arguments(PARSE_ARGV 0 arg "" "TARGET;BASE" "SOURCES;ALONE")
  set_target_properties(${arg_TARGET} PROPERTIES UNITY_BUILD ON UNITY_BUILD_MODE GROUP)
  if(NOT DRYTWIN_UNITY_BY_FOLDER)
    return()
  endif()
  set(members 0)
  set(previous_folder "//none")
  set(group_number 0)
  foreach(source IN LISTS arg_SOURCES)
    file(RELATIVE_PATH relative ${arg_BASE} ${source})
    get_filename_component(folder ${relative} DIRECTORY)
    if(relative IN_LIST arg_ALONE)
      continue()
    endif()
    if(NOT folder STREQUAL previous_folder OR members GREATER_EQUAL DRYTWIN_UNITY_FILES)
      math(EXPR group_number "${group_number} + 1")
      set(members 0)
      set(previous_folder "${folder}")
    endif()
    string(REPLACE "/" "_" group_name "folder_${folder}")
    set_source_files_properties(${source} PROPERTIES UNITY_GROUP "${group_name}_${group_number}")
    math(EXPR members "${members} + 1")
  endforeach()
endfunction()
