# The installed package, as a user gets it (cmake -P; tests/CMakeLists.txt passes the variables):
#   1. `cmake --install BUILD_DIR --prefix WORK_DIR/prefix`;
#   2. every installed header includes only installed headers, the standard library and the
#      libraries the package config finds (nlohmann, spdlog/fmt, OpenCV), nothing of the build;
#   3. consumer/ is configured against the prefix alone (all components; "core" alone; a version
#      the package must refuse), built and run: render_core and trace_scanline check their
#      results against hand-derived values;
#   4. the installed `scantrace --version`, the package version and the trace's generator agree.
foreach(var BUILD_DIR WORK_DIR SOURCE_DIR VERSION CXX_COMPILER)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_install_test.cmake: -D${var}=... is required")
  endif()
endforeach()

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT status EQUAL 0)
    string(REPLACE ";" " " command "${ARGN}")
    message(FATAL_ERROR "failed (${status}): ${command}\n${out}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})

# 2. Includes of the installed headers.
set(include_root ${prefix}/include)
file(GLOB_RECURSE headers ${include_root}/scantrace/*.hpp)
list(LENGTH headers header_count)
if(header_count LESS 20)
  message(FATAL_ERROR "only ${header_count} headers installed under ${include_root}/scantrace")
endif()
foreach(header IN LISTS headers)
  file(STRINGS ${header} lines REGEX "^[ \t]*#[ \t]*include")
  get_filename_component(header_dir ${header} DIRECTORY)
  foreach(line IN LISTS lines)
    if(line MATCHES "\"([^\"]+)\"")
      # The compiler's search for "x": the including header's directory, then the include path
      # the installed targets give (P/include/scantrace, P/include).
      set(name ${CMAKE_MATCH_1})
      if(NOT EXISTS ${header_dir}/${name} AND NOT EXISTS ${include_root}/scantrace/${name}
         AND NOT EXISTS ${include_root}/${name})
        message(FATAL_ERROR "${header}: includes \"${name}\", which is not installed")
      endif()
    elseif(line MATCHES "<([^>]+)>")
      set(name ${CMAKE_MATCH_1})
      # Standard headers have no directory and no extension; the others must be the package's
      # declared dependencies.
      if(NOT name MATCHES "^[a-z_0-9]+$" AND NOT name MATCHES "^(nlohmann|spdlog|opencv2)/"
         AND NOT name MATCHES "^scantrace/")
        message(FATAL_ERROR "${header}: includes <${name}>, which the package does not provide")
      endif()
    endif()
  endforeach()
  file(READ ${header} text)
  string(FIND "${text}" "${SOURCE_DIR}" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "${header}: mentions the source tree ${SOURCE_DIR}")
  endif()
endforeach()
file(GLOB_RECURSE package_files ${prefix}/*.cmake)
foreach(file IN LISTS package_files)
  file(READ ${file} text)
  foreach(tree ${SOURCE_DIR} ${BUILD_DIR})
    string(FIND "${text}" "${tree}" at)
    if(NOT at EQUAL -1)
      message(FATAL_ERROR "${file}: refers to ${tree}; an installed package must not")
    endif()
  endforeach()
endforeach()
message(STATUS "${header_count} installed headers include only installed or dependency headers")

# 3. The consumer, configured against the prefix alone (the same compiler and flags, so that an
# ASan build's libraries link).
set(configure_args -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
                   "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}" "-DCMAKE_EXE_LINKER_FLAGS=${LINKER_FLAGS}"
                   -DCMAKE_BUILD_TYPE=${BUILD_TYPE})
if(LAUNCHER)
  list(APPEND configure_args -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()
set(consumer ${SOURCE_DIR}/tests/install/consumer)

# A version the package must refuse (0.x: another minor version is another API).
execute_process(COMMAND ${CMAKE_COMMAND} -S ${consumer} -B ${WORK_DIR}/refused
                        ${configure_args} -DSCANTRACE_WANT_VERSION=0.3
                RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE out)
if(status EQUAL 0 OR NOT out MATCHES "0\\.3")
  message(FATAL_ERROR "find_package(scantrace 0.3) was not refused:\n${out}")
endif()

# scantrace::core alone: its targets must not ask for anything but Threads.
run(${CMAKE_COMMAND} -S ${consumer} -B ${WORK_DIR}/core-only ${configure_args}
    -DSCANTRACE_COMPONENTS=core)
run(${CMAKE_COMMAND} --build ${WORK_DIR}/core-only --target render_core)
file(READ ${prefix}/lib/cmake/scantrace/scantrace-core-targets.cmake core_targets)
if(core_targets MATCHES "INTERFACE_LINK_LIBRARIES \"([^\"]*)\"")
  if(NOT CMAKE_MATCH_1 STREQUAL "Threads::Threads")
    message(FATAL_ERROR "scantrace::core links ${CMAKE_MATCH_1}, expected Threads::Threads only")
  endif()
endif()

run(${CMAKE_COMMAND} -S ${consumer} -B ${WORK_DIR}/consumer ${configure_args})
if(NOT last_output MATCHES "scantrace package version: ([0-9.]+)")
  message(FATAL_ERROR "the consumer did not report the package version:\n${last_output}")
endif()
set(package_version ${CMAKE_MATCH_1})
run(${CMAKE_COMMAND} --build ${WORK_DIR}/consumer)
run(${WORK_DIR}/consumer/render_core)
message(STATUS "${last_output}")
run(${WORK_DIR}/consumer/trace_scanline)
message(STATUS "${last_output}")

# 4. One version everywhere (trace_scanline checked the generator against the package version).
run(${prefix}/bin/scantrace --version)
string(STRIP "${last_output}" command_version)
if(NOT package_version STREQUAL VERSION OR NOT command_version STREQUAL "scantrace ${VERSION}")
  message(FATAL_ERROR "versions disagree: project ${VERSION}, package ${package_version}, "
                      "installed command \"${command_version}\"")
endif()
message(STATUS "project, package, scantrace --version and trace generator: ${VERSION}")
