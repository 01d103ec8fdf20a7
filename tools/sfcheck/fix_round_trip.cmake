# sfcheck --fix on one file, end to end: the diff --dry-run prints, applied
# by patch to a copy, gives what --fix writes to another, and --fix on the
# fixed file changes nothing.
# Called as: cmake -DSFCHECK=... -DPATCH=... -DFILE=... -DWORK=... -P this
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/patched ${WORK}/fixed)
get_filename_component(name ${FILE} NAME)
file(COPY ${FILE} DESTINATION ${WORK}/patched)
file(COPY ${FILE} DESTINATION ${WORK}/fixed)

function(run_sfcheck folder)
  execute_process(COMMAND ${SFCHECK} -q ${ARGN} ${name} WORKING_DIRECTORY ${WORK}/${folder}
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 60)
  if(NOT status MATCHES "^[01]$")
    message(FATAL_ERROR "sfcheck ${ARGN} ${name}: exit status ${status}\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()

run_sfcheck(patched --fix --dry-run)
file(WRITE ${WORK}/fix.diff "${out}")
if(NOT out STREQUAL "")
  execute_process(COMMAND ${PATCH} --quiet -p1 -i ../fix.diff WORKING_DIRECTORY ${WORK}/patched
                  RESULT_VARIABLE status OUTPUT_VARIABLE patched ERROR_VARIABLE patched)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "patch refused the diff:\n${patched}\n--- the diff\n${out}")
  endif()
endif()
run_sfcheck(fixed --fix)
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORK}/patched/${name}
                        ${WORK}/fixed/${name} RESULT_VARIABLE differ)
if(differ)
  message(FATAL_ERROR "the patched file differs from what --fix wrote\n--- the diff\n${out}")
endif()
run_sfcheck(fixed --fix --dry-run)
if(NOT out STREQUAL "")
  message(FATAL_ERROR "--fix left fixes to apply:\n${out}")
endif()
file(REMOVE_RECURSE ${WORK})
