# A meter lag of 60 s switched on 5 min into one hour of a training recording (the training_shift
# scenario under the plant's PI loop, seed 7): `drytwin discover` on the recording names the meter
# lag first, near its strength, with an onset within ±10 min of the truth. One recording has no
# batches to compare, so the lag's estimate is judged on thirds of it; fitted from the start the
# thirds disagree (the first one holds 5 min without the lag), and the onset found on the lag's own
# effect makes them agree. Usage: cmake -DEXE=drytwin -DSCRIPT=a.json -DWORK=dir -P this file
include(${CMAKE_CURRENT_LIST_DIR}/DiscoverJson.cmake)
file(REMOVE_RECURSE ${WORK})
drytwin_run("training replay" training --script ${SCRIPT} --out ${WORK}/session)
drytwin_run(discover discover --data ${WORK}/session/recording --json ${WORK}/discover.json)
drytwin_expect_first_cause(${WORK}/discover.json moisture_meter_lag "on the recording")
string(JSON tau GET "${json}" findings 0 parameter value)
string(JSON onset ERROR_VARIABLE noOnset GET "${json}" findings 0 onset_s)
if(noOnset)
  message(FATAL_ERROR "the meter lag is named without its onset:\n${out}")
endif()
# CMake compares numbers as doubles with LESS/GREATER.
if(tau LESS 30 OR tau GREATER 120)
  message(FATAL_ERROR "tau_meter = ${tau} s, the plant's is 60 s")
endif()
if(onset GREATER 900)
  message(FATAL_ERROR "onset ${onset} s, the fault starts at 300 s")
endif()
message(STATUS "moisture_meter_lag named: tau ${tau} s, onset ${onset} s")
