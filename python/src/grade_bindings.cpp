// why, diff and check from Python: the grading layer's own functions (grade/, trace/), the same
// code as `scantrace why`, `diff` and `check`. Each returns plain values (JSON text, the CLI's
// text, arrays) that python/scantrace/_grade.py wraps into PixelStory, DiffReport and CheckResult.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cfloat>
#include <climits>
#include <cmath>
#include <cstring>
#include <optional>

#include <nlohmann/json.hpp>

#include "arrays.hpp"
#include "grade/diff_picture.hpp"
#include "grade/diff_report.hpp"
#include "grade/global_mistakes.hpp"
#include "grade/mistake_catalogue.hpp"
#include "grade/image_precheck.hpp"
#include "io/json_input.hpp"
#include "io/memory_budget.hpp"
#include "grade/pixel_story.hpp"
#include "io/npy_reader.hpp"
#include "py_trace.hpp"
#include "trace/trace_check.hpp"

namespace scantrace::python {

namespace {

// A pixel coordinate: an int on the canvas (a numpy integer too: x and y from np.nonzero),
// named in the error.
int pixel_coordinate(py::handle value, const char* name, int size) {
  const std::optional<py::int_> n = integer_value(value);
  if (!n)
    throw_type_error(std::string(name) + ": expected an int (a pixel " +
                     (name[0] == 'x' ? "column" : "row") + "), got " +
                     py::str(py::type::of(value).attr("__name__")).cast<std::string>());
  int overflow = 0;
  const long long v = PyLong_AsLongLongAndOverflow(n->ptr(), &overflow);
  if (overflow || v < 0 || v >= size)
    throw_value_error(std::string(name) + ": expected a pixel " +
                      (name[0] == 'x' ? "column, 0 .. width - 1 = " : "row, 0 .. height - 1 = ") +
                      std::to_string(size - 1) + ", got " + py::repr(value).cast<std::string>());
  return static_cast<int>(v);
}

py::tuple why(py::handle vertices, py::handle faces, py::handle vcolors, py::handle depth,
              py::handle x, py::handle y, const std::string& shading, const std::string& fill_rule,
              py::handle size, py::handle background) {
  const FillOptions opt = fill_options(shading, fill_rule);
  const Scene scene = scene_from_arrays(vertices, faces, vcolors, depth, size_argument(size),
                                        color_argument(background, "background"));
  const int px = pixel_coordinate(x, "x", scene.width),
            py_ = pixel_coordinate(y, "y", scene.height);
  grade::PixelStory story;
  {
    py::gil_scoped_release free;
    story = grade::why(scene, opt, px, py_);
  }
  return py::make_tuple(story.to_json().dump(2), story.to_text());
}

// An integer image's values must be 8-bit ones: 0 .. 255 (the first one outside is named).
void check_byte_range(const DoubleArray& f) {
  const double* p = f.data();
  for (py::ssize_t i = 0; i < f.size(); ++i)
    if (p[i] < 0 || p[i] > 255) {
      const py::ssize_t pixel = i / 3, w = f.shape(1);
      throw_value_error("image[" + std::to_string(pixel / w) + ", " + std::to_string(pixel % w) +
                        "]: an integer image holds 8-bit values 0 .. 255, got " +
                        std::to_string(static_cast<long long>(p[i])) +
                        " (a float image holds colours in [0, 1])");
    }
}

// The submitted image: H×W×3, uint8 (bytes / 255, as a decoded PNG) or float32/float64 (as a
// .npy, unscaled: [0, 255] floats are one of the global mistakes diff names).
// `format`: "npy" for arrays and .npy files, else the image file's ("png", "jpeg", "bmp"), decoded
// by the OpenCV module: the two readers of the command scale bytes differently in the last bit
// (grade/image_input.cpp: b / 255.0f for image files, b * (1 / 255.0f) for .npy), and diff must
// compare what the command compares.
grade::SubmittedImage submitted_array(py::handle value, const std::string& format) {
  if (!py::isinstance<py::array>(value))
    throw_type_error("image: expected an H x W x 3 numpy array or a path, got " +
                     py::str(py::type::of(value).attr("__name__")).cast<std::string>());
  const auto a = py::reinterpret_borrow<py::array>(value);
  const char kind = a.dtype().kind();
  // Integers of any width are 8-bit values when they are 0 .. 255 (an int64 array from
  // np.round(255 * img).astype(int), a uint16 holding bytes).
  const bool bytes = kind == 'u' || kind == 'i';
  if (!bytes && !(kind == 'f' && (a.itemsize() == 4 || a.itemsize() == 8)))
    throw_type_error("image: expected an integer dtype (values 0 .. 255), float32 or float64, "
                     "got " + py::str(a.dtype()).cast<std::string>());
  if (a.ndim() != 3 || a.shape(2) != 3 || a.shape(0) == 0 || a.shape(1) == 0)
    throw_value_error(
        "image: expected an array of shape (H, W, 3), got " +
        py::str(py::tuple(py::cast(std::vector<py::ssize_t>(a.shape(), a.shape() + a.ndim()))))
            .cast<std::string>());
  if (a.shape(0) > INT_MAX || a.shape(1) > INT_MAX || a.shape(0) * a.shape(1) > kMaxCanvasPixels)
    throw_value_error("image: " + std::to_string(a.shape(1)) + "x" + std::to_string(a.shape(0)) +
                      " pixels, more than the 2^28 that can be compared");
  // Read as float64 (numpy does the byte order and the strides; no copy of a C-order float64
  // array), then narrowed to float32 as the comparison holds it: finiteness is checked against
  // float32's range, so a float64 above FLT_MAX is refused instead of becoming inf.
  const DoubleArray f = DoubleArray::ensure(a);
  if (!f) throw py::error_already_set();
  if (kind == 'i' || (kind == 'u' && a.itemsize() > 1)) check_byte_range(f);
  grade::SubmittedImage out;
  out.name = "image";
  out.format = format;
  out.eight_bit = bytes;
  out.pixels = RgbImage(static_cast<int>(a.shape(1)), static_cast<int>(a.shape(0)));
  const double* p = f.data();
  for (int yy = 0; yy < out.pixels.height(); ++yy)
    for (int xx = 0; xx < out.pixels.width(); ++xx, p += 3) {
      float c[3];
      for (int k = 0; k < 3; ++k) {
        if (!(std::abs(p[k]) <= FLT_MAX))
          throw_value_error("image[" + std::to_string(yy) + ", " + std::to_string(xx) +
                            "]: NaN and infinity are not allowed, nor values beyond float32's "
                            "range, got " +
                            py::repr(py::float_(p[k])).cast<std::string>());
        c[k] = static_cast<float>(p[k]);
      }
      if (!bytes)
        out.pixels(xx, yy) = {c[0], c[1], c[2]};
      else if (format == "npy")
        out.pixels(xx, yy) = {c[0] * (1.0f / 255.0f), c[1] * (1.0f / 255.0f),
                              c[2] * (1.0f / 255.0f)};
      else
        out.pixels(xx, yy) = {c[0] / 255.0f, c[1] / 255.0f, c[2] / 255.0f};
    }
  return out;
}

// A .npy image file through the command's pre-check against a canvas of `canvas`
// (grade/image_precheck.hpp: its shape, the canvas, the memory budget) and its strict reader:
// (the array, (width, height)), the array None when the shape decides (nothing read of the values:
// diff reports canvas_size).
py::tuple read_npy_image(const std::string& path, std::pair<int, int> canvas) {
  const std::string bytes = within_memory(path, [&] { return json_input::read_text_file(path); });
  grade::ImageHeader header;
  const bool decided = grade::precheck_image(bytes, path, &grade::declared_png_or_bmp_size,
                                             canvas.first, canvas.second, header);
  const py::tuple size = py::make_tuple(header.width, header.height);
  if (decided) return py::make_tuple(py::none(), size);
  const NpyImage npy = parse_npy(bytes, path, grade::kMaxNpyImageBytes);
  if (npy.integer) {
    py::array_t<std::uint8_t> out({npy.height, npy.width, 3});
    for (std::size_t k = 0; k < npy.values.size(); ++k)
      out.mutable_data()[k] = static_cast<std::uint8_t>(npy.values[k]);
    return py::make_tuple(out, size);
  }
  py::array_t<float> out({npy.height, npy.width, 3});
  std::memcpy(out.mutable_data(), npy.values.data(), npy.values.size() * sizeof(float));
  return py::make_tuple(out, size);
}

py::tuple diff(py::handle vertices, py::handle faces, py::handle vcolors, py::handle depth,
               py::handle image, const std::string& shading, const std::string& fill_rule,
               py::handle size, py::handle background, py::handle tolerance, bool undo,
               const std::string& format, py::handle declared) {
  const FillOptions opt = fill_options(shading, fill_rule);
  const Scene scene = scene_from_arrays(vertices, faces, vcolors, depth, size_argument(size),
                                        color_argument(background, "background"));
  grade::DiffOptions o;
  if (!py::isinstance<py::float_>(tolerance) && !py::isinstance<py::int_>(tolerance))
    throw_type_error("tolerance: expected a number, got " +
                     py::str(py::type::of(tolerance).attr("__name__")).cast<std::string>());
  o.tolerance = tolerance.cast<double>();
  // NaN would compare false with everything, and every image would agree.
  if (!(o.tolerance >= 0 && o.tolerance <= 1))
    throw_value_error("tolerance: expected a difference per channel in [0, 1], got " +
                      py::repr(tolerance).cast<std::string>());
  o.undo = undo;
  grade::DiffReport report;
  if (image.is_none()) {  // a file whose header decided (read_npy_image, read_image): its size
    const auto [w, h] = declared.cast<std::pair<std::int64_t, std::int64_t>>();
    report = grade::canvas_size_report(scene, opt, {format, w, h}, o);
  } else {
    const grade::SubmittedImage submitted = submitted_array(image, format);
    py::gil_scoped_release free;
    report = grade::diff(scene, opt, submitted, o);
  }
  const std::vector<std::uint8_t> picture = grade::diff_picture(report);
  py::array_t<std::uint8_t> pic({report.height, report.width, 3});
  std::memcpy(pic.mutable_data(), picture.data(), picture.size());
  return py::make_tuple(report.to_json().dump(2), report.to_markdown(), pic);
}

// An image as an H x W x 3 float64 array.
py::array_t<double> float64_pixels(const RgbImage& image) {
  py::array_t<double> pixels({image.height(), image.width(), 3});
  double* q = pixels.mutable_data();
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x, q += 3) {
      const Rgb32f c = image(x, y);
      q[0] = c.r, q[1] = c.g, q[2] = c.b;
    }
  return pixels;
}

// diff's whole-image mistakes (grade/global_mistakes.cpp) on images alone, for the grader
// (scantrace/grade/whole_image.py): `reference` H×W×3, `faces` H×W true where the reference
// shows a face, the scene's `background`. One implementation and one set of thresholds (the
// catalogue's) for `diff` and `scantrace grade`. Returns ([{'kind', 'text', 'undone'}], the
// image on the reference's canvas with the mistakes undone (float64), notes).
py::tuple whole_image_mistakes(py::handle image, py::handle reference, py::handle faces,
                               py::handle background, py::handle tolerance, bool undo) {
  const DoubleArray ref = float_array(reference, "reference", {'H', 'W', 3});
  const int H = static_cast<int>(ref.shape(0)), W = static_cast<int>(ref.shape(1));
  const py::array mask_any = py::module_::import("numpy").attr("asarray")(faces, "bool");
  if (mask_any.ndim() != 2 || mask_any.shape(0) != H || mask_any.shape(1) != W)
    throw_value_error("faces: expected a boolean array of the reference's shape (" +
                      std::to_string(H) + ", " + std::to_string(W) + ")");
  const auto mask = py::array_t<bool, py::array::c_style | py::array::forcecast>::ensure(mask_any);
  grade::SubmittedImage in = submitted_array(image, "npy");
  const double tol = tolerance.cast<double>();
  Scene canvas;  // what the detection needs of a scene: the canvas and its background
  canvas.width = W, canvas.height = H;
  canvas.background = color_argument(background, "background");
  grade::FaceIdImage ids{W, H, std::vector<int>(static_cast<std::size_t>(W) * H, -1)};
  RgbImage reference_image(W, H);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * W + x;
      if (mask.data()[i]) ids.ids[i] = 0;
      const double* p = ref.data() + 3 * i;
      reference_image(x, y) = {static_cast<float>(p[0]), static_cast<float>(p[1]),
                               static_cast<float>(p[2])};
    }
  RgbImage out;
  std::vector<unsigned char> compared;
  std::vector<std::string> notes;
  std::vector<grade::GlobalMistake> found;
  {
    py::gil_scoped_release free;
    found = grade::find_global_mistakes(canvas, reference_image, ids, in, tol, undo, out,
                                        compared, notes);
  }
  py::list mistakes;
  for (const auto& g : found) {
    py::dict d;
    d["kind"] = g.kind, d["text"] = g.text, d["undone"] = g.undone;
    mistakes.append(d);
  }
  return py::make_tuple(mistakes, float64_pixels(out), py::cast(notes));
}

// The 0–255 scale of whole_image_mistakes alone (grade::find_scale_255), for the grader's canvases
// of any size (probes included), whose white is the grader's blank canvas: returns (the image with
// its painted pixels divided by 255 when scaled, float64; whether it was scaled; the largest
// value).
py::tuple scale_255(py::handle image, py::handle background, py::handle tolerance) {
  grade::SubmittedImage in = submitted_array(image, "npy");
  const Color bg = color_argument(background, "background");
  const double tol = tolerance.cast<double>();
  grade::Scale255 s;
  {
    py::gil_scoped_release free;
    s = grade::find_scale_255(in.pixels, bg, tol, true);
  }
  return py::make_tuple(float64_pixels(in.pixels), s.scaled, s.top);
}

py::dict check(const PyTrace& t, const std::string& name) {
  py::dict d;
  try {
    trace::CheckSummary s;
    {
      py::gil_scoped_release free;
      s = trace::check_consistency(t.trace.events(), name, trace::CheckDepth::thorough);
    }
    d["problem"] = py::none();
    d["events"] = s.events;
    d["triangles"] = s.triangles;
    d["edges"] = s.edges;
    d["scanlines"] = s.scanlines;
    d["pixels"] = s.pixels;
  } catch (const trace::TraceError& e) {
    d["problem"] = std::string(e.what());
  }
  d["complete"] = t.trace.complete();
  return d;
}

// `scantrace check FILE`: what the load refuses (its cheap checks) is the verdict as well.
py::dict check_file(const std::string& path) {
  std::optional<PyTrace> t;
  try {
    py::gil_scoped_release free;
    t = PyTrace{trace::Trace::load(path), std::nullopt};
  } catch (const trace::TraceError& e) {
    py::dict d;
    d["problem"] = std::string(e.what());
    d["complete"] = false;
    return d;
  }
  return check(*t, path);
}

}  // namespace

void bind_grade(py::module_& m) {
  m.def("why", &why, py::arg("vertices"), py::arg("faces"), py::arg("vcolors"), py::arg("depth"),
        py::arg("x"), py::arg("y"), py::kw_only(), py::arg("shading"), py::arg("fill_rule"),
        py::arg("size"), py::arg("background"));
  m.def("diff", &diff, py::arg("vertices"), py::arg("faces"), py::arg("vcolors"), py::arg("depth"),
        py::arg("image"), py::kw_only(), py::arg("shading"), py::arg("fill_rule"), py::arg("size"),
        py::arg("background"), py::arg("tolerance"), py::arg("undo"), py::arg("format"),
        py::arg("declared") = py::none());
  m.def("read_npy_image", &read_npy_image, py::arg("path"), py::arg("canvas"));
  m.def("whole_image_mistakes", &whole_image_mistakes, py::arg("image"), py::arg("reference"),
        py::arg("faces"), py::kw_only(), py::arg("background"), py::arg("tolerance"),
        py::arg("undo"));
  m.def("scale_255", &scale_255, py::arg("image"), py::kw_only(), py::arg("background"),
        py::arg("tolerance"));
  m.def("check", &check, py::arg("trace"), py::arg("name"));
  m.def("check_file", &check_file, py::arg("path"));
  py::list categories;
  for (const char* c : grade::kCategories) categories.append(c);
  m.attr("DIFF_CATEGORIES") = py::tuple(categories);
  py::list colours;
  for (const auto& c : grade::kCategoryColours) colours.append(py::make_tuple(c[0], c[1], c[2]));
  m.attr("DIFF_CATEGORY_COLOURS") = py::tuple(colours);
  // The mistake catalogue as embedded in the C++ (the Python grader reads the package's copy of
  // the same file; a test compares them).
  m.attr("MISTAKE_CATALOGUE_JSON") = std::string(grade::mistake_catalogue_json());
}

}  // namespace scantrace::python
