// The HTML player (viz/html_player.hpp) and the random access of the replayer behind it and
// behind `scantrace step`: the page embeds exactly the replayer's frames, and a frame asked for
// out of order is the frame of an in-order replay.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "cli/cli_test_support.hpp"
#include "page_test_support.hpp"
#include "viz/html_player.hpp"
#include "viz/replay.hpp"
#include "viz/replayer.hpp"
#include "viz_test_support.hpp"

using namespace scantrace;
using test::page_data;
using test::unbase64;

namespace {

bool same(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && a.type() == b.type() && cv::norm(a, b, cv::NORM_INF) == 0;
}

}  // namespace

TEST_CASE("base64 matches the RFC 4648 test vectors", "[viz][html]") {
  auto b64 = [](const std::string& s) {
    return viz::base64(std::vector<unsigned char>(s.begin(), s.end()));
  };
  CHECK(b64("") == "");
  CHECK(b64("f") == "Zg==");
  CHECK(b64("fo") == "Zm8=");
  CHECK(b64("foo") == "Zm9v");
  CHECK(b64("foob") == "Zm9vYg==");
  CHECK(b64("fooba") == "Zm9vYmE=");
  CHECK(b64("foobar") == "Zm9vYmFy");
  const std::vector<unsigned char> all = [] {
    std::vector<unsigned char> v;
    for (int i = 0; i < 256; ++i) v.push_back(static_cast<unsigned char>(i));
    return v;
  }();
  CHECK(unbase64(viz::base64(all)) == all);
}

TEST_CASE("the replayer gives the same frame in any order", "[viz][html]") {
  const trace::Trace t = test::record(test::medium_triangle());
  viz::StepOptions options;
  options.rows_per_step = 1;
  viz::Replayer in_order(t, options, {640, 360}, "t");
  std::vector<cv::Mat> frames;
  for (std::size_t i = 0; i < in_order.steps().size(); ++i) frames.push_back(in_order.frame(i));
  REQUIRE(frames.size() > 25);
  viz::Replayer any_order(t, options, {640, 360}, "t");
  // Forward, far back, back by one, to the end, to the start: checkpoints and replays from them.
  for (std::size_t i : {20u, 3u, 25u, 24u, 9u, 30u, 0u, 17u, 16u, 15u}) {
    INFO("step " << i + 1);
    CHECK(same(any_order.frame(i), frames[i]));
  }
}

TEST_CASE("the page embeds exactly the replayer's frames", "[viz][html]") {
  test::TempDir dir;
  const trace::Trace t = test::record(test::small_triangle());
  viz::Replayer replayer(t, {}, {640, 360}, "small.jsonl");
  const std::size_t n = replayer.steps().size();
  viz::HtmlPlayerOptions options;
  options.source = "small </script> & \"quoted\".jsonl";
  const viz::HtmlPlayerResult r =
      viz::write_html_player(replayer, 1, n - 1, dir / "p.html", options);
  CHECK(r.steps == n - 1);
  CHECK(r.format == "webp");
  const std::string page = test::read_text(dir / "p.html");
  CHECK(r.bytes == page.size());
  // Self-contained: nothing fetched from elsewhere; the source name cannot end the script.
  CHECK(page.find("http://") == std::string::npos);
  CHECK(page.find("https://") == std::string::npos);
  CHECK(page.find("small </script>") == std::string::npos);
  CHECK(
      page.find("<title>scantrace: small &lt;/script&gt; &amp; &quot;quoted&quot;.jsonl</title>") !=
      std::string::npos);
  const nlohmann::json data = page_data(page);
  CHECK(data["source"] == options.source);
  CHECK(data["first"] == 2);  // steps 2..n, numbered as in the replay
  CHECK(data["total"] == n);
  REQUIRE(data["frames"].size() == n - 1);
  REQUIRE(data["labels"].size() == n - 1);
  viz::Replayer reference(t, {}, {640, 360}, "small.jsonl");
  for (std::size_t i = 1; i < n; ++i) {
    INFO("step " << i + 1);
    const std::string url = data["frames"][i - 1];
    const std::string prefix = "data:image/webp;base64,";
    REQUIRE(url.rfind(prefix, 0) == 0);
    const cv::Mat decoded = cv::imdecode(unbase64(url.substr(prefix.size())), cv::IMREAD_COLOR);
    CHECK(same(decoded, reference.frame(i)));  // lossless: every digit as drawn
    const viz::Step& s = replayer.steps()[i];
    if (s.kind == viz::StepKind::scanlines)
      CHECK(data["rows"][i - 1] == nlohmann::json::array({s.first_row, s.last_row}));
    else
      CHECK(data["rows"][i - 1].is_null());
  }
  // Written atomically: nothing but the page is left.
  CHECK(test::file_names(dir.path()) == std::vector<std::string>{"p.html"});
}

TEST_CASE("an .html output is a page", "[viz][html]") {
  CHECK(viz::output_kind("t.html") == viz::OutputKind::html);
  CHECK(viz::output_kind("dir/t.htm") == viz::OutputKind::html);
  CHECK(viz::output_kind("t.mp4") == viz::OutputKind::video);
  CHECK_THROWS_AS(viz::output_kind("t.gif"), std::invalid_argument);
}
