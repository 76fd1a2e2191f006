# The WebAssembly build's third-party libraries (the top-level CMakeLists.txt includes this when
# the toolchain is emscripten's): the header-only ones from the system (/usr/include), as imported
# targets of the names the native build's find_package gives, so that the library folders link
# the same names in both builds. Only their own directories are put on the include path, never
# /usr/include itself, whose glibc headers would shadow emscripten's libc.
set(web_include ${CMAKE_BINARY_DIR}/include)
file(MAKE_DIRECTORY ${web_include})
foreach(dep nlohmann spdlog fmt hwy tiny_obj_loader.h)
  if(NOT EXISTS /usr/include/${dep})
    message(FATAL_ERROR "web build: /usr/include/${dep} is missing (bash scripts/deps.sh)")
  endif()
  file(CREATE_LINK /usr/include/${dep} ${web_include}/${dep} SYMBOLIC)
endforeach()

foreach(target nlohmann_json::nlohmann_json spdlog::spdlog hwy::hwy)
  add_library(${target} INTERFACE IMPORTED)
  set_target_properties(${target} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES ${web_include})
endforeach()
# tinyobjloader's implementation compiled here (natively it is Debian's library), with the same
# TINYOBJLOADER_USE_DOUBLE that io/obj_loader.cpp is compiled with.
add_library(web_tinyobjloader STATIC ${CMAKE_CURRENT_LIST_DIR}/tinyobj_implementation.cpp)
target_include_directories(web_tinyobjloader SYSTEM PUBLIC ${web_include})
target_compile_definitions(web_tinyobjloader PUBLIC TINYOBJLOADER_USE_DOUBLE)
add_library(tinyobjloader::tinyobjloader_double ALIAS web_tinyobjloader)

# -fwasm-exceptions, in every source: the readers report bad input by throwing InputError
# (emscripten's default turns a throw into an abort). WebAssembly's own exceptions run in Node 17+
# and every current browser, and cost nothing until thrown, unlike the JavaScript-emulated ones.
add_compile_options(-fwasm-exceptions)
# fmt header-only in every source (spdlog's, and any direct use): Debian's libfmt is the host's.
add_compile_definitions(FMT_HEADER_ONLY)
add_link_options(-fwasm-exceptions)
