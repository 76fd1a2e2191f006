# `cmake --install build --prefix P`: the scantrace command, the libraries as the CMake package
# `scantrace` (find_package(scantrace 0.2 CONFIG REQUIRED), targets scantrace::core, ::io, ::trace,
# ::reference, ::viz), and their headers under P/include/scantrace/{src,reference,io,trace,viz}/
# (README "Installing").
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(SCANTRACE_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/scantrace)

# One export set per library, in dependency order, so that the package config can load only the
# components whose dependencies are present: a consumer of scantrace::core needs no OpenCV.
set(scantrace_components core reference io trace viz)

foreach(component IN LISTS scantrace_components)
  set(target scantrace_${component})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${component})
  # scantrace_warnings only adds -Wall -Wextra to our own sources. A static library's PRIVATE
  # links are still recorded as $<LINK_ONLY:...> for its users, and an installed package cannot
  # refer to a build-only target, so that entry is dropped (linking it does nothing anyway).
  get_target_property(links ${target} INTERFACE_LINK_LIBRARIES)
  if(links)
    list(REMOVE_ITEM links "$<LINK_ONLY:scantrace_warnings>")
    set_target_properties(${target} PROPERTIES INTERFACE_LINK_LIBRARIES "${links}")
  endif()
  install(TARGETS ${target} EXPORT scantrace-${component}-targets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development)
  install(EXPORT scantrace-${component}-targets NAMESPACE scantrace::
          DESTINATION ${SCANTRACE_INSTALL_CMAKEDIR} COMPONENT development)
endforeach()

# The PNG writer (libdeflate) that viz's write_png and the command share, and viz's two libraries
# without OpenCV (the frame composer; its SVG and canvas backends), in viz's export set.
foreach(part png viz_composer viz_export)
  set(target scantrace_${part})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${part})
  get_target_property(part_links ${target} INTERFACE_LINK_LIBRARIES)
  list(REMOVE_ITEM part_links "$<LINK_ONLY:scantrace_warnings>")
  set_target_properties(${target} PROPERTIES INTERFACE_LINK_LIBRARIES "${part_links}")
  install(TARGETS ${target} EXPORT scantrace-viz-targets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development)
endforeach()

# The headers keep the repository's layout (src/ is the core) because they include each other
# by their path from the repository root ("src/scene.hpp"): the installed targets therefore put
# both P/include (for <scantrace/trace/trace.hpp>) and P/include/scantrace on the include path
# (src/CMakeLists.txt).
foreach(dir src reference io trace viz)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${dir}/
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/scantrace/${dir} COMPONENT development
          FILES_MATCHING PATTERN "*.hpp")
endforeach()
install(FILES ${PROJECT_SOURCE_DIR}/trace/trace_schema.json
        DESTINATION ${CMAKE_INSTALL_DATADIR}/scantrace COMPONENT development)

# `scantrace` hands every command but render to `scantrace-tools` (`diff` to `scantrace-diff`),
# which it finds beside itself.
install(TARGETS scantrace scantrace_tools RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
        COMPONENT runtime)
if(TARGET scantrace_diff)
  install(TARGETS scantrace_diff RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
endif()

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/scantrace-config.cmake.in
                              ${PROJECT_BINARY_DIR}/scantrace-config.cmake
                              INSTALL_DESTINATION ${SCANTRACE_INSTALL_CMAKEDIR})
# 0.x: a minor version may change the API, so 0.2 accepts 0.2.y only.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/scantrace-config-version.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/scantrace-config.cmake
              ${PROJECT_BINARY_DIR}/scantrace-config-version.cmake
        DESTINATION ${SCANTRACE_INSTALL_CMAKEDIR} COMPONENT development)

# The same names inside this build (add_subdirectory users, tests).
foreach(component IN LISTS scantrace_components)
  add_library(scantrace::${component} ALIAS scantrace_${component})
endforeach()
