# The README's story against a reference period, as scripts/demo-reference.sh tells it headless:
# six healthy batches, then four in which the outlet meter reads 0.8 % wb high from 20 min into
# each batch. The detectors must flag the change, the meter's offset must be named first, and its
# onset must lie within 2 min of 20 min (the story's screenshots show all three; with a reference
# of four batches the detectors had stopped alarming unnoticed). Usage:
#   cmake -DEXE=drytwin -DSCRIPT=scripts/demo-reference.sh -DWORK=dir -P this file
include(${CMAKE_CURRENT_LIST_DIR}/DiscoverJson.cmake)
file(REMOVE_RECURSE ${WORK})
execute_process(COMMAND ${CMAKE_COMMAND} -E env DRYTWIN_HEADLESS=1 DRYTWIN=${EXE} OUT=${WORK} bash ${SCRIPT}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "demo-reference.sh: exit ${rc}\n${out}\n${err}")
endif()
drytwin_expect_change_and_first_cause(${WORK}/discover.json moisture_meter_offset "in the demo's story")
string(JSON onset GET "${json}" findings 0 onset_s)
if(onset LESS 1080 OR onset GREATER 1320)
  message(FATAL_ERROR "the meter's offset starts at ${onset} s, not within 2 min of 1200 s:\n${out}")
endif()
string(JSON drytwin GET "${json}" detection detectors drytwin changed)
if(NOT drytwin)
  message(FATAL_ERROR "DryTwin's own detector does not flag the demo's change:\n${out}")
endif()
message(STATUS "the demo's story: changed, moisture_meter_offset first, from ${onset} s")
