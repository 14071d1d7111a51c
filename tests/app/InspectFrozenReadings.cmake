# Frozen transmitter readings in a generated data set (the plant's stuck faults, three per channel
# and hour): `drytwin inspect --json` lists each one the plant's truth file counts, and no other
# (the cleaning rule of docs/plant.md). Usage: cmake -DEXE=drytwin -DWORK=dir -P this file
include(${CMAKE_CURRENT_LIST_DIR}/DiscoverJson.cmake) # drytwin_run
file(REMOVE_RECURSE ${WORK})
drytwin_run(generate generate --out ${WORK}/data --truth ${WORK}/truth.json --seed 11 --batches 2 --samples 3000
            --sensor-stuck 3)
drytwin_run(inspect inspect --data ${WORK}/data --json ${WORK}/inspect.json)
file(READ ${WORK}/truth.json truth)
string(JSON channels GET "${truth}" sensors channels)
string(JSON count LENGTH "${channels}")
set(stuck 0)
math(EXPR last "${count} - 1")
foreach(i RANGE ${last})
  string(JSON name MEMBER "${channels}" ${i})
  string(JSON n GET "${channels}" ${name} stuck)
  math(EXPR stuck "${stuck} + ${n}")
endforeach()
file(READ ${WORK}/inspect.json json)
string(JSON found LENGTH "${json}" cleaning frozen_readings)
string(JSON rows GET "${json}" cleaning dropped_stuck)
# A stuck value can start inside a dropout or touch another; most must be found, none invented.
math(EXPR least "(${stuck} * 4) / 5")
if(stuck LESS 5 OR found LESS least OR found GREATER stuck OR rows LESS found)
  message(FATAL_ERROR "the plant froze ${stuck} readings; inspect lists ${found} (${rows} rows)")
endif()
message(STATUS "${found} of ${stuck} frozen readings listed, ${rows} rows left out")
