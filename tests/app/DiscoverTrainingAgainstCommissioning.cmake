# Training recordings judged against the line's commissioning runs (three fault-free runs of the
# same scenario with other seeds, the first three the Training tab's monitor commissions on; the
# fewest it could have, where each change test has least power): one hour of the
# training_shift scenario (seed 7) with fouling at twice its default from 5 min. One recording
# against three runs gives each cause's change test little power (z about 1.4 for every cause);
# once a detector has flagged the change the screen only ranks the causes, and fouling is fitted
# and named first (DiscoveryOptions::screenAlphaOnceDetected). The same hour with the conveyor's
# transport time 30 s longer: its outlet temperature answers later while the moisture hardly shows
# it, which alone is the line's own thermal dynamics; against the commissioning runs that answer is
# the line's structure learnt there, and the transport time is named (it was turned down as
# "line_dynamics" before 2026-11-27). And a moisture meter lagging 60 s, against the six runs the
# Training tab commissions on: a lag's tangent at 0 ranks it below three process causes that the
# widened screen lets through, so it was never fitted; a timing cause that passes the strict screen
# is now fitted as well, and named (against three runs its estimate is not consistent part by
# part, and nothing is named). Usage:
#   cmake -DEXE=drytwin -DSCENARIO=training_shift.json -DWORK=dir -P this file
include(${CMAKE_CURRENT_LIST_DIR}/DiscoverJson.cmake)
file(REMOVE_RECURSE ${WORK})
file(READ ${SCENARIO} scenario)
function(run_training name json)
  file(WRITE ${WORK}/${name}.json "${json}")
  drytwin_run("training ${name}" training --script ${WORK}/${name}.json --out ${WORK}/${name})
endfunction()
foreach(run 1 2 3 4 5 6)
  math(EXPR seed "90007 + ${run}")
  string(REPLACE "\"seed\": 7" "\"seed\": ${seed}" commissioning "${scenario}")
  run_training(commissioning-${run} "{\"scenario\": ${commissioning}, \"events\": []}")
  file(GLOB recorded ${WORK}/commissioning-${run}/recording/*.csv)
  file(READ ${recorded} text)
  # Each run its own batch id (a recording is named after its scenario; ids must be unique).
  string(REGEX REPLACE "# batch: [^\n]*" "# batch: C${run}" text "${text}")
  if(run LESS_EQUAL 3)
    file(WRITE ${WORK}/reference/C${run}.csv "${text}")
  endif()
  file(WRITE ${WORK}/reference6/C${run}.csv "${text}")
endforeach()
run_training(fouled "{\"scenario\": ${scenario}, \"end_s\": 3600, \"events\": [{\"at_s\": 0, \"type\": \"fault\", \
\"cause\": \"heat_transfer_fouling\", \"strength\": 0.4, \"onset_s\": 300}]}")
drytwin_run("discover --reference" discover --reference ${WORK}/reference --data ${WORK}/fouled/recording
            --json ${WORK}/discover.json)
drytwin_expect_change_and_first_cause(${WORK}/discover.json heat_transfer_fouling "against the commissioning runs")
message(STATUS "heat_transfer_fouling named first against the commissioning runs")

run_training(transport "{\"scenario\": ${scenario}, \"end_s\": 3600, \"events\": [{\"at_s\": 0, \"type\": \"fault\", \
\"cause\": \"transport_delay_error\", \"strength\": 30, \"onset_s\": 300}]}")
drytwin_run("discover --reference (transport)" discover --reference ${WORK}/reference --data ${WORK}/transport/recording
            --json ${WORK}/discover-transport.json)
drytwin_expect_change_and_first_cause(${WORK}/discover-transport.json transport_delay_error "against the commissioning runs")
message(STATUS "transport_delay_error named first against the commissioning runs")

run_training(meterlag "{\"scenario\": ${scenario}, \"end_s\": 3600, \"events\": [{\"at_s\": 0, \"type\": \"fault\", \
\"cause\": \"moisture_meter_lag\", \"strength\": 60, \"onset_s\": 300}]}")
drytwin_run("discover --reference (meter lag)" discover --reference ${WORK}/reference6 --data ${WORK}/meterlag/recording
            --json ${WORK}/discover-meterlag.json)
drytwin_expect_change_and_first_cause(${WORK}/discover-meterlag.json moisture_meter_lag "against six commissioning runs")
message(STATUS "moisture_meter_lag named first against six commissioning runs")
