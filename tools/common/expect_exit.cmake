# Runs a tool and checks its exit status, and that standard error matches a
# pattern (ctest alone tells only zero from non-zero).
# Called as: cmake -DEXIT=N -DMATCH=regex [-DWORKDIR=dir] [-DSTDOUT=file] -P this -- PROGRAM ARGS...
# STDOUT sends standard output to that file (/dev/full: a write that fails).
set(command "")
set(seen_separator FALSE)
math(EXPR last "${CMAKE_ARGC} - 1")
foreach(i RANGE ${last})
  if(seen_separator)
    list(APPEND command "${CMAKE_ARGV${i}}")
  elseif("${CMAKE_ARGV${i}}" STREQUAL "--")
    set(seen_separator TRUE)
  endif()
endforeach()
if(NOT WORKDIR)
  set(WORKDIR .)
endif()
if(STDOUT)
  execute_process(COMMAND ${command} WORKING_DIRECTORY ${WORKDIR} RESULT_VARIABLE status
                  OUTPUT_FILE ${STDOUT} ERROR_VARIABLE err TIMEOUT 120)
else()
  execute_process(COMMAND ${command} WORKING_DIRECTORY ${WORKDIR} RESULT_VARIABLE status
                  OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
endif()
if(NOT status EQUAL EXIT)
  message(FATAL_ERROR "exit status ${status}, expected ${EXIT}\n--- stderr\n${err}")
endif()
if(NOT err MATCHES "${MATCH}")
  message(FATAL_ERROR "standard error does not match '${MATCH}'\n--- stderr\n${err}")
endif()
