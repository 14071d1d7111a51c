# A change that begins during a batch and goes on (a moisture meter knocked 22 min into the third
# of four batches and not re-zeroed, so the fourth reads high from its first minute), against a
# healthy reference (distributed plant, realistic sensors). t_onset counts from each batch's start,
# so before 2026-11-29 the offset was taken to start 22 min into B04 too, or fitted from every
# batch's start, diluted by B03's healthy first minutes (the study's mid-batch part: 10 of 33
# named before, 15 after). Now DryTwin's monitor reads B04 changed before the onset time, B04 is
# judged as changed from its start (`batches_changed_from_start`), and the offset is named from
# its onset in B03 at its size. Usage:
#   cmake -DEXE=drytwin -DWORK=dir -P this file
include(${CMAKE_CURRENT_LIST_DIR}/DiscoverJson.cmake)
file(REMOVE_RECURSE ${WORK})
set(onset 1320)
drytwin_run("generate reference" generate --out ${WORK}/reference --seed 2030 --batches 6 --samples 3000)
drytwin_run("generate healthy" generate --out ${WORK}/healthy --seed 2031 --batches 2 --samples 3000)
drytwin_run("generate knocked" generate --out ${WORK}/knocked --seed 2032 --batches 1 --samples 3000
            --effect moisture_meter_offset=0.2 --onset moisture_meter_offset=${onset})
drytwin_run("generate after" generate --out ${WORK}/after --seed 2033 --batches 1 --samples 3000
            --effect moisture_meter_offset=0.2)
drytwin_compose_week(${WORK}/week ${WORK}/healthy:B01:B01 ${WORK}/healthy:B02:B02 ${WORK}/knocked:B01:B03
                     ${WORK}/after:B01:B04)
drytwin_run("discover --reference" discover --reference ${WORK}/reference --data ${WORK}/week
            --json ${WORK}/discover.json)
drytwin_expect_change_and_first_cause(${WORK}/discover.json moisture_meter_offset "from 22 min into B03 on")

# The batches the change goes on into, from their start: B04 alone.
string(JSON n LENGTH "${json}" batches_changed_from_start)
if(NOT n EQUAL 1)
  message(FATAL_ERROR "batches taken as changed from their start: ${n}, expected B04 alone:\n${out}")
endif()
string(JSON fromStart GET "${json}" batches_changed_from_start 0)
if(NOT fromStart STREQUAL "B04")
  message(FATAL_ERROR "batch taken as changed from its start: ${fromStart}, not B04:\n${out}")
endif()
string(JSON actsFromStart GET "${json}" findings 0 acts_from_start_of 0)
if(NOT actsFromStart STREQUAL "B04")
  message(FATAL_ERROR "the finding acts from the start of ${actsFromStart}, not B04:\n${out}")
endif()

# Named from its onset, within 5 min, at its size (0.2 % wb; from every batch's start, the first
# 22 healthy minutes of B03 pull it down).
string(JSON onsetS GET "${json}" findings 0 onset_s)
math(EXPR early "${onset} - 300")
math(EXPR late "${onset} + 300")
if(onsetS LESS early OR onsetS GREATER late)
  message(FATAL_ERROR "onset found at ${onsetS} s, not within 5 min of ${onset} s:\n${out}")
endif()
string(JSON value GET "${json}" findings 0 parameter value)
if(value LESS 0.17 OR value GREATER 0.23)
  message(FATAL_ERROR "meter offset fitted at ${value} % wb, not within 0.17-0.23 (true 0.2):\n${out}")
endif()
string(JSON notes GET "${json}" notes)
if(NOT notes MATCHES "the change goes on from the start of B04")
  message(FATAL_ERROR "no note says the change goes on from the start of B04: ${notes}")
endif()
message(STATUS "meter offset ${value} % wb named from ${onsetS} s in B03 and from the start of B04")
