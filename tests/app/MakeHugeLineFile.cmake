# Writes OUT, a plant file whose second line runs on for 600 MiB (an export without line breaks, as
# a fresh user's 600 MB file was), for cli_historian_huge_line. The line is a hole of zeros
# (truncate makes the file sparse), so the file takes no disk space and is made in no time; read
# whole, as it was, it took 1.7 GB of memory before it was refused.
if(NOT OUT)
  message(FATAL_ERROR "OUT is required")
endif()
file(WRITE ${OUT} "Timestamp;HDT_TT101.PV\n")
execute_process(COMMAND truncate -s 600M ${OUT} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "truncate -s 600M ${OUT} failed: ${rc}")
endif()
