#include "grade/jpeg_header.hpp"

#include <csetjmp>
#include <cstdio>

#include <jpeglib.h>

namespace scantrace::grade {
namespace {

// libjpeg reports a fatal error through error_exit, which must not return: it jumps back to
// read_header's setjmp. Only trivially destructible objects live in that frame, so the jump
// skips no destructor.
struct ErrorManager {
  jpeg_error_mgr base;
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
};

extern "C" void on_error(j_common_ptr info) {
  auto* errors = reinterpret_cast<ErrorManager*>(info->err);
  (*info->err->format_message)(info, errors->message);
  std::longjmp(errors->jump, 1);
}

// Warnings are not printed (stderr is the command's): the header read only wants the size.
extern "C" void on_message(j_common_ptr) {}

// 0 on success; 1 with `errors.message` set.
int read_header(const unsigned char* data, unsigned long size, ErrorManager& errors,
                jpeg_decompress_struct& info) {
  info.err = jpeg_std_error(&errors.base);
  errors.base.error_exit = on_error;
  errors.base.output_message = on_message;
  errors.message[0] = '\0';
  if (setjmp(errors.jump)) {
    jpeg_destroy_decompress(&info);
    return 1;
  }
  jpeg_create_decompress(&info);
  jpeg_mem_src(&info, data, size);
  jpeg_read_header(&info, TRUE);
  return 0;
}

}  // namespace

JpegHeader read_jpeg_header(std::string_view bytes) {
  JpegHeader out;
  ErrorManager errors{};
  jpeg_decompress_struct info{};
  if (read_header(reinterpret_cast<const unsigned char*>(bytes.data()),
                  static_cast<unsigned long>(bytes.size()), errors, info) != 0) {
    out.problem = errors.message;
    return out;
  }
  out.ok = true;
  out.width = info.image_width, out.height = info.image_height;
  jpeg_destroy_decompress(&info);
  return out;
}

}  // namespace scantrace::grade
