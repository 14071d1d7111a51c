# `drytwin report --project`: the pipeline's report from a project the workbench saved, re-running
# nothing. The workbench runs every step on a small data set and saves the project; the project is
# then copied where its relative paths lead nowhere (it must find its data where they were saved),
# and the report must be written with every section. A project lacking a step's result is refused
# naming the step, and a file that is not a project is refused naming the file; both exit 3 and
# write no report. Usage: cmake -DEXE=drytwin -DWORK=dir -P this file
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
# The saved project with some of its keys set (KEY VALUE ... as JSON values), written to DEST.
function(write_project dest)
  file(READ ${WORK}/saved/line.dtproj project)
  set(pairs ${ARGN})
  while(pairs)
    list(POP_FRONT pairs key value)
    string(JSON project SET "${project}" ${key} "${value}")
  endwhile()
  file(WRITE ${dest} "${project}")
endfunction()

# `report --project PROJECT` refused with exit 3, its message matching PATTERN, and no report in
# the folder it was given; WHAT names the case in a failure.
function(expect_refused project pattern what)
  execute_process(COMMAND ${EXE} report --project ${project} --out ${WORK}/refused-report
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 3 OR NOT err MATCHES "${pattern}")
    message(FATAL_ERROR "${what}: exit ${rc}, not refused as such:\n${out}\n${err}")
  endif()
  if(EXISTS ${WORK}/refused-report/report.html)
    message(FATAL_ERROR "${what}: a report was written")
  endif()
endfunction()

function(run expect_rc)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL expect_rc)
    message(FATAL_ERROR "${ARGN}: exit ${rc}, expected ${expect_rc}\n${out}\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
  set(err "${err}" PARENT_SCOPE)
endfunction()

run(0 ${EXE} generate --seed 3 --batches 2 --samples 900 --out ${WORK}/data)
run(0 ${CMAKE_COMMAND} -E env QT_QPA_PLATFORM=offscreen ${EXE} --data ${WORK}/data
    --run calibrate,train,evaluate,ablation,discover,mpc --save-project ${WORK}/saved/line.dtproj
    --screenshot ${WORK}/window.png)
file(COPY ${WORK}/saved/ DESTINATION ${WORK}/mailed/away/project)

run(0 ${EXE} report --project ${WORK}/mailed/away/project/line.dtproj --out ${WORK}/report)
foreach(f report.html report.pdf)
  if(NOT EXISTS ${WORK}/report/${f})
    message(FATAL_ERROR "no ${f} written:\n${out}\n${err}")
  endif()
endforeach()
file(READ ${WORK}/report/report.html html)
foreach(section "Calibration" "Held-out accuracy" "Ablation (paper Table 3)" "Discovery"
        "Closed-loop MPC (paper Table 2)" "drytwin report --project")
  string(FIND "${html}" "${section}" at)
  if(at LESS 0)
    message(FATAL_ERROR "the report lacks '${section}'")
  endif()
endforeach()

# A nightly job writes into the same folder again: replaced, not refused.
run(0 ${EXE} report --project ${WORK}/mailed/away/project/line.dtproj --out ${WORK}/report)
string(FIND "${html}" "re-draws results made earlier" at)
if(at LESS 0)
  message(FATAL_ERROR "the report does not say it re-draws the project's results")
endif()

# The project pointed at other data (two batches of 600 s): refused, naming then and now.
run(0 ${EXE} generate --seed 4 --batches 2 --samples 600 --out ${WORK}/other-data)
write_project(${WORK}/pointed/line.dtproj data_path "\"../other-data\"" data_path_absolute "\"\""
              results_path_absolute "\"${WORK}/saved/line.dtproj.results.json\"")
expect_refused(${WORK}/pointed/line.dtproj
  "its data at .*other-data are not those its results were made on .batches and rows then: B01:900 B02:900; now: B01:600 B02:600"
  "a report on other data than the results'")

# The same batches and rows with one reading edited in place (a cleaned spike, a corrected
# value): refused too, saying that the values changed.
file(COPY ${WORK}/data/ DESTINATION ${WORK}/edited-data)
file(READ ${WORK}/edited-data/B01.csv batch)
string(REGEX REPLACE "\n(5,[^\n]*),[0-9.]+\n" "\n\\1,60.5\n" edited "${batch}")
if(edited STREQUAL batch)
  message(FATAL_ERROR "the test could not edit row 5 of B01.csv")
endif()
file(WRITE ${WORK}/edited-data/B01.csv "${edited}")
write_project(${WORK}/edited/line.dtproj data_path "\"../edited-data\"" data_path_absolute "\"\""
              results_path_absolute "\"${WORK}/saved/line.dtproj.results.json\"")
expect_refused(${WORK}/edited/line.dtproj
  "the same batches and rows .B01:900 B02:900. hold other values than when the results were made"
  "a report on data edited in place")

# The data moved to an archive: named with --data, the report is written; without it, refused.
file(COPY ${WORK}/data/ DESTINATION ${WORK}/archive/data)
write_project(${WORK}/archived/line.dtproj data_path "\"../nowhere\"" data_path_absolute "\"${WORK}/gone\""
              results_path_absolute "\"${WORK}/saved/line.dtproj.results.json\"")
expect_refused(${WORK}/archived/line.dtproj "its data set is not where the project says.*give --data"
  "moved data without --data")
run(0 ${EXE} report --project ${WORK}/archived/line.dtproj --data ${WORK}/archive/data --out ${WORK}/archived-report)

# The same project without its what-if run: refused, naming the step, no report.
file(READ ${WORK}/saved/line.dtproj.results.json results)
string(JSON results REMOVE "${results}" mpc)
file(WRITE ${WORK}/partial/line.dtproj.results.json "${results}")
write_project(${WORK}/partial/line.dtproj results_path "\"line.dtproj.results.json\"" results_path_absolute "\"\"")
expect_refused(${WORK}/partial/line.dtproj "line.dtproj: the report needs every step's result; still to run: mpc"
  "a project without its what-if run")
expect_refused(${WORK}/data/B01.csv "B01.csv: not a DryTwin project" "a batch file given as a project")
message(STATUS "report from a moved project: every section; a missing step and a non-project refused")
