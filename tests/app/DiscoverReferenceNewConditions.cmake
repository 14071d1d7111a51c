# A healthy pair whose new data ran in weather the reference never saw (distributed plant,
# realistic sensors with their spikes, stuck values and dropouts, unmeasured drift; healthy pair
# 216 of `study_discovery --reference`): its first batch at 14 °C and 73 % RH against reference runs at 27-34 °C. Its level had raised
# DryTwin's alarm; now that batch is judged only for changes within it, both detectors say
# "no change", nothing is named, and discover.json lists the batch under "level_not_judged" with a
# note that says why. Usage:
#   cmake -DEXE=drytwin -DWORK=dir -P this file
include(${CMAKE_CURRENT_LIST_DIR}/DiscoverJson.cmake)
file(REMOVE_RECURSE ${WORK})
set(healthy --batches 4 --samples 3000 --drift)
drytwin_run("generate reference" generate --out ${WORK}/reference --seed 7216 ${healthy})
drytwin_run("generate new" generate --out ${WORK}/new --seed 216 ${healthy})
drytwin_run("discover --reference" discover --reference ${WORK}/reference --data ${WORK}/new
            --json ${WORK}/discover.json)
file(READ ${WORK}/discover.json json)
string(JSON count LENGTH "${json}" findings)
if(NOT count EQUAL 0)
  string(JSON cause GET "${json}" findings 0 cause)
  message(FATAL_ERROR "a healthy pair named ${cause}:\n${out}")
endif()
foreach(detector drytwin pca)
  string(JSON changed GET "${json}" detection detectors ${detector} changed)
  string(JSON free GET "${json}" detection detectors ${detector} level_not_judged)
  if(changed)
    message(FATAL_ERROR "${detector} flags a healthy pair:\n${out}")
  endif()
  if(NOT free MATCHES "\"B01\"")
    message(FATAL_ERROR "${detector}: B01 (14 °C against 27-34 °C) should be judged only within itself: ${free}")
  endif()
endforeach()
string(JSON notes GET "${json}" notes)
if(NOT notes MATCHES "B01: T_amb_C is typically 14[^\"]*only changes within this batch")
  message(FATAL_ERROR "no note on B01's weather and what it means for the detectors: ${notes}")
endif()
message(STATUS "healthy pair in new weather: no change, nothing named; level not judged: ${free}")
