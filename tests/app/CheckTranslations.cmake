# Every user-visible string of widgets/ and app/ has a Simplified Chinese translation: lupdate on
# the sources into a copy of the .ts must leave nothing unfinished (a new or changed string would).
file(COPY ${TS} DESTINATION ${WORK})
get_filename_component(name ${TS} NAME)
execute_process(COMMAND ${LUPDATE} -no-obsolete ${SOURCES}/widgets ${SOURCES}/app -ts ${WORK}/${name}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "lupdate failed: ${out}${err}")
endif()
file(READ ${WORK}/${name} text)
string(REGEX MATCHALL "<source>[^<]*</source>[ \n]*<translation type=\"unfinished\">" missing "${text}")
list(LENGTH missing count)
if(count GREATER 0)
  message(FATAL_ERROR "${count} string(s) without a translation in ${name} (run lupdate, then translations/zh_CN.py):\n${missing}")
endif()
message(STATUS "every string translated in ${name}")
