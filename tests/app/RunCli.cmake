# Runs drytwin with ARGS; checks the exit code and that stderr+stdout contain EXPECT_STDERR.
separate_arguments(args UNIX_COMMAND "${ARGS}")
execute_process(COMMAND ${EXE} ${args} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc STREQUAL "${EXPECT_RC}")
  message(FATAL_ERROR "exit code ${rc}, expected ${EXPECT_RC}\nstdout:\n${out}\nstderr:\n${err}")
endif()
if(EXPECT_STDERR AND NOT "${out}${err}" MATCHES "${EXPECT_STDERR}")
  message(FATAL_ERROR "output lacks '${EXPECT_STDERR}'\nstdout:\n${out}\nstderr:\n${err}")
endif()
