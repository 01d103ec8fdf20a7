# Runs sfcheck on one testdata file and compares what it prints with the
# expected diagnostics beside the file (NAME.expect), or with nothing when
# there is no such file. The exit status must be 1 exactly when an error is
# expected. Called as: cmake -DSFCHECK=... -DDIR=... -DNAME=... -P this
# LAUNCHER (optional, a ;-list) runs sfcheck, e.g. under valgrind, which is
# some fifty times slower: the time limit grows with it.
set(timeout 20)
if(LAUNCHER)
  set(timeout 600)
endif()
# -v: the .expect files hold the notes too, which sfcheck prints only when
# verbose.
execute_process(
  COMMAND ${LAUNCHER} ${SFCHECK} -v ${NAME}
  WORKING_DIRECTORY ${DIR}
  RESULT_VARIABLE status
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err
  TIMEOUT ${timeout})
# The lines of sfcheck's own (what -v tells of the file, the summary) are
# left out; the rest are the diagnostics, in the text form with the source
# quoted under each (lines "   3 | ..." and "     | ^~~"), which the .expect
# files leave out: they hold the short form (sfcheck --format short), and
# the quotes have tests of their own.
string(REGEX REPLACE "\nsfcheck: [^\n]*" "" diagnostics "\n${err}")
string(REGEX REPLACE "^\n" "" diagnostics "${diagnostics}")
string(REGEX REPLACE "\n *[0-9]* [|] [^\n]*" "" diagnostics "${diagnostics}")
set(expected "")
if(EXISTS ${DIR}/${NAME}.expect)
  file(READ ${DIR}/${NAME}.expect expected)
endif()
if(NOT diagnostics STREQUAL expected)
  message(FATAL_ERROR "diagnostics differ for ${NAME}\n--- expected\n${expected}--- got\n${diagnostics}")
endif()
set(want_status 0)
if(expected MATCHES ": error: ")
  set(want_status 1)
endif()
if(NOT status EQUAL want_status)
  message(FATAL_ERROR "sfcheck ${NAME} exited with ${status}, expected ${want_status}")
endif()
