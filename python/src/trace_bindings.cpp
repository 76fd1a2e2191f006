// Traces in Python: the C++ query API (trace/trace.hpp) with Python names, events as read-only
// objects whose fields are plain values (ints, floats, (x, y) and (r, g, b) tuples, lists, None),
// and the image the traced fill drew, as numpy.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <optional>
#include <variant>

#include "arrays.hpp"
#include "casters.hpp"
#include "py_trace.hpp"
#include "src/option_table.hpp"
#include "trace/record.hpp"

namespace scantrace::python {

Scene load_scene_file(const std::string& path, Shading obj_shading);

namespace {

using namespace scantrace::trace;
// The trace event's span (scantrace::Span, the fill's, is another type).
using scantrace::trace::Span;

py::object image_of(const PyTrace& t) {
  if (!t.image) return py::none();
  const RgbImage& im = *t.image;
  py::array_t<double> out({im.height(), im.width(), 3});
  double* o = out.mutable_data();
  for (const Rgb32f& p : im.pixels()) {
    *o++ = p.r;
    *o++ = p.g;
    *o++ = p.b;
  }
  return out;
}

// repr() of a value as Python shows it (floats shortest, tuples, lists of bound objects).
template <class T>
std::string rep(const T& value) {
  return py::repr(py::cast(value)).template cast<std::string>();
}

TraceLevel level_argument(const std::string& s) {
  if (const std::optional<TraceLevel> level = parse_option<TraceLevel>(s)) return *level;
  throw_value_error("level: expected " + option_table<TraceLevel>().listed(" or ", "'") +
                    ", got '" + s + "'");
}

// A count from Python: an int (not a bool, not a float) in 0 .. 2^63 - 1.
std::int64_t count_argument(py::handle value, const char* name) {
  const std::optional<py::int_> v = integer_value(value);  // numpy integers too
  if (!v)
    throw_type_error(std::string(name) + ": expected an int, got " +
                     py::str(py::type::of(value).attr("__name__")).cast<std::string>());
  int overflow = 0;
  const long long n = PyLong_AsLongLongAndOverflow(v->ptr(), &overflow);
  if (overflow || n < 0)
    throw_value_error(std::string(name) + ": expected a count in 0 .. 2^63 - 1, got " +
                      py::repr(value).cast<std::string>());
  return n;
}

// The selection of trace_scene/trace_triangle, refused as the command line refuses it
// (cli/selection_check.cpp) when it selects nothing: no face of the `faces` there are, or no row
// of a canvas `height` rows high; and rows given last before first.
TraceFilter filter_argument(const std::string& level, py::handle triangles, py::handle rows,
                            py::handle max_events, std::int64_t faces, int height) {
  TraceFilter f;
  f.level = level_argument(level);
  if (!triangles.is_none()) {
    std::string text;
    if (py::isinstance<py::str>(triangles)) {
      text = triangles.cast<std::string>();
    } else {
      const IndexArray a = index_array(triangles, "triangles", {'K'});
      if (a.size() == 0) throw_value_error("triangles: expected at least one face index");
      for (py::ssize_t i = 0; i < a.size(); ++i) {
        if (i) text += ',';
        text += std::to_string(a.data()[i]);
      }
    }
    try {
      f.triangles = IndexSet::parse(text);
    } catch (const std::invalid_argument& e) {
      throw_value_error(std::string("triangles: ") + e.what());
    }
    const auto& r = f.triangles->ranges();
    if (!r.empty() && r.front().first >= faces)
      throw_value_error("triangles: '" + text + "' selects no face: the scene has " +
                        std::to_string(faces) + " face" + (faces == 1 ? "" : "s") +
                        " (indices 0.." + std::to_string(faces - 1) + ")");
  }
  if (!rows.is_none()) {
    const IndexArray a = index_array(rows, "rows", {2});
    f.rows = RowRange{a.data()[0], a.data()[1]};
    if (f.rows->first > f.rows->last)
      throw_value_error("rows: expected (first, last) with first <= last, got (" +
                        std::to_string(f.rows->first) + ", " + std::to_string(f.rows->last) + ")");
    if (f.rows->last < 0 || f.rows->first > height - 1)
      throw_value_error("rows: (" + std::to_string(f.rows->first) + ", " +
                        std::to_string(f.rows->last) + ") selects no row of the canvas (rows 0.." +
                        std::to_string(height - 1) + ")");
  }
  if (!max_events.is_none()) f.max_events = count_argument(max_events, "max_events");
  return f;
}

// The face index a single triangle's trace calls it by (its index in a scene: a face taken out
// of the course scene keeps its number).
int face_id_argument(py::handle face) {
  const std::optional<py::int_> v = integer_value(face);
  if (!v)
    throw_type_error("face: expected an int (the face's index in its scene), got " +
                     py::str(py::type::of(face).attr("__name__")).cast<std::string>());
  int overflow = 0;
  const long long n = PyLong_AsLongLongAndOverflow(v->ptr(), &overflow);
  if (overflow || n < 0 || n > INT_MAX)
    throw_value_error("face: expected an index in 0 .. 2^31 - 1, got " +
                      py::repr(face).cast<std::string>());
  return static_cast<int>(n);
}

// The trace of triangle 0 with every event's triangle called `id` instead.
Trace renumbered(const Trace& t, int id) {
  std::vector<Event> events = t.events();
  for (Event& e : events)
    std::visit(
        [id](auto& ev) {
          if constexpr (requires { ev.triangle; }) ev.triangle = id;
        },
        e);
  return Trace::from_events(std::move(events), "memory");
}

std::string trace_repr(const PyTrace& t) {
  const Header& h = t.trace.header();
  const std::vector<int> tri = t.trace.triangles();
  std::string faces;
  for (std::size_t i = 0; i < tri.size() && i < 8; ++i)
    faces += (i ? ", " : "") + std::to_string(tri[i]);
  if (tri.size() > 8) faces += ", ...";
  return "<Trace: " + std::to_string(tri.size()) + " triangle" + (tri.size() == 1 ? "" : "s") +
         " [" + faces + "], " + std::to_string(t.trace.events().size()) + " events, level " +
         rep(option_name(h.level)) + ", " + std::to_string(h.canvas.width) + "x" +
         std::to_string(h.canvas.height) + " " + option_name(h.shading) + " " +
         option_name(h.fill_rule) +
         (t.trace.complete() ? std::string(t.trace.truncated() ? ", truncated" : "")
                             : ", incomplete (no footer)") +
         (t.image ? ", with its image" : "") + ">";
}

// The events of a trace as Python classes, read-only, each with a repr that says what it holds;
// one function per part of the trace format v1 (docs/design.md).

// The trace's first line and a triangle's first event.
void bind_header_and_triangle(py::module_& m) {
  py::class_<Header>(m, "Header", "The first line of a trace: canvas and fill settings.")
      .def_readonly("format", &Header::format)
      .def_readonly("version", &Header::version)
      .def_property_readonly(
          "canvas", [](const Header& h) { return py::make_tuple(h.canvas.width, h.canvas.height); })
      .def_property_readonly("shading", [](const Header& h) { return option_name(h.shading); })
      .def_property_readonly("fill_rule", [](const Header& h) { return option_name(h.fill_rule); })
      .def_readonly("subpixel_bits", &Header::subpixel_bits)
      .def_property_readonly("level", [](const Header& h) { return option_name(h.level); })
      .def_readonly("generator", &Header::generator)
      .def_property_readonly("visibility",
                             [](const Header& h) { return option_name(h.visibility); })
      .def("__repr__", [](const Header& h) {
        return "Header(canvas=(" + std::to_string(h.canvas.width) + ", " +
               std::to_string(h.canvas.height) + "), shading=" + rep(option_name(h.shading)) +
               ", fill_rule=" + rep(option_name(h.fill_rule)) +
               ", level=" + rep(option_name(h.level)) +
               ", visibility=" + rep(option_name(h.visibility)) +
               ", subpixel_bits=" + std::to_string(h.subpixel_bits) +
               ", generator=" + rep(h.generator) + ")";
      });
  py::class_<TriangleBegin>(m, "TriangleBegin", "A traced triangle: vertices as given and snapped.")
      .def_readonly("triangle", &TriangleBegin::triangle)
      .def_readonly("vertices", &TriangleBegin::vertices)
      .def_readonly("snapped", &TriangleBegin::snapped)
      .def_readonly("colors", &TriangleBegin::colors)
      .def_readonly("depth", &TriangleBegin::depth)
      .def_readonly("flat_color", &TriangleBegin::flat_color);
}

// A triangle's edge table: its entries and its horizontal edges.
void bind_edge_table(py::module_& m) {
  py::class_<EdgeEntry>(m, "EdgeEntry", "One non-horizontal edge of the edge table.")
      .def_readonly("edge", &EdgeEntry::edge)
      .def_readonly("from_", &EdgeEntry::from)
      .def_readonly("to", &EdgeEntry::to)
      .def_readonly("y_min", &EdgeEntry::y_min)
      .def_readonly("y_max", &EdgeEntry::y_max)
      .def_readonly("x_at_y_min", &EdgeEntry::x_at_y_min)
      .def_readonly("dx_dy", &EdgeEntry::dx_dy)
      .def_readonly("first_row", &EdgeEntry::first_row)
      .def_readonly("last_row", &EdgeEntry::last_row)
      .def("__repr__", [](const EdgeEntry& e) {
        return "EdgeEntry(edge=" + std::to_string(e.edge) +
               ", y_min=" + py::repr(py::float_(e.y_min)).cast<std::string>() +
               ", y_max=" + py::repr(py::float_(e.y_max)).cast<std::string>() +
               ", x_at_y_min=" + py::repr(py::float_(e.x_at_y_min)).cast<std::string>() +
               ", dx_dy=" + py::repr(py::float_(e.dx_dy)).cast<std::string>() + ")";
      });
  py::class_<HorizontalEntry>(m, "HorizontalEntry", "A horizontal edge, kept out of the table.")
      .def_readonly("edge", &HorizontalEntry::edge)
      .def_readonly("from_", &HorizontalEntry::from)
      .def_readonly("to", &HorizontalEntry::to)
      .def_readonly("y", &HorizontalEntry::y)
      .def_readonly("reason", &HorizontalEntry::reason)
      .def("__repr__", [](const HorizontalEntry& e) {
        return "HorizontalEntry(edge=" + std::to_string(e.edge) + ", y=" + rep(e.y) +
               ", reason=" + rep(e.reason) + ")";
      });
  py::class_<EdgeTableEvent>(m, "EdgeTable", "A triangle's edge table, sorted by first row.")
      .def_readonly("triangle", &EdgeTableEvent::triangle)
      .def_readonly("edges", &EdgeTableEvent::edges)
      .def_readonly("horizontal", &EdgeTableEvent::horizontal)
      .def("__repr__", [](const EdgeTableEvent& e) {
        return "EdgeTable(triangle=" + std::to_string(e.triangle) + ", edges=" + rep(e.edges) +
               ", horizontal=" + rep(e.horizontal) + ")";
      });
}

// One row of a triangle: the edges crossing it, the active points, the span and its colours.
void bind_scanline(py::module_& m) {
  py::class_<scantrace::trace::EdgeCrossing>(
      m, "EdgeCrossing", "Where an active edge crosses a row: its edge and exact intersection x.")
      .def_readonly("edge", &scantrace::trace::EdgeCrossing::edge)
      .def_readonly("x", &scantrace::trace::EdgeCrossing::x)
      .def("__repr__", [](const scantrace::trace::EdgeCrossing& e) {
        return "EdgeCrossing(edge=" + std::to_string(e.edge) +
               ", x=" + py::repr(py::float_(e.x)).cast<std::string>() + ")";
      });
  // Its name until the one-sweep redesign, kept so that scripts using it still run.
  m.attr("ActiveEdge") = m.attr("EdgeCrossing");
  py::class_<scantrace::trace::ActivePoint>(m, "ActivePoint",
                                            "An active point: x, its edge and interpolated colour.")
      .def_readonly("x", &scantrace::trace::ActivePoint::x)
      .def_readonly("edge", &scantrace::trace::ActivePoint::edge)
      .def_readonly("color", &scantrace::trace::ActivePoint::color)
      .def("__repr__", [](const scantrace::trace::ActivePoint& p) {
        return "ActivePoint(x=" + py::repr(py::float_(p.x)).cast<std::string>() +
               ", edge=" + std::to_string(p.edge) +
               ", color=" + py::repr(py::cast(p.color)).cast<std::string>() + ")";
      });
  py::class_<Span>(m, "Span", "The pixels filled on a row: [x_begin, x_end), clipped.")
      .def_readonly("x_begin", &Span::x_begin)
      .def_readonly("x_end", &Span::x_end)
      .def("__len__", [](const Span& s) { return s.size(); })
      .def("__contains__", [](const Span& s, std::int64_t x) { return s.contains(x); })
      .def("__repr__", [](const Span& s) {
        return "Span(x_begin=" + std::to_string(s.x_begin) + ", x_end=" + std::to_string(s.x_end) +
               ")";
      });
  py::class_<SpanColors>(m, "SpanColors", "Gouraud: colours of the first and last pixel.")
      .def_readonly("begin", &SpanColors::begin)
      .def_readonly("end", &SpanColors::end)
      .def("__repr__", [](const SpanColors& c) {
        return "SpanColors(begin=" + rep(c.begin) + ", end=" + rep(c.end) + ")";
      });
  py::class_<Scanline>(m, "Scanline", "One row of one triangle, as the fill saw it.")
      .def_readonly("triangle", &Scanline::triangle)
      .def_readonly("y", &Scanline::y)
      .def_readonly("entered", &Scanline::entered)
      .def_readonly("retired", &Scanline::retired)
      .def_readonly("active_edges", &Scanline::active_edges)
      .def_readonly("active_points", &Scanline::active_points)
      .def_readonly("span", &Scanline::span)
      .def_readonly("span_colors", &Scanline::span_colors)
      .def("__repr__", [](const Scanline& l) {
        return "Scanline(triangle=" + std::to_string(l.triangle) + ", y=" + std::to_string(l.y) +
               ", span=" + rep(l.span) + ", active_points=" + rep(l.active_points) +
               ", entered=" + rep(l.entered) + ", retired=" + rep(l.retired) +
               (l.span_colors ? ", span_colors=" + rep(*l.span_colors) : std::string()) + ")";
      });
}

// Pixel events, a triangle's end or skip, the footer.
void bind_pixel_and_end(py::module_& m) {
  py::class_<Pixel>(m, "Pixel", "A pixel event (level 'pixel').")
      .def_readonly("triangle", &Pixel::triangle)
      .def_readonly("x", &Pixel::x)
      .def_readonly("y", &Pixel::y)
      .def_readonly("color", &Pixel::color)
      .def_readonly("t", &Pixel::t);
  py::class_<TriangleEnd>(m, "TriangleEnd", "A finished triangle: rows and pixels written.")
      .def_readonly("triangle", &TriangleEnd::triangle)
      .def_readonly("rows", &TriangleEnd::rows)
      .def_readonly("pixels", &TriangleEnd::pixels);
  py::class_<TriangleSkipped>(m, "TriangleSkipped", "A triangle that filled nothing, and why.")
      .def_readonly("triangle", &TriangleSkipped::triangle)
      .def_readonly("reason", &TriangleSkipped::reason);
  py::class_<Footer>(m, "Footer", "The last line of a complete trace.")
      .def_readonly("events", &Footer::events)
      .def_readonly("truncated", &Footer::truncated);
}

// The answer of Trace.pixel_history: the writes of one pixel, in drawing order.
void bind_pixel_history(py::module_& m) {
  py::class_<PixelWrite>(m, "PixelWrite", "One write of a pixel: the triangle and the colour.")
      .def_readonly("triangle", &PixelWrite::triangle)
      .def_readonly("color", &PixelWrite::color)
      .def_readonly("from_pixel_event", &PixelWrite::from_pixel_event)
      .def("__repr__", [](const PixelWrite& w) {
        return "PixelWrite(triangle=" + std::to_string(w.triangle) +
               ", color=" + py::repr(py::cast(w.color)).cast<std::string>() + ")";
      });
  py::class_<PixelHistory>(m, "PixelHistory",
                           "Who wrote a pixel, in drawing order (empty when no triangle did).")
      .def_readonly("writes", &PixelHistory::writes)
      .def("__len__", [](const PixelHistory& h) { return h.writes.size(); })
      .def("empty", &PixelHistory::empty)
      .def(
          "final",
          [](const PixelHistory& h) -> std::optional<PixelWrite> {
            if (h.empty()) return std::nullopt;
            return h.final();
          },
          "The visible (last) write, or None when no triangle wrote the pixel (it shows the "
          "background).")
      .def("__repr__", [](const PixelHistory& h) {
        if (h.empty()) return std::string("PixelHistory(empty: no triangle wrote this pixel)");
        return "PixelHistory(" + std::to_string(h.writes.size()) + " write" +
               (h.writes.size() == 1 ? "" : "s") + ", final=" + rep(h.final()) +
               ", writes=" + rep(h.writes) + ")";
      });
}

void bind_events(py::module_& m) {
  bind_header_and_triangle(m);
  bind_edge_table(m);
  bind_scanline(m);
  bind_pixel_and_end(m);
  bind_pixel_history(m);
}

// Trace.scanline(i, y) for a row the trace does not hold: why, in the fill's terms, where a bare
// IndexError would leave the reader guessing (the row of a triangle's bottom vertex, say).
Scanline scanline_or_why_not(const PyTrace& t, int i, std::int64_t y) {
  if (const Scanline* s = t.trace.find_scanline(i, y)) return *s;
  const std::string row = "row " + std::to_string(y);
  const TriangleBegin* begin = t.trace.has_triangle(i) ? t.trace.find_triangle_begin(i) : nullptr;
  if (t.trace.has_triangle(i))
    if (const auto skipped = t.trace.skipped(i))
      throw py::index_error(row + " is not filled: triangle " + std::to_string(i) +
                            " is skipped by the fill (" + skipped->reason + ")");
  if (!begin) {
    std::string held;
    for (int k : t.trace.triangles()) held += (held.empty() ? "" : ", ") + std::to_string(k);
    throw py::index_error("triangle " + std::to_string(i) + " is not in the trace; it holds " +
                          (held.empty() ? "no triangle" : "triangle(s) " + held) +
                          " (trace_triangle calls its triangle by face=, 0 unless given)");
  }
  double y_min = begin->snapped.at(0).y, y_max = y_min;
  for (const Vec2& v : begin->snapped) y_min = std::min(y_min, v.y), y_max = std::max(y_max, v.y);
  const auto first = static_cast<std::int64_t>(std::ceil(y_min)),
             last = static_cast<std::int64_t>(std::ceil(y_max)) - 1;
  const std::string rows = "triangle " + std::to_string(i) + "'s rows are " +
                           std::to_string(first) + ".." + std::to_string(last) +
                           " (ceil(y_min) .. ceil(y_max) − 1";
  if (t.trace.header().level == TraceLevel::triangle)
    throw py::index_error(row + " is not in the trace: it was recorded at level 'triangle', "
                          "without rows (trace at level='scanline'); " + rows + ")");
  if (y >= first && y <= last)
    throw py::index_error(row + " is not in the trace (its rows= selection left it out); " +
                          rows + ")");
  std::string why;
  if (y < first)
    why = ": row " + std::to_string(y) + " is above the triangle's top, y_min = " +
          py::repr(py::float_(y_min)).cast<std::string>() + ")";
  else if (static_cast<double>(y) == y_max)
    why = ": the top-left rule leaves the bottom vertex's row out)";
  else
    why = ": row " + std::to_string(y) + " is below the triangle's bottom, y_max = " +
          py::repr(py::float_(y_max)).cast<std::string>() + ")";
  throw py::index_error(row + " is not filled: " + rows + why);
}

void bind_trace_class(py::module_& m) {
  py::class_<PyTrace>(m, "Trace", R"(A trace of the fill: what it did, event by event, with queries.

Made by trace_triangle(), trace_scene() or Trace.load(path) (a .jsonl file written by
`scantrace trace`). Triangles are numbered by face index (0 for trace_triangle):

    t.triangles()                         faces traced, in drawing order
    t.edge_table(0).edges[1].dx_dy        the edge table (EdgeEntry: edge, y_min, y_max, ...)
    t.scanline(0, 42).active_points[0].x  a row: entered, retired, active_edges, active_points,
    t.scanline(0, 42).span.x_begin        span (None when empty), span_colors
    t.pixel_history(x, y).final().triangle   who wrote pixel (x, y) last, and its colour
    t.pixels(0)                           pixel events (level='pixel')
    t.image                               the image the traced fill drew (None when loaded)

A query about a triangle or row that is not in the trace raises IndexError.)")
      .def_static(
          "load",
          [](const std::filesystem::path& path) {
            // A directory opens as a stream on Linux and fails at the first read, in the
            // library's words ("basic_filebuf::underflow"): said here instead.
            std::error_code ec;
            if (std::filesystem::is_directory(path, ec))
              throw TraceError(path.string() + ": is a directory, not a trace file (.jsonl)");
            PyTrace t{Trace::load(path), std::nullopt};
            return t;
          },
          py::arg("path"), "Reads a .jsonl trace; a malformed file raises InputError (file:line).")
      .def_property_readonly("header", [](const PyTrace& t) { return t.trace.header(); })
      .def_property_readonly("footer", [](const PyTrace& t) { return t.trace.footer(); })
      .def_property_readonly("complete", [](const PyTrace& t) { return t.trace.complete(); })
      .def_property_readonly("truncated", [](const PyTrace& t) { return t.trace.truncated(); })
      .def_property_readonly("image", &image_of)
      .def("__repr__", &trace_repr)
      .def("__len__", [](const PyTrace& t) { return t.trace.events().size(); })
      .def("triangles", [](const PyTrace& t) { return t.trace.triangles(); })
      .def("has_triangle", [](const PyTrace& t, int i) { return t.trace.has_triangle(i); })
      .def("triangle_begin", [](const PyTrace& t, int i) { return t.trace.triangle_begin(i); })
      .def(
          "edge_table", [](const PyTrace& t, int i) { return t.trace.edge_table(i); },
          py::arg("triangle"))
      .def(
          "scanline",
          [](const PyTrace& t, int i, std::int64_t y) { return scanline_or_why_not(t, i, y); },
          py::arg("triangle"), py::arg("y"))
      .def("has_scanline",
           [](const PyTrace& t, int i, std::int64_t y) { return t.trace.has_scanline(i, y); })
      .def("scanlines",
           [](const PyTrace& t, int i) {
             std::vector<Scanline> out;
             for (const Scanline* s : t.trace.scanlines(i)) out.push_back(*s);
             return out;
           })
      .def("pixels",
           [](const PyTrace& t, int i) {
             std::vector<Pixel> out;
             for (const Pixel* p : t.trace.pixels(i)) out.push_back(*p);
             return out;
           })
      .def("triangle_end", [](const PyTrace& t, int i) { return t.trace.triangle_end(i); })
      .def("skipped", [](const PyTrace& t, int i) { return t.trace.skipped(i); })
      .def(
          "pixel_history",
          [](const PyTrace& t, std::int64_t x, std::int64_t y) {
            return t.trace.pixel_history(x, y);
          },
          py::arg("x"), py::arg("y"));
}

}  // namespace

void bind_trace(py::module_& m) {
  bind_events(m);
  bind_trace_class(m);
  m.def(
      "trace_triangle",
      [](py::handle vertices, py::handle vcolors, const std::string& shading,
         const std::string& fill_rule, const std::string& level, py::handle size,
         py::handle background, py::handle face) {
        const int id = face_id_argument(face);
        TriangleInput in;
        in.vertices = triangle_vertices(vertices);
        in.colors = triangle_colors(vcolors);
        std::tie(in.width, in.height) = size_argument(size);
        in.background = color_argument(background, "background");
        FillOptions opt;
        opt.shading = shading_argument(shading);
        opt.fill_rule = fill_rule_argument(fill_rule);
        const TraceFilter filter =
            filter_argument(level, py::none(), py::none(), py::none(), 1, in.height);
        py::gil_scoped_release free;
        RgbImage image;
        Trace t = record_triangle(in, opt, filter, &image);
        if (id != 0) t = renumbered(t, id);
        return PyTrace{std::move(t), std::move(image)};
      },
      py::arg("vertices"), py::arg("vcolors"), py::kw_only(), py::arg("shading"),
      py::arg("fill_rule"), py::arg("level"), py::arg("size"), py::arg("background"),
      py::arg("face") = 0);
  m.def(
      "trace_scene",
      [](py::handle vertices, py::handle faces, py::handle vcolors, py::handle depth,
         const std::string& shading, const std::string& fill_rule, const std::string& level,
         py::handle triangles, py::handle rows, py::handle max_events, py::handle size,
         py::handle background) {
        FillOptions opt;
        opt.shading = shading_argument(shading);
        opt.fill_rule = fill_rule_argument(fill_rule);
        const Scene scene = scene_from_arrays(vertices, faces, vcolors, depth, size_argument(size),
                                              color_argument(background, "background"));
        const TraceFilter filter =
            filter_argument(level, triangles, rows, max_events,
                            static_cast<std::int64_t>(scene.faces.size()), scene.height);
        py::gil_scoped_release free;
        RgbImage image;
        Trace t = record_scene(scene, opt, filter, &image);
        return PyTrace{std::move(t), std::move(image)};
      },
      py::arg("vertices"), py::arg("faces"), py::arg("vcolors"), py::arg("depth"), py::kw_only(),
      py::arg("shading"), py::arg("fill_rule"), py::arg("level"), py::arg("triangles"),
      py::arg("rows"), py::arg("max_events"), py::arg("size"), py::arg("background"));
}

}  // namespace scantrace::python
