// The step page of SVG frames (viz/step_page.hpp), which `scantrace` writes without OpenCV (the
// demo's build): every step's display list, as SVG, gzipped, in order, with its label.
#include <libdeflate.h>

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include "composer/course_triangle.hpp"
#include "page_test_support.hpp"
#include "viz/step_label.hpp"
#include "viz/step_page.hpp"
#include "viz/svg_frame.hpp"

using namespace scantrace;

namespace {

// gunzip, sized by the gzip trailer's length field (the frames are far below 4 GB).
std::string gunzip(const std::vector<unsigned char>& gz) {
  REQUIRE(gz.size() > 18);
  REQUIRE((gz[0] == 0x1f && gz[1] == 0x8b));
  const std::size_t n = gz[gz.size() - 4] | gz[gz.size() - 3] << 8 | gz[gz.size() - 2] << 16 |
                        static_cast<std::size_t>(gz[gz.size() - 1]) << 24;
  std::string out(n, '\0');
  const std::unique_ptr<libdeflate_decompressor, void (*)(libdeflate_decompressor*)> d(
      libdeflate_alloc_decompressor(), &libdeflate_free_decompressor);
  std::size_t got = 0;
  REQUIRE(libdeflate_gzip_decompress(d.get(), gz.data(), gz.size(), out.data(), n, &got) ==
          LIBDEFLATE_SUCCESS);
  REQUIRE(got == n);
  return out;
}

}  // namespace

TEST_CASE("the SVG step page holds every step's frame as gzipped SVG, in order, with its label",
          "[composer][html]") {
  const trace::Trace trace = test::course_triangle_trace();
  // Two sequences: the page's, and one the test walks itself, so that a page that skipped,
  // repeated or reordered steps differs.
  viz::FrameSequence page_frames(trace, {}, {640, 360}, "t.jsonl");
  viz::FrameSequence expected(trace, {}, {640, 360}, "t.jsonl");
  const std::size_t n = expected.steps().size();
  REQUIRE(n == 47);
  const auto dir = std::filesystem::temp_directory_path() / "scantrace_svg_step_page";
  std::filesystem::create_directories(dir);
  const auto out = dir / "p.html";
  viz::HtmlPlayerOptions options;
  options.source = "t.jsonl";
  // Steps 3 .. 47, as `replay --steps 3:47` would ask.
  const viz::HtmlPlayerResult r = viz::write_svg_step_page(page_frames, 2, n - 1, out, options);
  CHECK(r.steps == n - 2);
  CHECK(r.format == "svg");
  CHECK(r.bytes == std::filesystem::file_size(out));

  std::ifstream in(out);
  std::stringstream text;
  text << in.rdbuf();
  const std::string page = text.str();
  CHECK(page.find("<script src") == std::string::npos);  // no network: one self-contained file
  CHECK(page.find("http://") == std::string::npos);
  const nlohmann::json data = test::page_data(page);
  CHECK(data["gzip"] == true);
  CHECK(data["mime"] == "image/svg+xml");
  CHECK(data["extension"] == "svg");
  CHECK(data["first"] == 3);
  CHECK(data["total"] == n);
  CHECK(data["width"] == 640);
  CHECK(data["height"] == 360);
  REQUIRE(data["frames"].size() == n - 2);
  for (std::size_t i = 2; i < n; ++i) {
    INFO("step " << i + 1);
    const std::string svg = gunzip(test::unbase64(data["frames"][i - 2].get<std::string>()));
    CHECK(svg == viz::to_svg(expected.frame(i)));
    CHECK(data["labels"][i - 2] == viz::step_label(expected.plan(), expected.steps()[i]));
  }
  std::filesystem::remove_all(dir);
}
