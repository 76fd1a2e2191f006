// The course's functions and the renders: numpy arrays in, numpy arrays out, the library's fill
// writing straight into the arrays (array_canvas.hpp).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <cmath>
#include <cstring>

#include "array_canvas.hpp"
#include "arrays.hpp"
#include "casters.hpp"
#include "io/obj_loader.hpp"
#include "io/scene_json.hpp"
#include "src/painter.hpp"
#include "src/shade_mesh.hpp"
#include "src/vector_interp.hpp"
#include "viz/image_file.hpp"

namespace scantrace::python {

namespace {

// Fills `img` with one triangle. The fill runs without the GIL: the arrays it reads were copied
// into C++ values and `img` stays referenced by the caller for the duration of the call.
template <class P>
void fill_array(py::array& img, const std::array<Vec2, 3>& v, const std::array<Color, 3>& c,
                const FillOptions& opt) {
  ArrayCanvas<P> canvas(static_cast<P*>(img.mutable_data()), static_cast<int>(img.shape(1)),
                        static_cast<int>(img.shape(0)));
  py::gil_scoped_release free;
  FillScratch scratch;
  fill_polygon(canvas, PolygonInput{v, c, 0, std::nullopt}, opt, scratch);
}

py::object shade(py::object img, py::handle vertices, py::handle vcolors, Shading shading) {
  py::array target = image_array(img, "img");
  const auto v = triangle_vertices(vertices);
  const auto c = triangle_colors(vcolors);
  FillOptions opt;
  opt.shading = shading;
  // A non-contiguous view (img[::2], a transposed array) is filled through a contiguous copy that
  // is written back, so the caller's array is still the one that changes.
  const bool direct = (target.flags() & py::array::c_style) != 0;
  py::array work =
      direct ? target : py::array(py::module_::import("numpy").attr("ascontiguousarray")(target));
  if (work.itemsize() == 8)
    fill_array<Rgb64>(work, v, c, opt);
  else
    fill_array<Rgb32f>(work, v, c, opt);
  if (!direct) target.attr("__setitem__")(py::ellipsis(), work);
  return img;
}

template <class P>
py::array render_array(const Scene& scene, const FillOptions& opt) {
  py::array_t<decltype(P::r)> out({scene.height, scene.width, 3});
  ArrayCanvas<P> canvas(reinterpret_cast<P*>(out.mutable_data()), scene.width, scene.height);
  {
    py::gil_scoped_release free;
    canvas.clear(scene.background);
    NoTracer none;
    render_into(canvas, scene, opt, none);
  }
  return out;
}

py::array render_scene(const Scene& scene, const FillOptions& opt, py::handle dtype) {
  const py::dtype dt = py::dtype::from_args(py::reinterpret_borrow<py::object>(dtype));
  if (dt.is(py::dtype::of<double>()) || dt.equal(py::dtype::of<double>()))
    return render_array<Rgb64>(scene, opt);
  if (dt.equal(py::dtype::of<float>())) return render_array<Rgb32f>(scene, opt);
  if (dt.equal(py::dtype::of<std::uint8_t>())) {
    // The bytes of the PNG the command line writes: round(255·c) of the float canvas.
    const py::array_t<float> f = render_array<Rgb32f>(scene, opt);
    py::array_t<std::uint8_t> out({scene.height, scene.width, 3});
    const float* in = f.data();
    std::uint8_t* o = out.mutable_data();
    for (py::ssize_t i = 0; i < f.size(); ++i) o[i] = to_byte(in[i]);
    return out;
  }
  throw_type_error("dtype: expected float64, float32 or uint8, got " +
                   py::str(static_cast<py::handle>(dt)).cast<std::string>());
}

FillOptions fill_options(const std::string& shading, const std::string& fill_rule) {
  FillOptions opt;
  opt.shading = shading_argument(shading);
  opt.fill_rule = fill_rule_argument(fill_rule);
  return opt;
}

template <class T>
py::array_t<T> to_numpy(const std::vector<T>& v, std::vector<py::ssize_t> shape) {
  py::array_t<T> a(shape);
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

py::dict scene_dict(const Scene& s) {
  py::dict d;
  py::array_t<double> v({static_cast<py::ssize_t>(s.vertices.size()), py::ssize_t{2}});
  py::array_t<double> c({static_cast<py::ssize_t>(s.vcolors.size()), py::ssize_t{3}});
  py::array_t<std::int64_t> f({static_cast<py::ssize_t>(s.faces.size()), py::ssize_t{3}});
  for (std::size_t i = 0; i < s.vertices.size(); ++i) {
    v.mutable_at(i, 0) = s.vertices[i].x;
    v.mutable_at(i, 1) = s.vertices[i].y;
    c.mutable_at(i, 0) = s.vcolors[i].r;
    c.mutable_at(i, 1) = s.vcolors[i].g;
    c.mutable_at(i, 2) = s.vcolors[i].b;
  }
  for (std::size_t i = 0; i < s.faces.size(); ++i)
    for (int j = 0; j < 3; ++j) f.mutable_at(i, j) = s.faces[i][j];
  d["vertices"] = v;
  d["faces"] = f;
  d["vcolors"] = c;
  d["depth"] = to_numpy(s.depth, {static_cast<py::ssize_t>(s.depth.size())});
  d["size"] = py::make_tuple(s.width, s.height);
  d["background"] = s.background;
  return d;
}

RgbImage float_image(py::handle img, const char* name) {
  const DoubleArray a = float_array(img, name, {'M', 'N', 3});
  RgbImage image(static_cast<int>(a.shape(1)), static_cast<int>(a.shape(0)));
  const double* p = a.data();
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x, p += 3)
      image(x, y) =
          Rgb32f{static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])};
  return image;
}

}  // namespace

Scene load_scene_file(const std::string& path, Shading obj_shading) {
  if (is_obj_file(path)) {
    ShadeOptions o;  // the command line's defaults for a model
    o.shading = obj_shading;
    return shade_mesh(load_obj(path), o);
  }
  return load_scene(path);
}

void bind_course(py::module_& m) {
  m.def(
      "vector_interp",
      [](py::handle p1, py::handle p2, py::handle V1, py::handle V2, double coord,
         int dim) -> py::object {
        const DoubleArray a = float_array(p1, "p1", {2}), b = float_array(p2, "p2", {2});
        const py::array s1 = py::module_::import("numpy").attr("asarray")(V1);
        std::vector<Dim> shape;
        for (py::ssize_t i = 0; i < s1.ndim(); ++i) shape.push_back(Dim(int(s1.shape(i))));
        const DoubleArray v1 = float_array(V1, "V1", shape), v2 = float_array(V2, "V2", shape);
        if (!std::isfinite(coord)) throw_value_error("coord: NaN and infinity are not allowed");
        if (dim != 1 && dim != 2)
          throw_value_error("dim: expected 1 (along x) or 2 (along y), got " + std::to_string(dim));
        // The C++ function interpolates colours, three components at a time, each independently;
        // a value of any shape is interpolated in groups of three (the last padded with zeros).
        const Vec2 q1{a.data()[0], a.data()[1]}, q2{b.data()[0], b.data()[1]};
        py::array_t<double> out(shape.empty()
                                    ? std::vector<py::ssize_t>{}
                                    : std::vector<py::ssize_t>(s1.shape(), s1.shape() + s1.ndim()));
        const py::ssize_t n = v1.size();
        for (py::ssize_t i = 0; i < n; i += 3) {
          double x1[3] = {0, 0, 0}, x2[3] = {0, 0, 0};
          for (py::ssize_t k = 0; k < 3 && i + k < n; ++k) {
            x1[k] = v1.data()[i + k];
            x2[k] = v2.data()[i + k];
          }
          const Color c =
              vector_interp(q1, q2, {x1[0], x1[1], x1[2]}, {x2[0], x2[1], x2[2]}, coord, dim);
          const double r[3] = {c.r, c.g, c.b};
          for (py::ssize_t k = 0; k < 3 && i + k < n; ++k) out.mutable_data()[i + k] = r[k];
        }
        if (out.ndim() == 0) return py::float_(out.data()[0]);
        return out;
      },
      py::arg("p1"), py::arg("p2"), py::arg("V1"), py::arg("V2"), py::arg("coord"), py::arg("dim"));
  m.def(
      "f_shading",
      [](py::object img, py::handle v, py::handle c) { return shade(img, v, c, Shading::flat); },
      py::arg("img"), py::arg("vertices"), py::arg("vcolors"));
  m.def(
      "g_shading",
      [](py::object img, py::handle v, py::handle c) { return shade(img, v, c, Shading::gouraud); },
      py::arg("img"), py::arg("vertices"), py::arg("vcolors"));
  m.def(
      "render",
      [](py::handle vertices, py::handle faces, py::handle vcolors, py::handle depth,
         const std::string& shading, const std::string& fill_rule, py::handle size,
         py::handle background, py::handle dtype) {
        const FillOptions opt = fill_options(shading, fill_rule);
        const Scene scene = scene_from_arrays(vertices, faces, vcolors, depth, size_argument(size),
                                              color_argument(background, "background"));
        return render_scene(scene, opt, dtype);
      },
      py::arg("vertices"), py::arg("faces"), py::arg("vcolors"), py::arg("depth"), py::kw_only(),
      py::arg("shading"), py::arg("fill_rule"), py::arg("size"), py::arg("background"),
      py::arg("dtype"));
  m.def(
      "load_scene",
      [](const std::string& path, const std::string& shading) {
        return scene_dict(load_scene_file(path, shading_argument(shading)));
      },
      py::arg("path"), py::arg("shading"));
  m.def(
      "write_png",
      [](py::handle img, const std::string& path) {
        const RgbImage image = float_image(img, "img");
        py::gil_scoped_release free;
        write_png(image, path);
      },
      py::arg("img"), py::arg("path"));
  // The library's own render of a scene file, for the tests and the benchmark: the C++ float
  // canvas (Image<Rgb32f>) the Python renders are compared with, and its time.
  m.def("_cpp_render_file", [](const std::string& path, const std::string& shading) {
    const Scene scene = load_scene_file(path, Shading::gouraud);
    FillOptions opt;
    opt.shading = shading_argument(shading);
    const RgbImage image = render(scene, opt);
    py::array_t<float> out({scene.height, scene.width, 3});
    std::memcpy(out.mutable_data(), image.pixels().data(), image.pixels().size_bytes());
    return out;
  });
  m.def("_cpp_render_seconds", [](const std::string& path, const std::string& shading, int n) {
    const Scene scene = load_scene_file(path, Shading::gouraud);
    FillOptions opt;
    opt.shading = shading_argument(shading);
    py::gil_scoped_release free;
    std::vector<double> times;
    for (int i = 0; i < n; ++i) {
      const auto t0 = std::chrono::steady_clock::now();
      const RgbImage image = render(scene, opt);
      times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      if (image.width() == 0) break;
    }
    return times;
  });
}

}  // namespace scantrace::python
