# The mistake catalogue embedded into the C++ (grade/mistake_catalogue.hpp): the Python grader's
# python/scantrace/grade/mistakes.json, where the package and `pip install .` find it, written into
# a generated source as a string at configure time; a change to the file reconfigures. Used by
# grade/CMakeLists.txt and web/CMakeLists.txt (the WebAssembly build lists grade/'s sources).
#   scantrace_mistake_catalogue_source(VAR): VAR = the generated .cpp (in the current binary dir)
function(scantrace_mistake_catalogue_source out)
  set(json ${PROJECT_SOURCE_DIR}/python/scantrace/grade/mistakes.json)
  file(READ ${json} SCANTRACE_MISTAKES_JSON)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${json})
  set(cpp ${CMAKE_CURRENT_BINARY_DIR}/mistake_catalogue_data.cpp)
  configure_file(${PROJECT_SOURCE_DIR}/grade/mistake_catalogue_data.cpp.in ${cpp} @ONLY)
  set(${out} ${cpp} PARENT_SCOPE)
endfunction()
