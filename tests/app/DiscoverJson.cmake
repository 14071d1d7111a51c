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
