# A change that begins at a batch change (fouling after a failed cleaning, from the third of four
# batches) against a healthy reference (distributed plant, realistic sensors): DryTwin's monitor
# places the change in the third batch, the two batches before it are left out of the causes'
# fits (`batches_before_change`), and fouling is named. Judged with the two healthy batches in,
# nothing was named (the first two were called a batch shift; 2026-11-28). Usage:
#   cmake -DEXE=drytwin -DWORK=dir -P this file
include(${CMAKE_CURRENT_LIST_DIR}/DiscoverJson.cmake)
file(REMOVE_RECURSE ${WORK})
drytwin_run("generate reference" generate --out ${WORK}/reference --seed 2030 --batches 6 --samples 3000)
drytwin_run("generate healthy" generate --out ${WORK}/healthy --seed 2031 --batches 2 --samples 3000)
drytwin_run("generate fouled" generate --out ${WORK}/fouled --seed 2032 --batches 2 --samples 3000
            --effect heat_transfer_fouling=0.2)
# The week judged: two healthy batches, then the two fouled ones as B03 and B04.
drytwin_compose_week(${WORK}/week ${WORK}/healthy:B01:B01 ${WORK}/healthy:B02:B02 ${WORK}/fouled:B01:B03
                     ${WORK}/fouled:B02:B04)
drytwin_run("discover --reference" discover --reference ${WORK}/reference --data ${WORK}/week
            --json ${WORK}/discover.json)
drytwin_expect_change_and_first_cause(${WORK}/discover.json heat_transfer_fouling "from the third batch on")
string(JSON onsetBatch GET "${json}" detection detectors drytwin onset batch)
if(NOT onsetBatch STREQUAL "B03")
  message(FATAL_ERROR "DryTwin's monitor places the change in ${onsetBatch}, not B03:\n${out}")
endif()
string(JSON onsetS GET "${json}" detection detectors drytwin onset time_s)
string(JSON lowS GET "${json}" detection detectors drytwin onset ci95 0)
# The windows before the estimate include a stretch no window judges: the interval reaches back
# over it (it read "900 to 960 s" before, as if the change could not have come earlier).
if(NOT lowS LESS onsetS)
  message(FATAL_ERROR "the onset's interval starts at ${lowS} s, not before its estimate ${onsetS} s")
endif()
string(JSON n LENGTH "${json}" batches_before_change)
set(before "")
if(n GREATER 0)
  math(EXPR last "${n} - 1")
  foreach(i RANGE ${last})
    string(JSON b GET "${json}" batches_before_change ${i})
    list(APPEND before ${b})
  endforeach()
endif()
if(NOT before STREQUAL "B01;B02")
  message(FATAL_ERROR "batches left out before the change: '${before}', expected B01 and B02:\n${out}")
endif()
string(JSON notes GET "${json}" notes)
if(NOT notes MATCHES "judged on the batches from B03 on")
  message(FATAL_ERROR "no note says the causes are judged from B03 on: ${notes}")
endif()
message(STATUS "fouling named from B03 on (monitor's onset ${onsetS} s, interval from ${lowS} s); left out: ${before}")
