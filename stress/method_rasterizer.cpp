// The library's four fill methods as stress rasterizers: fill_polygon straight into the canvas,
// with one FillScratch reused across triangles as a renderer would.
#include "src/scanline_fill.hpp"
#include "stress/rasterizer.hpp"

namespace scantrace::stress {
namespace {

class MethodRasterizer final : public Rasterizer {
 public:
  explicit MethodRasterizer(Method m) : method_(m) {}

  std::string name() const override { return to_string(method_); }
  FillRule rule() const override { return FillRule::top_left; }
  bool shades() const override { return true; }

  void draw(StressCanvas& canvas, const Triangle& t, int bits, Shading shading) override {
    FillOptions opt;
    opt.shading = shading;
    opt.fill_rule = FillRule::top_left;
    opt.subpixel_bits = bits;
    opt.method = method_;
    fill_polygon(canvas, PolygonInput{t.v, t.c, 0, std::nullopt}, opt, scratch_);
  }

 private:
  Method method_;
  FillScratch scratch_;
};

}  // namespace

std::unique_ptr<Rasterizer> make_method(Method m) {
  return std::make_unique<MethodRasterizer>(m);
}

}  // namespace scantrace::stress
