#pragma once
// What the image libraries print while a submitted image decodes: libpng ("libpng warning: iCCP:
// known incorrect sRGB profile"), libjpeg ("Corrupt JPEG data: premature end of data segment")
// and OpenCV's own log write to the process's stderr, a line before scantrace's one-line error and
// in other words. Their text is captured instead and goes into scantrace's message (or one
// warning line when the image decodes all the same).
#include <string>

namespace scantrace::grade {

// Redirects file descriptor 2 to an anonymous file until text() or destruction. Not for
// concurrent use: the descriptor is the process's.
class CapturedStderr {
 public:
  CapturedStderr();
  ~CapturedStderr();
  CapturedStderr(const CapturedStderr&) = delete;
  CapturedStderr& operator=(const CapturedStderr&) = delete;

  // Restores stderr and returns what was written meanwhile, on one line ("; " between lines,
  // control characters dropped, cut to 300 characters).
  std::string text();

 private:
  void restore();
  int saved_ = -1, capture_ = -1;
};

}  // namespace scantrace::grade
