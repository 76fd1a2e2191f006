// tinyobjloader's implementation for the WebAssembly build: natively it comes from Debian's
// compiled library (tinyobjloader_double); here its header is compiled with the same
// TINYOBJLOADER_USE_DOUBLE (web/CMakeLists.txt) that io/obj_loader.cpp is compiled with.
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
