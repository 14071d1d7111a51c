# A gas-phase coupling on the lumped plant against a healthy reference (seeds 101 and 7101, as
# study_discovery's first lumped seed): the wall loss, its look-alike, predicts worse alone. One
# change, one finding: the coupling, with the wall loss listed beside it, neither named after it
# nor as a second finding (before 2026-11-27 evening: two findings; before 2026-12-08: named after
# the coupling with a joint value). Usage:
#   cmake -DEXE=drytwin -DWORK=dir -P this file
include(${CMAKE_CURRENT_LIST_DIR}/DiscoverJson.cmake)
file(REMOVE_RECURSE ${WORK})
foreach(step "reference;--seed;7101" "after;--seed;101;--effect;gas_phase_coupling=0.25")
  list(GET step 0 name)
  list(SUBLIST step 1 -1 options)
  drytwin_run("generate ${name}" generate --plant lumped --sensors builtin --out ${WORK}/${name} --batches 4
              --samples 3000 ${options})
endforeach()
drytwin_run("discover --reference" discover --reference ${WORK}/reference --data ${WORK}/after
            --json ${WORK}/discover.json)
drytwin_expect_change_and_first_cause(${WORK}/discover.json gas_phase_coupling "against the reference")
# The wall loss is the coupling's look-alike, listed with it; but it is not on this line: after
# the coupling is taken in, it does not lower the outlet moisture's held-out error (an output it
# acts on), so it is not named after the coupling (issue #72 item 2; before 2026-12-08 it was, with
# a joint value of 0.29: a cause that is not there).
string(JSON count LENGTH "${json}" findings 0 look_alikes)
set(listed FALSE)
math(EXPR last "${count} - 1")
foreach(i RANGE ${last})
  string(JSON cause GET "${json}" findings 0 look_alikes ${i} cause)
  string(JSON after GET "${json}" findings 0 look_alikes ${i} named_after)
  if(cause STREQUAL "tube_wall_heat_loss")
    set(listed TRUE)
    if(after)
      message(FATAL_ERROR "the wall loss, not on this line, is named after the coupling\n${out}")
    endif()
  endif()
endforeach()
if(NOT listed)
  message(FATAL_ERROR "the wall loss is not listed as the coupling's look-alike\n${out}")
endif()
string(JSON findings LENGTH "${json}" findings)
foreach(i RANGE ${findings})
  if(i LESS findings)
    string(JSON cause GET "${json}" findings ${i} cause)
    if(cause STREQUAL "tube_wall_heat_loss")
      message(FATAL_ERROR "the wall loss is named again as finding ${i}\n${out}")
    endif()
  endif()
endforeach()
message(STATUS "gas_phase_coupling named; the wall loss listed as its look-alike, not named after it")
