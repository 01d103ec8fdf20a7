# Converts one testdata file to POV-Ray with sfconvert and compares what it
# prints with the expected diagnostics beside the file (NAME.expect), or with
# nothing; then converts the .pov back to a scene file, which must be the
# bytes that converting the file straight to a scene file gives.
# Called as: cmake -DSFCONVERT=... -DDIR=... -DNAME=... -DWORK=... -P this
# LAUNCHER (optional, a ;-list) runs sfconvert, e.g. under valgrind, which is
# some fifty times slower: the time limit grows with it.
set(timeout 20)
if(LAUNCHER)
  set(timeout 600)
endif()
file(MAKE_DIRECTORY ${WORK})
# -v: the expected diagnostics hold the notes too.
execute_process(
  COMMAND ${LAUNCHER} ${SFCONVERT} -v --format short ${NAME} ${WORK}/${NAME}.pov
  WORKING_DIRECTORY ${DIR}
  RESULT_VARIABLE status
  ERROR_VARIABLE err
  TIMEOUT ${timeout})
# sfconvert's own lines (what -v tells, what it wrote) left out, the rest
# are diagnostics.
string(REGEX REPLACE "\nsfconvert: [^\n]*" "" err "\n${err}")
string(REGEX REPLACE "^\n" "" err "${err}")
set(expected "")
if(EXISTS ${DIR}/${NAME}.expect)
  file(READ ${DIR}/${NAME}.expect expected)
endif()
if(NOT err STREQUAL expected)
  message(FATAL_ERROR "diagnostics differ for ${NAME}\n--- expected\n${expected}--- got\n${err}")
endif()
if(NOT status EQUAL 0)
  message(FATAL_ERROR "sfconvert ${NAME} exited with ${status}")
endif()
foreach(step IN ITEMS "${DIR}/${NAME};direct" "${WORK}/${NAME}.pov;back")
  list(GET step 0 from)
  list(GET step 1 to)
  execute_process(COMMAND ${LAUNCHER} ${SFCONVERT} ${from} ${WORK}/${NAME}.${to}.sf
                  RESULT_VARIABLE status ERROR_VARIABLE step_err TIMEOUT ${timeout})
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "sfconvert ${from} to a scene file exited with ${status}\n${step_err}")
  endif()
endforeach()
file(READ ${WORK}/${NAME}.direct.sf direct)
file(READ ${WORK}/${NAME}.back.sf back)
if(NOT direct STREQUAL back)
  message(FATAL_ERROR "${NAME}: the scene file from the .pov differs\n--- direct\n${direct}--- back\n${back}")
endif()
