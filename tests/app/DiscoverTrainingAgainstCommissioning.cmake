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
# part, and nothing is named). On seed 8 the moisture rises 1.7 % wb in the first 3 min, before the
# lag begins: read without the lag, that step held the lag fitted from the start at 5.7 s, and
# nothing was named; the lag is now also fitted from the detector's change point (11 min), and
# named there (DiscoveryOptions::lagFromChangePoint). Usage:
#   cmake -DEXE=drytwin -DSCENARIO=training_shift.json -DWORK=dir -P this file
include(${CMAKE_CURRENT_LIST_DIR}/DiscoverJson.cmake)
file(REMOVE_RECURSE ${WORK})
file(READ ${SCENARIO} scenario)
function(run_training name json)
  file(WRITE ${WORK}/${name}.json "${json}")
  drytwin_run("training ${name}" training --script ${WORK}/${name}.json --out ${WORK}/${name})
endfunction()
# The commissioning runs of the line of seed LINE_SEED (seeds LINE_SEED + 90001 ... + 90006, as the
# Training tab's monitor commissions them): the first three in DIR, all six in DIR6.
function(commission line_seed dir dir6)
  foreach(run 1 2 3 4 5 6)
    math(EXPR seed "${line_seed} + 90000 + ${run}")
    string(REPLACE "\"seed\": 7" "\"seed\": ${seed}" commissioning "${scenario}")
    run_training(commissioning-${line_seed}-${run} "{\"scenario\": ${commissioning}, \"events\": []}")
    file(GLOB recorded ${WORK}/commissioning-${line_seed}-${run}/recording/*.csv)
    file(READ ${recorded} text)
    # Each run its own batch id (a recording is named after its scenario; ids must be unique).
    string(REGEX REPLACE "# batch: [^\n]*" "# batch: C${run}" text "${text}")
    if(run LESS_EQUAL 3)
      file(WRITE ${WORK}/${dir}/C${run}.csv "${text}")
    endif()
    file(WRITE ${WORK}/${dir6}/C${run}.csv "${text}")
  endforeach()
endfunction()
commission(7 reference reference6)
# One hour of the scenario (seed SEED) with CAUSE at STRENGTH from 5 min, judged against
# REFERENCE: CAUSE first. Its finding's JSON is left in `finding` (the caller's scope).
function(expect_named_first_on_seed cause strength seed reference what)
  string(REPLACE "\"seed\": 7" "\"seed\": ${seed}" seeded "${scenario}")
  run_training(${cause}-${seed} "{\"scenario\": ${seeded}, \"end_s\": 3600, \"events\": [{\"at_s\": 0, \
\"type\": \"fault\", \"cause\": \"${cause}\", \"strength\": ${strength}, \"onset_s\": 300}]}")
  drytwin_run("discover --reference (${cause}, seed ${seed})" discover --reference ${WORK}/${reference}
              --data ${WORK}/${cause}-${seed}/recording --json ${WORK}/discover-${cause}-${seed}.json)
  drytwin_expect_change_and_first_cause(${WORK}/discover-${cause}-${seed}.json ${cause} "${what}")
  string(JSON first GET "${json}" findings 0)
  set(finding "${first}" PARENT_SCOPE)
  message(STATUS "${cause} named first ${what} (seed ${seed})")
endfunction()
function(expect_named_first cause strength reference what)
  expect_named_first_on_seed(${cause} ${strength} 7 ${reference} "${what}")
endfunction()
expect_named_first(heat_transfer_fouling 0.4 reference "against the commissioning runs")
expect_named_first(transport_delay_error 30 reference "against the commissioning runs")
expect_named_first(moisture_meter_lag 60 reference6 "against six commissioning runs")
# Seed 8: a step of the process before the lag began (see the head of this file), against its own
# line's six commissioning runs.
commission(8 reference-8 reference6-8)
expect_named_first_on_seed(moisture_meter_lag 60 8 reference6-8 "against its line's six commissioning runs")
string(JSON lag GET "${finding}" parameter value)
string(JSON onset GET "${finding}" onset_s)
# From the start it stayed at 5.7 s; from the change point 39 s (a first-order lag fitted to the
# plant's second-order 60 s one, 95 % interval 17 to 61 s). Not before the fault began.
if(lag LESS 20 OR lag GREATER 120 OR onset LESS 300)
  message(FATAL_ERROR "meter lag on seed 8: ${lag} s (true 60 s) from ${onset} s (it began at 300 s):\n${out}")
endif()
message(STATUS "meter lag on seed 8: ${lag} s from ${onset} s")
