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
# One hour of the scenario with CAUSE at STRENGTH from 5 min, judged against REFERENCE: CAUSE first.
function(expect_named_first cause strength reference what)
  run_training(${cause} "{\"scenario\": ${scenario}, \"end_s\": 3600, \"events\": [{\"at_s\": 0, \
\"type\": \"fault\", \"cause\": \"${cause}\", \"strength\": ${strength}, \"onset_s\": 300}]}")
  drytwin_run("discover --reference (${cause})" discover --reference ${WORK}/${reference}
              --data ${WORK}/${cause}/recording --json ${WORK}/discover-${cause}.json)
  drytwin_expect_change_and_first_cause(${WORK}/discover-${cause}.json ${cause} "${what}")
  message(STATUS "${cause} named first ${what}")
endfunction()
expect_named_first(heat_transfer_fouling 0.4 reference "against the commissioning runs")
expect_named_first(transport_delay_error 30 reference "against the commissioning runs")
expect_named_first(moisture_meter_lag 60 reference6 "against six commissioning runs")
