# The formats of the suite, read from the one list of them,
# include/scenefile/formats.def (SCENEFILE_FORMAT(Enumerator, name, folder,
# row) lines), so that the per-format tests and fuzz targets follow the
# registry:
#   SCENEFILE_FORMAT_NAMES    the --to names, in the file's order
#   SCENEFILE_FORMAT_FOLDERS  each one's folder under libscene/formats/
file(STRINGS ${PROJECT_SOURCE_DIR}/include/scenefile/formats.def format_lines
     REGEX "^SCENEFILE_FORMAT\\(")
set(SCENEFILE_FORMAT_NAMES "")
set(SCENEFILE_FORMAT_FOLDERS "")
foreach(line ${format_lines})
  if(NOT line MATCHES "^SCENEFILE_FORMAT\\(([A-Za-z]+), *([a-z]+), *([a-z]+), *([A-Za-z]+)\\)")
    message(FATAL_ERROR "formats.def: cannot read '${line}'")
  endif()
  list(APPEND SCENEFILE_FORMAT_NAMES ${CMAKE_MATCH_2})
  list(APPEND SCENEFILE_FORMAT_FOLDERS ${CMAKE_MATCH_3})
endforeach()
if(NOT SCENEFILE_FORMAT_NAMES)
  message(FATAL_ERROR "formats.def names no format")
endif()
