# libscene's sources: the files of the folders by role (the core model, text
# utilities, one folder per format, and the registry here), each folder's
# tests (NAME_test.cpp) left out. Adding a format adds a folder, which is
# found here, and a row to the registry. Included by this folder's
# CMakeLists.txt and by the web build's (web/wasm/).
file(GLOB_RECURSE scene_sources CONFIGURE_DEPENDS
     ${CMAKE_CURRENT_LIST_DIR}/*.cpp)
list(FILTER scene_sources EXCLUDE REGEX "_test[.]cpp$")
