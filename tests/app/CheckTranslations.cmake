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

# Nor may English reach the screen past tr(): a table header, an axis title, a plot legend or a
# 3D view's text written as a literal shows in English in every language. The pipeline report
# (widgets/report/) is written in English by design, like the CLI's output, and is not checked.
set(ALL_L "[^\"]*[A-Za-z][A-Za-z][A-Za-z]") # a literal with a word in it
set(patterns
    "addPlot\\((QStringLiteral\\()?\"${ALL_L}"
    "setXTitle\\((QStringLiteral\\()?\"${ALL_L}"
    "(makeResultTable|setHorizontalHeaderLabels)\\(\\{ *(QStringLiteral\\()?\"${ALL_L}"
    "add(Curve|Dots)\\([^,()]+, *(QStringLiteral\\()?\"${ALL_L}"
    "setAxisTitle\\([^,()]+, *(QStringLiteral\\(|QwtText\\()?\"${ALL_L}"
    "setEmptyText\\((QStringLiteral\\()?\"${ALL_L}"
    "(SetTitle|SetInput)\\(\"${ALL_L}")
file(GLOB_RECURSE checked ${SOURCES}/widgets/*.cpp ${SOURCES}/app/*.cpp)
list(FILTER checked EXCLUDE REGEX "/widgets/report/")
set(literal_hits "")
foreach(source IN LISTS checked)
  file(READ ${source} code)
  foreach(pattern IN LISTS patterns)
    string(REGEX MATCHALL "${pattern}" hits "${code}")
    foreach(hit IN LISTS hits)
      list(APPEND literal_hits "${source}: ${hit}")
    endforeach()
  endforeach()
endforeach()
list(LENGTH literal_hits literal_count)
if(literal_count GREATER 0)
  string(REPLACE ";" "\n" literal_hits "${literal_hits}")
  message(FATAL_ERROR "${literal_count} English literal(s) on screen outside tr() (headers, axis titles, "
                      "legends): wrap them in tr() or a display name:\n${literal_hits}")
endif()
message(STATUS "no English literal in headers, axis titles or legends")

# Nor may the engine's English reach the Chinese window (issue #72 item 11): the engine writes its
# notes and reasons in English for the command line (ARCHITECTURE.md rule 11), and the GUI words
# them (widgets/common/EngineText.h, ErrorText.h, DisplayNames.h). A reason, an error's message, a
# note or an MPC's fallback reason turned into a QString anywhere else reaches the screen as the
# engine wrote it. The wording files themselves read the engine's English back, and are not checked.
set(ENGINE_TEXT "QString::fromStdString\\([^;\n]*(\\.reason|\\.message\\(\\)|notes|[Nn]ote\\(\\)|FallbackReason|describe\\(\\)|\\.what\\(\\))")
set(wording_files "/widgets/report/|/widgets/common/ErrorText\\.cpp$|/widgets/common/DisplayNames\\.cpp$|/widgets/common/EngineText\\.cpp$")
set(engine_hits "")
foreach(source IN LISTS checked)
  if(source MATCHES "${wording_files}")
    continue()
  endif()
  file(READ ${source} code)
  string(REGEX MATCHALL "${ENGINE_TEXT}" hits "${code}")
  foreach(hit IN LISTS hits)
    list(APPEND engine_hits "${source}: ${hit}")
  endforeach()
endforeach()
list(LENGTH engine_hits engine_count)
if(engine_count GREATER 0)
  string(REPLACE ";" "\n" engine_hits "${engine_hits}")
  message(FATAL_ERROR "${engine_count} place(s) put the engine's English on screen unworded: pass it through "
                      "dataNoteText(), fallbackReasonText(), engineDetailText() (common/EngineText.h) or "
                      "errorText():\n${engine_hits}")
endif()
message(STATUS "no engine text on screen unworded")
