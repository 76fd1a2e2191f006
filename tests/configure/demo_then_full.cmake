# One build directory configured as the README's two commands do: first for the demo
# (scripts/build.sh --demo: SCANTRACE_TOOLS=OFF), then for everything (scripts/build.sh). The
# capability options the tools need must follow SCANTRACE_TOOLS, not keep the demo's OFF from the
# cache: the second configuration fails otherwise (cmake/scantrace_capabilities.cmake).
#   cmake -DSOURCE_DIR=... -DWORK_DIR=... -P demo_then_full.cmake
file(REMOVE_RECURSE ${WORK_DIR})
set(common -S ${SOURCE_DIR} -B ${WORK_DIR} -DCMAKE_BUILD_TYPE=Release -DSCANTRACE_BUILD_WEB=OFF
           --log-level=ERROR)
foreach(form demo full)
  if(form STREQUAL demo)
    set(flags -DSCANTRACE_BUILD_TESTS=OFF -DSCANTRACE_BUILD_BENCH=OFF -DSCANTRACE_BUILD_PYTHON=OFF
              -DSCANTRACE_TOOLS=OFF)
    set(want OFF)
  else()
    set(flags -DSCANTRACE_BUILD_TESTS=ON -DSCANTRACE_BUILD_BENCH=ON -DSCANTRACE_BUILD_PYTHON=ON
              -DSCANTRACE_TOOLS=ON)
    set(want ON)
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} ${common} ${flags} RESULT_VARIABLE rc
                  OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the ${form} configuration after the ones before failed:\n${err}")
  endif()
  load_cache(${WORK_DIR} READ_WITH_PREFIX got_ SCANTRACE_WITH_OPENCV SCANTRACE_WITH_MATIO
             SCANTRACE_WITH_IMAGE_CODECS)
  foreach(o SCANTRACE_WITH_OPENCV SCANTRACE_WITH_MATIO SCANTRACE_WITH_IMAGE_CODECS)
    if(NOT got_${o} STREQUAL want)
      message(FATAL_ERROR "after the ${form} configuration ${o} is ${got_${o}}, not ${want}")
    endif()
  endforeach()
endforeach()
message(STATUS "the demo's configuration, then the full one, in one build directory: both configure")
