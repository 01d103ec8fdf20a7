cmake_minimum_required(VERSION 3.25)
# Renders one scene with sfrender, as a user runs it, and checks the image it
# writes: a binary PPM of exactly WIDTHxHEIGHT pixels, or a PNG (written
# through the OpenImageIO module that sfrender loads). The tool, not the
# picture, is under test here: the renderer's accuracy has its own tests.
# Called as: cmake -DSFRENDER=... [-DSCENE=...] -DOUTPUT=... -DWIDTH=... -DHEIGHT=... -P this
# LAUNCHER (optional, a ;-list) runs sfrender, e.g. under valgrind, which is
# some fifty times slower: the time limit grows with it.
set(timeout 60)
if(LAUNCHER)
  set(timeout 600)
endif()
get_filename_component(folder ${OUTPUT} DIRECTORY)
file(MAKE_DIRECTORY ${folder})
file(REMOVE ${OUTPUT})
execute_process(
  COMMAND ${LAUNCHER} ${SFRENDER} ${SCENE} -o ${OUTPUT} --width ${WIDTH} --height ${HEIGHT}
          --spp 2 --threads 2 --quiet
  RESULT_VARIABLE status
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err
  TIMEOUT ${timeout})
if(NOT status EQUAL 0 OR NOT err STREQUAL "")
  message(FATAL_ERROR "sfrender ${SCENE} -o ${OUTPUT} exited with ${status}\n${out}${err}")
endif()
if(NOT EXISTS ${OUTPUT})
  message(FATAL_ERROR "sfrender wrote no ${OUTPUT}")
endif()
file(SIZE ${OUTPUT} size)
if(OUTPUT MATCHES "\\.ppm$")
  set(header "P6\n${WIDTH} ${HEIGHT}\n255\n")
  file(READ ${OUTPUT} start LIMIT 32)
  string(FIND "${start}" "${header}" at)
  string(LENGTH "${header}" header_size)
  math(EXPR want_size "${header_size} + ${WIDTH} * ${HEIGHT} * 3")
  if(NOT at EQUAL 0 OR NOT size EQUAL want_size)
    message(FATAL_ERROR "${OUTPUT}: ${size} bytes, expected a ${WIDTH}x${HEIGHT} P6 of ${want_size}")
  endif()
elseif(OUTPUT MATCHES "\\.png$")
  # The PNG signature, then the IHDR chunk with the width and height.
  file(READ ${OUTPUT} start LIMIT 24 HEX)
  if(NOT start MATCHES "^89504e470d0a1a0a0000000d49484452")
    message(FATAL_ERROR "${OUTPUT} is no PNG: ${start}")
  endif()
  string(SUBSTRING "${start}" 32 8 width_hex)
  string(SUBSTRING "${start}" 40 8 height_hex)
  math(EXPR got_width "0x${width_hex}")
  math(EXPR got_height "0x${height_hex}")
  if(NOT got_width EQUAL WIDTH OR NOT got_height EQUAL HEIGHT)
    message(FATAL_ERROR "${OUTPUT} is ${got_width}x${got_height}, expected ${WIDTH}x${HEIGHT}")
  endif()
else()
  message(FATAL_ERROR "check_render.cmake knows no format for ${OUTPUT}")
endif()
