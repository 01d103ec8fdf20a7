# Converts one testdata file to every output format with sfconvert, and
# holds each conversion to its expected diagnostics (NAME.FORMAT.expect
# beside the file, or nothing): where they hold an error, sfconvert must exit
# 1 and write nothing; otherwise it must exit 0, and what it wrote must read
# back. From glTF, GLB and POV-Ray the file must come back bit for bit: the
# scene or instruction file converted back is the bytes that converting the
# input straight to its own format gives.
# Called as: cmake -DSFCONVERT=... -DDIR=... -DNAME=... -DWORK=... -P this
# LAUNCHER (optional, a ;-list) runs sfconvert, e.g. under valgrind.
set(timeout 20)
if(LAUNCHER)
  set(timeout 600)
endif()
file(MAKE_DIRECTORY ${WORK})
get_filename_component(kind ${NAME} LAST_EXT)
string(SUBSTRING ${kind} 1 -1 kind)

execute_process(COMMAND ${LAUNCHER} ${SFCONVERT} ${NAME} ${WORK}/${NAME}.direct.${kind}
                WORKING_DIRECTORY ${DIR} RESULT_VARIABLE status ERROR_QUIET TIMEOUT ${timeout})
if(NOT status EQUAL 0)
  message(FATAL_ERROR "sfconvert ${NAME} to its own format exited with ${status}")
endif()
file(READ ${WORK}/${NAME}.direct.${kind} direct)

foreach(format IN ITEMS sf txt gltf glb pov)
  set(out ${WORK}/${NAME}.${format})
  file(REMOVE ${out})
  # -v: the expected diagnostics hold the notes too.
  execute_process(COMMAND ${LAUNCHER} ${SFCONVERT} -v --format short ${NAME} ${out}
                  WORKING_DIRECTORY ${DIR} RESULT_VARIABLE status ERROR_VARIABLE err
                  TIMEOUT ${timeout})
  # sfconvert's own lines (what -v tells, what it wrote) left out, the rest
  # are diagnostics.
  string(REGEX REPLACE "\nsfconvert: [^\n]*" "" err "\n${err}")
  string(REGEX REPLACE "^\n" "" err "${err}")
  set(expected "")
  if(EXISTS ${DIR}/${NAME}.${format}.expect)
    file(READ ${DIR}/${NAME}.${format}.expect expected)
  endif()
  if(NOT err STREQUAL expected)
    message(FATAL_ERROR
            "diagnostics differ for ${NAME} to .${format}\n--- expected\n${expected}--- got\n${err}")
  endif()
  if(expected MATCHES ": error: ")
    if(NOT status EQUAL 1 OR EXISTS ${out})
      message(FATAL_ERROR "${NAME} to .${format}: exit ${status}, expected 1 and no output")
    endif()
    continue()
  endif()
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "sfconvert ${NAME} to .${format} exited with ${status}")
  endif()
  set(back ${WORK}/${NAME}.${format}.back.${kind})
  execute_process(COMMAND ${LAUNCHER} ${SFCONVERT} ${out} ${back}
                  RESULT_VARIABLE status ERROR_VARIABLE back_err TIMEOUT ${timeout})
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "what sfconvert wrote to .${format} does not read back (${status})\n"
                        "${back_err}")
  endif()
  if(format MATCHES "^(gltf|glb|pov)$")
    file(READ ${back} again)
    if(NOT again STREQUAL direct)
      message(FATAL_ERROR
              "${NAME} through .${format} differs\n--- direct\n${direct}--- back\n${again}")
    endif()
  endif()
endforeach()
