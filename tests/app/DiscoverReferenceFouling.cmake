# Fouling after a failed cleaning against a healthy reference (distributed plant, realistic
# sensors; the seeds of test_discovery_reference): `drytwin discover --reference` names fouling
# first, writes the reference's value beside the new one, and says in "response_scale" how much
# each output it acts on moved against the model form's prediction (the moisture as the model
# says, the temperatures less: a lumped tube without a gas phase). Usage:
#   cmake -DEXE=drytwin -DWORK=dir -P this file
include(${CMAKE_CURRENT_LIST_DIR}/DiscoverJson.cmake)
file(REMOVE_RECURSE ${WORK})
foreach(step "reference;--seed;41" "after;--seed;42;--effect;heat_transfer_fouling=0.3")
  list(GET step 0 name)
  list(SUBLIST step 1 -1 options)
  drytwin_run("generate ${name}" generate --out ${WORK}/${name} --batches 4 --samples 3000 ${options})
endforeach()
drytwin_run("discover --reference" discover --reference ${WORK}/reference --data ${WORK}/after
            --json ${WORK}/discover.json)
drytwin_expect_change_and_first_cause(${WORK}/discover.json heat_transfer_fouling "against the reference")
string(JSON value GET "${json}" findings 0 parameter value)
string(JSON reference GET "${json}" findings 0 parameter reference_value)
if(NOT value GREATER reference)
  message(FATAL_ERROR "theta_foul ${value} 1/h is not above its reference value ${reference}")
endif()
string(JSON moisture GET "${json}" findings 0 response_scale X_out)
string(JSON temperature GET "${json}" findings 0 response_scale T_hdt)
if(moisture LESS 0.75 OR moisture GREATER 1.25)
  message(FATAL_ERROR "X_out moved ${moisture} times the model's fouling effect; expected about 1")
endif()
if(NOT temperature LESS 0.667 OR NOT temperature GREATER 0.25)
  message(FATAL_ERROR "T_hdt moved ${temperature} times the model's fouling effect; expected 0.25-0.67")
endif()
message(STATUS "heat_transfer_fouling named: ${value} 1/h (reference ${reference}); X_out ${moisture}, T_hdt ${temperature}")
