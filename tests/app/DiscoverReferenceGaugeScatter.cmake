# An inlet moisture gauge that scatters about three times as much as it did in a healthy reference
# (distributed plant, realistic sensors; seeds of the reference study): `drytwin discover
# --reference` names its scatter first and says how much it rose, although refitting its share
# explains only 1-2 % of the model's held-out error (the reference already took nearly all of the
# inlet's fast variation as scatter; docs/reference-period.md). Usage:
#   cmake -DEXE=drytwin -DWORK=dir -P this file
include(${CMAKE_CURRENT_LIST_DIR}/DiscoverJson.cmake)
file(REMOVE_RECURSE ${WORK})
drytwin_run("generate reference" generate --out ${WORK}/reference --batches 4 --samples 3000 --seed 7101)
drytwin_run("generate new" generate --out ${WORK}/new --batches 4 --samples 3000 --seed 101
            --effect inlet_moisture_sensor_noise=0.4)
drytwin_run("discover --reference" discover --reference ${WORK}/reference --data ${WORK}/new
            --json ${WORK}/discover.json)
drytwin_expect_first_cause(${WORK}/discover.json inlet_moisture_sensor_noise "against the reference")
string(JSON evidence GET "${json}" findings 0 evidence)
string(REGEX MATCH "fast scatter is [0-9.]+ % wb here against [0-9.]+ % wb on the reference \\(([0-9.]+) times\\)"
       found "${evidence}")
if(NOT found OR CMAKE_MATCH_1 LESS 2)
  message(FATAL_ERROR "the finding does not say the gauge's scatter at least doubled:\n${evidence}")
endif()
message(STATUS "inlet gauge scatter named: ${CMAKE_MATCH_1} times the reference's")
