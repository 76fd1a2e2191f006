# The libraries' capabilities: what they may use beyond the standard library and the header-only
# libraries (nlohmann-json, spdlog, Highway, tinyobjloader). A library folder's source that needs
# one is declared with it,
#     scantrace_sources_need(SCANTRACE_WITH_MATIO mat_scene.cpp mat5_layout.cpp)
# and built only where the option is on; every other source of the folder is in one of its targets.
# scantrace_check_library_sources() holds every configuration to that, the WebAssembly build's
# (all options off) included: a new .cpp in a library folder is built there, or refused by name.
if(EMSCRIPTEN)
  # Debian's compiled libraries are for the host; emscripten can compile none of them.
  set(scantrace_host_libraries OFF)
else()
  set(scantrace_host_libraries ON)
endif()
if(SCANTRACE_TOOLS AND scantrace_host_libraries)
  set(scantrace_tools_libraries ON)
else()
  set(scantrace_tools_libraries OFF)
endif()
# The three the tools need follow SCANTRACE_TOOLS: a build directory configured first for the demo
# (SCANTRACE_TOOLS=OFF, scripts/build.sh --demo) and then for everything keeps its cache, where
# option() would leave them OFF. When SCANTRACE_TOOLS changes, they take its new default again.
if(DEFINED CACHE{SCANTRACE_CAPABILITIES_FOR_TOOLS}
   AND NOT SCANTRACE_CAPABILITIES_FOR_TOOLS STREQUAL scantrace_tools_libraries)
  foreach(o SCANTRACE_WITH_OPENCV SCANTRACE_WITH_MATIO SCANTRACE_WITH_IMAGE_CODECS)
    get_property(help CACHE ${o} PROPERTY HELPSTRING)
    set(${o} ${scantrace_tools_libraries} CACHE BOOL "${help}" FORCE)
  endforeach()
endif()
set(SCANTRACE_CAPABILITIES_FOR_TOOLS ${scantrace_tools_libraries} CACHE INTERNAL
    "the SCANTRACE_TOOLS default the tools' capability options were given")
option(SCANTRACE_WITH_OPENCV
       "OpenCV: raster frames, videos, windows, JPEG and BMP images (scantrace_viz, scantrace_grade)"
       ${scantrace_tools_libraries})
option(SCANTRACE_WITH_MATIO "matio and zlib: the 2021 course's MATLAB .mat scenes (scantrace_mat)"
       ${scantrace_tools_libraries})
option(SCANTRACE_WITH_IMAGE_CODECS
       "libpng and libjpeg: submitted image files and diff.png (scantrace_grade_files)"
       ${scantrace_tools_libraries})
option(SCANTRACE_WITH_SIMDJSON "simdjson: the scene file's fast reader (io/scene_json_fast.hpp)"
       ${scantrace_host_libraries})
option(SCANTRACE_WITH_LIBDEFLATE
       "libdeflate: compressed PNGs and gzip; off, PNGs are stored uncompressed (web/shim/libdeflate.h)"
       ${scantrace_host_libraries})
option(SCANTRACE_WITH_THREADS "threads: the core links the platform's thread library"
       ${scantrace_host_libraries})
if(SCANTRACE_TOOLS AND NOT EMSCRIPTEN
   AND NOT (SCANTRACE_WITH_OPENCV AND SCANTRACE_WITH_MATIO AND SCANTRACE_WITH_IMAGE_CODECS))
  message(FATAL_ERROR "SCANTRACE_TOOLS (scantrace-tools) needs SCANTRACE_WITH_OPENCV, "
                      "SCANTRACE_WITH_MATIO and SCANTRACE_WITH_IMAGE_CODECS")
endif()

# The folders whose sources are libraries (the command, stress and bench are executables' parts).
set(SCANTRACE_LIBRARY_FOLDERS src reference demo io trace viz grade)

# scantrace_sources_need(OPTION FILES...): FILES, of the calling folder, are built only where
# OPTION is on.
function(scantrace_sources_need option)
  if(NOT DEFINED ${option})
    message(FATAL_ERROR "scantrace_sources_need: ${option} is not a capability option")
  endif()
  foreach(f ${ARGN})
    get_filename_component(f ${f} ABSOLUTE BASE_DIR ${CMAKE_CURRENT_SOURCE_DIR})
    set_property(GLOBAL APPEND PROPERTY SCANTRACE_SOURCES_NEEDING_${option} ${f})
  endforeach()
  set_property(GLOBAL APPEND PROPERTY SCANTRACE_CAPABILITIES ${option})
endfunction()

# The sources of the targets defined in `dir`, as absolute paths.
function(scantrace_built_sources dir out)
  set(built)
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  foreach(t ${targets})
    get_target_property(type ${t} TYPE)
    if(type STREQUAL INTERFACE_LIBRARY)
      continue()
    endif()
    get_target_property(sources ${t} SOURCES)
    foreach(s ${sources})
      get_filename_component(s ${s} ABSOLUTE BASE_DIR ${dir})
      list(APPEND built ${s})
    endforeach()
  endforeach()
  set(${out} ${built} PARENT_SCOPE)
endfunction()

# Fails the configuration when a library folder's .cpp is in none of the folder's targets and is
# not declared with an option that is off here.
function(scantrace_check_library_sources)
  get_property(options GLOBAL PROPERTY SCANTRACE_CAPABILITIES)
  list(REMOVE_DUPLICATES options)
  set(refused)
  foreach(option ${options})
    if(NOT ${option})
      get_property(files GLOBAL PROPERTY SCANTRACE_SOURCES_NEEDING_${option})
      list(APPEND refused ${files})
    endif()
  endforeach()
  set(missing)
  get_property(added DIRECTORY ${PROJECT_SOURCE_DIR} PROPERTY SUBDIRECTORIES)
  foreach(folder ${SCANTRACE_LIBRARY_FOLDERS})
    set(dir ${PROJECT_SOURCE_DIR}/${folder})
    if(NOT dir IN_LIST added)  # a folder this build leaves out (grade/ in the demo's build)
      continue()
    endif()
    scantrace_built_sources(${dir} built)
    file(GLOB_RECURSE files CONFIGURE_DEPENDS ${dir}/*.cpp)
    foreach(f ${files})
      if(NOT f IN_LIST built AND NOT f IN_LIST refused)
        file(RELATIVE_PATH rel ${PROJECT_SOURCE_DIR} ${f})
        list(APPEND missing ${rel})
      endif()
    endforeach()
  endforeach()
  if(missing)
    list(JOIN missing ", " missing)
    message(FATAL_ERROR "built by no target of its folder, and needing no capability that is off "
                        "here (cmake/scantrace_capabilities.cmake): ${missing}")
  endif()
endfunction()
