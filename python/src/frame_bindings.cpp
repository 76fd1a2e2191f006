// A trace's replay frames in Python, from the display list (viz/frame.hpp; no OpenCV): one frame as
// SVG or canvas JSON with its marks, and every frame at once as the inline player's deck
// (player_deck.hpp). python/scantrace/_player.py builds the Jupyter player on them.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <map>
#include <memory>
#include <mutex>

#include "arrays.hpp"
#include "player_deck.hpp"
#include "py_trace.hpp"
#include "viz/frame_json.hpp"
#include "viz/frame_sequence.hpp"
#include "viz/step_label.hpp"
#include "viz/svg_frame.hpp"
#include "viz/web_player_files.hpp"

namespace scantrace::python {
namespace {

// Frames larger than 4K are no use inline and cost their size in memory per frame.
constexpr int kMaxFrameWidth = 3840, kMaxFrameHeight = 2160;

// A trace's replay: the sequence keeps a reference to the trace, so the Python Trace is kept alive
// with it. The sequence's canvas state changes as frames are composed (GIL released): one at a
// time.
struct PyFrames {
  py::object owner;
  std::unique_ptr<viz::FrameSequence> sequence;
  std::mutex busy;
};

viz::ReplayMode mode_argument(const std::string& s) {
  if (s == "auto") return viz::ReplayMode::automatic;
  try {
    return viz::parse_replay_mode(s);
  } catch (const std::invalid_argument&) {
    throw_value_error("mode: expected 'auto', 'triangles' or 'scene', got '" + s + "'");
  }
}

int step_count_argument(int value, const char* name, int least) {
  if (value < least)
    throw_value_error(std::string(name) + ": expected at least " + std::to_string(least) +
                      ", got " + std::to_string(value));
  return value;
}

viz::Size frame_size_argument(py::handle value) {
  const auto [w, h] = size_argument(value, "frame_size");
  if (w < viz::kMinFrameWidth || h < viz::kMinFrameHeight || w > kMaxFrameWidth ||
      h > kMaxFrameHeight)
    throw_value_error("frame_size: expected (width, height) from (" +
                      std::to_string(viz::kMinFrameWidth) + ", " +
                      std::to_string(viz::kMinFrameHeight) + ") to (" +
                      std::to_string(kMaxFrameWidth) + ", " + std::to_string(kMaxFrameHeight) +
                      "), got (" + std::to_string(w) + ", " + std::to_string(h) + ")");
  return {w, h};
}

std::size_t step_index(const PyFrames& f, py::ssize_t i) {
  const auto n = static_cast<py::ssize_t>(f.sequence->steps().size());
  if (i < -n || i >= n)
    throw py::index_error("step " + std::to_string(i) + " is out of range (" + std::to_string(n) +
                          " steps)");
  return static_cast<std::size_t>(i < 0 ? i + n : i);
}

py::dict mark_dict(const viz::Mark& m) {
  py::dict d;
  d["kind"] = viz::to_string(m.kind);
  d["what"] = m.what;
  d["box"] = py::make_tuple(m.box.x, m.box.y, m.box.width, m.box.height);
  d["layer"] = m.layer;
  return d;
}

py::dict step_dict(const viz::StepPlan& plan, const viz::Step& s) {
  py::dict d;
  d["kind"] = viz::to_string(s.kind);
  d["label"] = viz::step_label(plan, s);
  d["triangle"] = s.triangle >= 0 ? py::object(py::int_(s.triangle)) : py::object(py::none());
  if (s.kind == viz::StepKind::scanlines) d["rows"] = py::make_tuple(s.first_row, s.last_row);
  if (s.kind == viz::StepKind::painter_batch) d["drawn"] = py::make_tuple(s.first, s.last);
  return d;
}

std::string frame_repr(const viz::Frame& f) {
  std::map<std::string, int> kinds;
  for (const viz::Mark& m : f.marks()) ++kinds[viz::to_string(m.kind)];
  std::string marks;
  for (const auto& [kind, n] : kinds)
    marks += (marks.empty() ? "" : ", ") + std::to_string(n) + " " + kind;
  return "<Frame " + std::to_string(f.size().width) + "x" + std::to_string(f.size().height) + ": " +
         std::to_string(f.ops().size()) +
         " drawing operations; marks: " + (marks.empty() ? "none" : marks) + ">";
}

void bind_frame(py::module_& m) {
  py::class_<viz::Frame>(m, "Frame", R"(One replay frame as a display list (what is drawn, where).

    f.to_svg()     a self-contained SVG 1.1 document (text as strokes; no font, no link)
    f.to_json()    the canvas JSON drawn by drawScantraceFrame (scantrace.frame_canvas_script())
    f.marks()      what the frame marks: [{'kind': 'scanline', 'what': 'y = 42', 'box': (x, y, w, h),
                   'layer': 0}, ...]; marks('active_point') only those of one kind
In Jupyter a Frame shows itself as its SVG.)")
      .def_property_readonly(
          "size",
          [](const viz::Frame& f) { return py::make_tuple(f.size().width, f.size().height); })
      .def("to_svg", [](const viz::Frame& f) { return viz::to_svg(f); })
      .def("to_json", [](const viz::Frame& f) { return viz::to_json(f); })
      .def("_repr_svg_", [](const viz::Frame& f) { return viz::to_svg(f); })
      .def(
          "marks",
          [](const viz::Frame& f, std::optional<std::string> kind) {
            py::list out;
            for (const viz::Mark& mk : f.marks())
              if (!kind || *kind == viz::to_string(mk.kind)) out.append(mark_dict(mk));
            return out;
          },
          py::arg("kind") = py::none())
      .def("__repr__", &frame_repr);
}

void bind_frames_class(py::module_& m) {
  py::class_<PyFrames>(m, "Frames", R"(A trace's replay, one frame per step (Trace.frames()).

    len(frames), frames.steps      the steps: {'kind', 'label', 'triangle', 'rows' or 'drawn'}
    frames[i]                      the Frame of step i (negative from the end)
    frames.deck(first, last)       steps first..last as the inline player's JSON)")
      .def("__len__", [](const PyFrames& f) { return f.sequence->steps().size(); })
      .def(
          "__getitem__",
          [](PyFrames& f, py::ssize_t i) {
            const std::size_t k = step_index(f, i);
            py::gil_scoped_release free;
            std::lock_guard lock(f.busy);
            return f.sequence->frame(k);
          },
          py::arg("step"))
      .def_property_readonly("steps",
                             [](const PyFrames& f) {
                               py::list out;
                               for (const viz::Step& s : f.sequence->steps())
                                 out.append(step_dict(f.sequence->plan(), s));
                               return out;
                             })
      .def_property_readonly(
          "mode", [](const PyFrames& f) { return viz::to_string(f.sequence->plan().mode); })
      .def_property_readonly("frame_size",
                             [](const PyFrames& f) {
                               return py::make_tuple(f.sequence->frame_size().width,
                                                     f.sequence->frame_size().height);
                             })
      .def(
          "deck",
          [](PyFrames& f, py::ssize_t first, std::optional<py::ssize_t> last) {
            const std::size_t a = step_index(f, first);
            const std::size_t b = last ? step_index(f, *last) : f.sequence->steps().size() - 1;
            if (b < a) throw_value_error("last: expected a step at or after first");
            py::gil_scoped_release free;
            std::lock_guard lock(f.busy);
            const Deck d = write_deck(*f.sequence, a, b);
            return std::make_pair(d.json, d.distinct_ops);
          },
          py::arg("first") = 0, py::arg("last") = py::none(),
          "Steps first..last as the player's JSON deck (python/src/player_deck.hpp); returns "
          "(json, distinct drawing operations).")
      .def("__repr__", [](const PyFrames& f) {
        return "<Frames: " + std::to_string(f.sequence->steps().size()) + " steps (" +
               viz::to_string(f.sequence->plan().mode) + "), " +
               std::to_string(f.sequence->frame_size().width) + "x" +
               std::to_string(f.sequence->frame_size().height) + ">";
      });
}

// A trace's replay as Frames (steps as `scantrace replay` plans them).
std::unique_ptr<PyFrames> trace_frames(py::object trace, py::handle frame_size,
                                       const std::string& mode, int rows_per_step,
                                       int max_scanline_steps, int max_scene_steps,
                                       const std::string& source) {
  viz::StepOptions options;
  options.mode = mode_argument(mode);
  options.rows_per_step = step_count_argument(rows_per_step, "rows_per_step", 0);
  options.max_scanline_steps = step_count_argument(max_scanline_steps, "max_scanline_steps", 1);
  options.max_scene_steps = step_count_argument(max_scene_steps, "max_scene_steps", 1);
  const viz::Size size = frame_size_argument(frame_size);
  const PyTrace& t = trace.cast<const PyTrace&>();
  auto f = std::make_unique<PyFrames>();
  f->owner = trace;
  f->sequence = std::make_unique<viz::FrameSequence>(t.trace, options, size, source);
  return f;
}

// Trace's replay methods, defined on the type with the rest of it: frames() and frame() here,
// player() and _repr_html_ by the inline player's Python (scantrace/_player.py), imported when
// first called.
void bind_trace_replay(py::module_& m) {
  auto trace = py::reinterpret_borrow<py::class_<PyTrace>>(m.attr("Trace"));
  const auto in_python = [](const char* name) {
    return [name](py::object self, py::kwargs options) {
      return py::module_::import("scantrace._player").attr(name)(self, **options);
    };
  };
  trace.def(
      "frames",
      [](py::object self, py::handle frame_size, const std::string& mode, int rows_per_step,
         int max_scanline_steps, int max_scene_steps) {
        return trace_frames(self, frame_size, mode, rows_per_step, max_scanline_steps,
                            max_scene_steps, "the trace");
      },
      py::kw_only(), py::arg("frame_size") = py::make_tuple(1280, 720), py::arg("mode") = "auto",
      py::arg("rows_per_step") = 0, py::arg("max_scanline_steps") = 40,
      py::arg("max_scene_steps") = 100,
      R"(The replay of this trace, one frame per step (the steps of ``scantrace replay``).

mode: ``'auto'`` (one triangle step by step; several: the scene), ``'triangles'`` or
``'scene'``. rows_per_step: scanlines per step (0: at most ``max_scanline_steps`` per
triangle). max_scene_steps: the painter's batches of a scene. Returns :class:`Frames`::

    f = t.frames()
    len(f), f.steps[5]['label']     # 'scanline y = 24 (5 of 380)'
    f[5].to_svg()                   # the frame as a self-contained SVG document
    f[5].marks('scanline')          # [{'kind': 'scanline', 'what': 'y = 24', 'box': ...}])");
  trace.def(
      "frame",
      [](py::object self, py::object step, py::kwargs options) {
        // Held here: an item accessor keeps only a borrowed handle of what it indexes.
        const py::object frames = self.attr("frames")(**options);
        return py::object(frames[step]);
      },
      py::arg("step"),
      "The :class:`Frame` of replay step ``step`` (from 0; negative from the end); the options "
      "are those of :meth:`frames`. ``t.frame(10).to_svg()``.");
  trace.def("player", in_python("player"),
            "The trace's replay as an inline HTML :class:`Player` (what a Trace shows in "
            "Jupyter): player(frame_size=(960, 540), mode='auto', max_bytes=None). frame_size: "
            "of the frames (the player scales to the notebook's width); max_bytes: the size "
            "bound (default 1 MB for triangles, 2 MB for a scene), past which steps are batched.");
  trace.def("_repr_html_", in_python("_repr_html_"));
}

}  // namespace

void bind_frames(py::module_& m) {
  bind_frame(m);
  bind_frames_class(m);
  m.def("frames", trace_frames, py::arg("trace"), py::kw_only(), py::arg("frame_size"),
        py::arg("mode"), py::arg("rows_per_step"), py::arg("max_scanline_steps"),
        py::arg("max_scene_steps"), py::arg("source"));
  m.def(
      "frame_canvas_script", [] { return std::string(viz::frame_canvas_script()); },
      "The JavaScript of drawScantraceFrame(ctx, frame), which draws Frame.to_json() on a "
      "<canvas>.");
  m.def(
      "player_core_script", [] { return std::string(viz::web_player::player_core_js); },
      "The JavaScript of the player core every page shares (web/player/: the key table, the "
      "stepper, its controls, the Hershey layout), as one classic script.");
  bind_trace_replay(m);
}

}  // namespace scantrace::python
