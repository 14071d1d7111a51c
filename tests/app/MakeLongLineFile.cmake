# Writes OUT, a plant file whose second line is 2 MiB of digits (an export without line breaks),
# for cli_historian_long_line: the file is made at test time rather than kept in the repository.
if(NOT OUT)
  message(FATAL_ERROR "OUT is required")
endif()
string(REPEAT "1234567890;" 190651 line)
file(WRITE ${OUT} "Timestamp;HDT_TT101.PV\n${line}\n")
