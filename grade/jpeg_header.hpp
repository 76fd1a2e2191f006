#pragma once
// The frame size of a JPEG as libjpeg itself reads it (jpeg_read_header), the library OpenCV
// decodes with. A separate marker walker disagreed with it: a 65 KB file whose first marker (TEM,
// FF01) carried a false length sent the walker to a 1x1 frame after EOI, while libjpeg decoded the
// real 12000x12000 frame (3.39 GB under a 500 MB budget). The size checked is now the decoder's.
#include <cstdint>
#include <string>
#include <string_view>

namespace scantrace::grade {

struct JpegHeader {
  bool ok = false;
  std::int64_t width = 0, height = 0;
  std::string problem;  // libjpeg's message when !ok
};

// Reads the header of the JPEG in `bytes` (nothing is decoded, nothing large allocated).
JpegHeader read_jpeg_header(std::string_view bytes);

}  // namespace scantrace::grade
