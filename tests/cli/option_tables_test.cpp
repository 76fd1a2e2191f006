// The option tables (src/option_table.hpp) against names written out here by hand, so that a
// dropped or renamed entry fails; then every reader of a name — the command line, the trace
// header reader — accepts exactly a table's names, and every value prints back to its name.
#include <catch2/catch.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_test_support.hpp"
#include "src/option_table.hpp"
#include "src/tracer.hpp"
#include "trace/trace.hpp"

using namespace scantrace;
using scantrace::test::run_scantrace;
using scantrace::test::TempDir;
using Names = std::vector<std::string>;

namespace {

// Every name parses to a value that prints back as that name, and nothing else parses.
template <class E>
void round_trips(const Names& expected, const std::string& default_name) {
  const OptionTable<E>& t = option_table<E>();
  INFO(t.key);
  CHECK(t.names() == expected);
  CHECK(t.default_name() == default_name);
  for (const std::string& n : expected) {
    const std::optional<E> v = t.parse(n);
    REQUIRE(v);
    CHECK(t.name(*v) == n);
    CHECK_FALSE(t.parse(n + " "));
    CHECK_FALSE(t.parse(std::string(1, static_cast<char>(n[0] - 'a' + 'A')) + n.substr(1)));
  }
  CHECK_FALSE(t.parse(""));
  CHECK_FALSE(t.parse("bogus"));
}

const std::string kHeader =
    R"({"type": "header", "format": "scantrace-trace", "version": 1, "canvas": {"width": 4,)"
    R"( "height": 4}, "shading": "gouraud", "fill_rule": "top-left", "subpixel_bits": 8,)"
    R"( "level": "scanline", "generator": "test")";

// A one-line trace (a header, a footer) whose header has `key` set to `value`.
trace::Trace read_header(const std::string& key, const std::string& value) {
  std::string line = kHeader;
  const std::string quoted = "\"" + key + "\": ";
  const std::size_t at = line.find(quoted);
  if (at == std::string::npos) {
    line += ", " + quoted + "\"" + value + "\"";
  } else {
    const std::size_t begin = line.find('"', at + quoted.size()) + 1;
    line.replace(begin, line.find('"', begin) - begin, value);
  }
  std::istringstream in(line + "}\n" + R"({"type": "footer", "events": 0, "truncated": false})" +
                        "\n");
  return trace::Trace::parse(in, "t.jsonl");
}

template <class E, class Field>
void header_reads(const Field& field) {
  const OptionTable<E>& t = option_table<E>();
  INFO(t.key);
  for (const std::string& n : t.names()) {
    const trace::Trace tr = read_header(t.key, n);
    CHECK(option_name(E(field(tr.header()))) == n);
  }
  const Names n = t.names();
  CHECK_THROWS_WITH(read_header(t.key, "bogus"),
                    Catch::Contains(std::string(t.key) + " \"bogus\" is " +
                                    (n.size() == 2 ? "neither " + n[0] + " nor " + n[1]
                                                   : "not " + n[0] + ", " + n[1] + " or " + n[2])));
}

// `args` with `flag NAME` accepted for each of the table's names, and a usage error listing
// exactly them for anything else.
template <class E>
void command_line_takes(const Names& args, const std::string& flag) {
  const OptionTable<E>& t = option_table<E>();
  TempDir dir;
  INFO(flag);
  for (const std::string& n : t.names()) {
    Names a = args;
    a.insert(a.end(), {flag, n});
    const auto r = run_scantrace(dir.path(), a);
    INFO(n << ": " << r.err);
    CHECK(r.exit_code == 0);
  }
  Names a = args;
  a.insert(a.end(), {flag, "bogus"});
  const auto r = run_scantrace(dir.path(), a);
  CHECK(r.exit_code == 2);
  std::string set = "{";
  for (const std::string& n : t.names()) set += (set.size() > 1 ? "," : "") + n;
  CHECK_THAT(r.err, Catch::Contains(flag + ": bogus not in " + set + "}"));
}

}  // namespace

TEST_CASE("each option table holds the names written here, and each name round-trips",
          "[options]") {
  round_trips<Shading>({"flat", "gouraud"}, "gouraud");
  round_trips<FillRule>({"top-left", "closed"}, "top-left");
  round_trips<Method>({"exact", "float", "double", "halfspace"}, "exact");
  round_trips<WindingRule>({"even-odd", "non-zero"}, "even-odd");
  round_trips<Cull>({"none", "back", "front"}, "none");
  round_trips<Visibility>({"painter", "zbuffer"}, "painter");
  round_trips<Occlusion>({"near-to-far", "far-to-near", "auto"}, "auto");
  round_trips<TraceLevel>({"triangle", "scanline", "pixel"}, "scanline");
  CHECK(option_table<FillRule>().listed() == "top-left or closed");
  CHECK(option_table<TraceLevel>().listed(" or ", "'") == "'triangle', 'scanline' or 'pixel'");
}

TEST_CASE("a trace header is read with exactly the tables' names", "[options][trace]") {
  using trace::Header;
  header_reads<Shading>([](const Header& h) { return h.shading; });
  header_reads<FillRule>([](const Header& h) { return h.fill_rule; });
  header_reads<TraceLevel>([](const Header& h) { return h.level; });
  header_reads<WindingRule>([](const Header& h) { return *h.winding_rule; });
  header_reads<Visibility>([](const Header& h) { return h.visibility; });
  header_reads<Cull>([](const Header& h) { return h.cull; });
}

TEST_CASE("the command line takes exactly the tables' names", "[options][command]") {
  const Names triangle = {"trace", "--triangle", "1,1 9,2 4,8", "--size", "12x12", "-o", "t.jsonl"};
  command_line_takes<Shading>(triangle, "--shading");
  command_line_takes<FillRule>(triangle, "--fill-rule");
  command_line_takes<Method>(triangle, "--method");
  command_line_takes<TraceLevel>(triangle, "--level");
  command_line_takes<Cull>(triangle, "--cull");
  command_line_takes<Visibility>(triangle, "--depth");
  command_line_takes<WindingRule>(
      {"trace", "--polygon", "1,1 9,2 4,8", "--size", "12x12", "-o", "p.jsonl"}, "--winding");
}
