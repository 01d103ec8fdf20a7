# sfcheck's camera-fov note and sfrender's picture agree: the image sfrender
# renders of a POV-Ray scene with no view flags is, byte for byte, the one
# it renders with the flags of sfcheck's hint; and another --fov, which the
# command line gives, changes it. Called as:
#   cmake -DSFCHECK=... -DSFRENDER=... -DSCENE=... -DWORK=... -P this
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${SFCHECK} -v ${SCENE} RESULT_VARIABLE status ERROR_VARIABLE report)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "sfcheck ${SCENE} failed:\n${report}")
endif()
if(NOT report MATCHES "hint: render with sfrender (--fov [^\n]*)\n")
  message(FATAL_ERROR "no camera-fov hint in:\n${report}")
endif()
separate_arguments(hinted UNIX_COMMAND "${CMAKE_MATCH_1}")
message(STATUS "sfcheck's hint: ${hinted}")
set(common --spp 1 --depth 1 --threads 2 --quiet)
execute_process(COMMAND ${SFRENDER} ${SCENE} -o ${WORK}/plain.ppm ${common}
                RESULT_VARIABLE plain)
execute_process(COMMAND ${SFRENDER} ${SCENE} -o ${WORK}/hinted.ppm ${common} ${hinted}
                RESULT_VARIABLE hint)
execute_process(COMMAND ${SFRENDER} ${SCENE} -o ${WORK}/other.ppm ${common} --fov 30
                RESULT_VARIABLE other)
if(NOT plain EQUAL 0 OR NOT hint EQUAL 0 OR NOT other EQUAL 0)
  message(FATAL_ERROR "sfrender failed: ${plain} ${hint} ${other}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORK}/plain.ppm ${WORK}/hinted.ppm
                RESULT_VARIABLE differ)
if(NOT differ EQUAL 0)
  message(FATAL_ERROR "sfrender's picture without flags is not the one sfcheck's hint asks for")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORK}/plain.ppm ${WORK}/other.ppm
                RESULT_VARIABLE same)
if(same EQUAL 0)
  message(FATAL_ERROR "--fov 30 did not change the picture: the flag must win over the view")
endif()
