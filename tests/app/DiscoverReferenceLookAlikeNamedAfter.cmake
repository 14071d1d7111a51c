# A gas-phase coupling on the lumped plant against a healthy reference (seeds 101 and 7101, as
# study_discovery's first lumped seed): the wall loss, its look-alike, predicts worse alone but is
# needed on top of the coupling. One change, one finding: the coupling names the group, the wall
# loss is in it as "named_after" with its joint value, and no second finding repeats it (before
# 2026-11-27 evening: "gas_phase_coupling" then "tube_wall_heat_loss", two findings). Usage:
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
string(JSON group GET "${json}" findings 0 group)
if(NOT group MATCHES "tube_wall_heat_loss")
  message(FATAL_ERROR "the coupling's finding is not the group with the wall loss: ${group}\n${out}")
endif()
string(JSON count LENGTH "${json}" findings 0 look_alikes)
set(folded "")
math(EXPR last "${count} - 1")
foreach(i RANGE ${last})
  string(JSON cause GET "${json}" findings 0 look_alikes ${i} cause)
  string(JSON after GET "${json}" findings 0 look_alikes ${i} named_after)
  if(cause STREQUAL "tube_wall_heat_loss" AND after)
    string(JSON folded GET "${json}" findings 0 look_alikes ${i} value)
  endif()
endforeach()
if(folded STREQUAL "" OR NOT folded GREATER 0)
  message(FATAL_ERROR "the wall loss is not in the finding as named after it with a joint value > 0\n${out}")
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
message(STATUS "gas_phase_coupling named as the group; theta_wall ${folded} named after it, in the same finding")
