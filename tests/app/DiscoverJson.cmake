# Shared by the CLI tests that run drytwin and read its discover.json.

# Runs `EXE -q ARGN` and stops the test, naming WHAT and showing both outputs, unless it exits 0;
# its standard output is left in `out`.
macro(drytwin_run WHAT)
  execute_process(COMMAND ${EXE} -q ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${WHAT}: exit ${rc}\n${out}\n${err}")
  endif()
endmacro()

# Reads FILE into the variable `json` and stops
# the test unless its first finding names CAUSE (WHAT says on which data, for the message; `out`,
# the program's output, is shown with it).
macro(drytwin_expect_first_cause FILE CAUSE WHAT)
  file(READ ${FILE} json)
  string(JSON count LENGTH "${json}" findings)
  if(count EQUAL 0)
    message(FATAL_ERROR "nothing named ${WHAT}:\n${out}")
  endif()
  string(JSON cause GET "${json}" findings 0 cause)
  if(NOT cause STREQUAL "${CAUSE}")
    message(FATAL_ERROR "first cause named ${WHAT}: ${cause}, not ${CAUSE}:\n${out}")
  endif()
endmacro()

# As drytwin_expect_first_cause, and the judgement against a reference must have detected a change.
macro(drytwin_expect_change_and_first_cause FILE CAUSE WHAT)
  drytwin_expect_first_cause(${FILE} ${CAUSE} "${WHAT}")
  string(JSON changed GET "${json}" detection changed)
  if(NOT changed)
    message(FATAL_ERROR "no change detected ${WHAT}:\n${out}")
  endif()
endmacro()

# Writes a week of batches into WEEK from runs of the plant: each further argument is
# "FOLDER:FROM:TO", the file FROM.csv of FOLDER written as batch TO (its header renamed).
function(drytwin_compose_week WEEK)
  file(MAKE_DIRECTORY ${WEEK})
  foreach(spec ${ARGN})
    string(REPLACE ":" ";" parts "${spec}")
    list(GET parts 0 folder)
    list(GET parts 1 from)
    list(GET parts 2 to)
    file(READ ${folder}/${from}.csv text)
    string(REPLACE "# batch: ${from}" "# batch: ${to}" text "${text}")
    file(WRITE ${WEEK}/${to}.csv "${text}")
  endforeach()
endfunction()
