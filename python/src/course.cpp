// The course's functions and the renders: numpy arrays in, numpy arrays out, the library's fill
// writing straight into the arrays (array_canvas.hpp).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <climits>
#include <cmath>
#include <condition_variable>
#include <cstring>
#include <memory>
#include <mutex>
#include <thread>

#include <time.h>

#include "array_canvas.hpp"
#include "arrays.hpp"
#include "casters.hpp"
#include "demo/demo_scene.hpp"
#include "io/mat_scene.hpp"
#include "io/memory_budget.hpp"
#include "io/obj_loader.hpp"
#include "io/png_writer.hpp"
#include "io/scene_json.hpp"
#include "src/fast/occlusion_choice.hpp"
#include "src/painter.hpp"
#include "src/shade_mesh.hpp"
#include "src/vector_interp.hpp"

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
  // A non-contiguous view (img[::2], a transposed array) or one of the other byte order ('>f8')
  // is filled through a contiguous native copy that is written back (numpy converting the byte
  // order), so the caller's array is still the one that changes, with the right values.
  const bool native = target.dtype().attr("isnative").cast<bool>();
  const bool direct = native && (target.flags() & py::array::c_style) != 0;
  py::array work = direct ? target
                          : py::array(py::module_::import("numpy").attr("ascontiguousarray")(
                                target, target.dtype().attr("newbyteorder")("=")));
  if (work.itemsize() == 8)
    fill_array<Rgb64>(work, v, c, opt);
  else
    fill_array<Rgb32f>(work, v, c, opt);
  if (!direct) target.attr("__setitem__")(py::ellipsis(), work);
  return img;
}

// A long render runs on a worker thread while this one, holding the GIL only for that, checks for
// signals every 50 ms: Ctrl-C then raises KeyboardInterrupt at once. The core has no way to stop a
// render halfway, so an interrupted worker is left to finish on its own (it owns its scene and
// image through the shared Job) and its result is dropped. A short one (`long_run` false) runs
// here without the GIL: handing a 2 ms render to another thread cost 1-5 ms of scheduling on a
// busy machine (the course scene's render_img went from 1.2 to 3-6 times the C++ render).
template <class Work>
void run_interruptibly(Work work, bool long_run) {
  if (!long_run) {
    py::gil_scoped_release free;
    work();
    return;
  }
  struct Job {
    std::mutex m;
    std::condition_variable cv;
    bool done = false;
    std::exception_ptr error;
  };
  auto job = std::make_shared<Job>();
  std::thread worker([job, work = std::move(work)]() mutable {
    try {
      work();
    } catch (...) {
      job->error = std::current_exception();
    }
    const std::lock_guard lock(job->m);
    job->done = true;
    job->cv.notify_all();
  });
  bool interrupted = false;
  {
    py::gil_scoped_release free;
    std::unique_lock lock(job->m);
    while (!job->cv.wait_for(lock, std::chrono::milliseconds(50), [&] { return job->done; })) {
      lock.unlock();
      {
        py::gil_scoped_acquire gil;
        interrupted = PyErr_CheckSignals() != 0;
      }
      if (interrupted) break;
      lock.lock();
    }
  }
  if (interrupted) {
    worker.detach();
    throw py::error_already_set();  // KeyboardInterrupt (or what the signal handler raised)
  }
  worker.join();
  if (job->error) std::rethrow_exception(job->error);
}

// The storage of the last render whose array Python has let go of, kept for the next render of
// the same pixel type. Why: a fresh image is memory the kernel must zero when the render first
// touches it (huge pages, image.cpp), 8 MiB for the course's 512 x 512 float64 canvas: perf put
// 11% of render_img in clear_page_erms. A loop that renders and drops (`img = render_img(...)`
// in a cell run again, a benchmark, a grader) reuses one buffer instead. One slot per pixel type,
// images of at most kRecycledBytes only: what stays allocated after the arrays are gone is
// bounded. The slot is touched only with the GIL held (capsule destructors, render_array before
// it releases it), the mutex is for clarity should that ever change.
constexpr std::size_t kRecycledBytes = std::size_t{64} << 20;

template <class P>
class RecycledImage {
 public:
  static std::shared_ptr<Image<P>> take() {
    const std::lock_guard lock(mutex());
    auto& s = slot();
    return s ? std::move(s) : std::make_shared<Image<P>>();
  }
  // Called when the last array over `image` is gone: kept if no worker still writes it (an
  // interrupted render) and it is small enough.
  static void give_back(std::shared_ptr<Image<P>>&& image) {
    if (image.use_count() != 1 || image->pixels().size_bytes() > kRecycledBytes) return;
    const std::lock_guard lock(mutex());
    slot() = std::move(image);
  }

 private:
  static std::shared_ptr<Image<P>>& slot() {
    static std::shared_ptr<Image<P>> s;
    return s;
  }
  static std::mutex& mutex() {
    static std::mutex m;
    return m;
  }
};

// The scene as the command renders it (the library's render(): far to near, or near to far for a
// scene of high overdraw, into an Image of the array's own pixel type: Rgb64 holds the float
// canvas's values widened, array_canvas.hpp), and the image handed to numpy without a copy. The
// image is shared by the array and the worker: an interrupted render's worker may still write it
// after the array is gone, and the last one frees it. (Rendering near to far into the library's
// float Image and copying it into the array cost the course scene's render_img 1.4 times the C++
// render; python/bench/bench_render_img.py.)
template <class P>
py::array render_array(Scene scene, const FillOptions& opt) {
  using T = decltype(P::r);
  static_assert(sizeof(P) == 3 * sizeof(T));
  std::shared_ptr<Image<P>> image = RecycledImage<P>::take();
  auto shared = std::make_shared<const Scene>(std::move(scene));
  // The choice too runs on the worker: estimating the overdraw of a million large faces takes
  // seconds, which Ctrl-C must be able to interrupt. What takes a worker: 2^16 faces or more, or
  // a canvas of 2^22 pixels (2048²) or more, renders of tens of milliseconds and up.
  const bool long_run =
      shared->faces.size() >= (1u << 16) ||
      static_cast<std::size_t>(shared->width) * shared->height >= (std::size_t{1} << 22);
  run_interruptibly(
      [shared, opt, image] {
        RenderScratch scratch;
        NoTracer none;
        render(*image, *shared, opt, scratch, none);
      },
      long_run);
  auto* owner = new std::shared_ptr<Image<P>>(image);
  py::capsule free(owner, [](void* p) {
    auto* held = static_cast<std::shared_ptr<Image<P>>*>(p);
    RecycledImage<P>::give_back(std::move(*held));
    delete held;
  });
  T* data = image->width() ? &image->row(0)->r : nullptr;
  return py::array_t<T>({image->height(), image->width(), 3}, data, free);
}

py::array render_scene(Scene scene, const FillOptions& opt, py::handle dtype) {
  const py::dtype dt = py::dtype::from_args(py::reinterpret_borrow<py::object>(dtype));
  if (dt.is(py::dtype::of<double>()) || dt.equal(py::dtype::of<double>()))
    return render_array<Rgb64>(std::move(scene), opt);
  if (dt.equal(py::dtype::of<float>())) return render_array<Rgb32f>(std::move(scene), opt);
  if (dt.equal(py::dtype::of<std::uint8_t>())) {
    // The bytes of the PNG the command line writes: round(255·c) of the float canvas.
    const py::array_t<float> f = render_array<Rgb32f>(std::move(scene), opt);
    py::array_t<std::uint8_t> out({f.shape(0), f.shape(1), py::ssize_t{3}});
    const float* in = f.data();
    std::uint8_t* o = out.mutable_data();
    for (py::ssize_t i = 0; i < f.size(); ++i) o[i] = to_byte(in[i]);
    return out;
  }
  throw_type_error("dtype: expected float64, float32 or uint8, got " +
                   py::str(static_cast<py::handle>(dt)).cast<std::string>());
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
  // The size first, as f_shading's: a large strided array would otherwise be copied to float64
  // before anything is said.
  const py::array raw = py::module_::import("numpy").attr("asarray")(img);
  if (raw.ndim() == 3 && raw.shape(2) == 3) {
    const py::ssize_t h = raw.shape(0), w = raw.shape(1);
    if (h > INT_MAX || w > INT_MAX || h * w > kMaxCanvasPixels)
      throw_value_error(std::string(name) + ": image of " + std::to_string(w) + "x" +
                        std::to_string(h) + " pixels is too large (at most 2^28)");
    // A float64 copy, the float image and the PNG's rows.
    check_memory(static_cast<std::uint64_t>(h * w) * (24 + 12 + 3), "writing this PNG", name, "");
  }
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
  if (is_mat_file(path)) return load_mat_scene(path);
  if (is_obj_file(path)) {
    ShadeOptions o;  // the command line's defaults for a model
    o.shading = obj_shading;
    return shade_mesh(load_obj(path), o);
  }
  return load_scene(path);
}

namespace {

// The course's vector_interp on values of any shape (the C++ function interpolates colours).
py::object vector_interp_values(py::handle p1, py::handle p2, py::handle V1, py::handle V2,
                                double coord, int dim) {
  const DoubleArray a = float_array(p1, "p1", {2}), b = float_array(p2, "p2", {2});
  const py::array s1 = py::module_::import("numpy").attr("asarray")(V1);
  std::vector<Dim> shape;
  for (py::ssize_t i = 0; i < s1.ndim(); ++i) shape.push_back(Dim(s1.shape(i)));
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
    const Color c = vector_interp(q1, q2, {x1[0], x1[1], x1[2]}, {x2[0], x2[1], x2[2]}, coord, dim);
    const double r[3] = {c.r, c.g, c.b};
    for (py::ssize_t k = 0; k < 3 && i + k < n; ++k) out.mutable_data()[i + k] = r[k];
  }
  if (out.ndim() == 0) return py::float_(out.data()[0]);
  return out;
}

}  // namespace

// The course's four functions: vector_interp, f_shading, g_shading, and render (render_img's
// core).
void bind_course_functions(py::module_& m) {
  m.def("vector_interp", &vector_interp_values, py::arg("p1"), py::arg("p2"), py::arg("V1"),
        py::arg("V2"), py::arg("coord"), py::arg("dim"));
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
        Scene scene = scene_from_arrays(vertices, faces, vcolors, depth, size_argument(size),
                                        color_argument(background, "background"));
        return render_scene(std::move(scene), opt, dtype);
      },
      py::arg("vertices"), py::arg("faces"), py::arg("vcolors"), py::arg("depth"), py::kw_only(),
      py::arg("shading"), py::arg("fill_rule"), py::arg("size"), py::arg("background"),
      py::arg("dtype"));
}

// Scenes and images in and out: the demo scene, scene files, PNG files.
void bind_scene_io(py::module_& m) {
  m.def("demo_scene", [] { return scene_dict(demo_scene()); });
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
        png::write(image, path);
      },
      py::arg("img"), py::arg("path"));
}

// The library's own render of a scene file, for the tests and the benchmark: the C++ float
// canvas (Image<Rgb32f>) the Python renders are compared with, and its time.
void bind_cpp_reference(py::module_& m) {
  m.def("_cpp_render_file", [](const std::string& path, const std::string& shading) {
    const Scene scene = load_scene_file(path, Shading::gouraud);
    FillOptions opt;
    opt.shading = shading_argument(shading);
    const RgbImage image = render(scene, opt);
    py::array_t<float> out({scene.height, scene.width, 3});
    std::memcpy(out.mutable_data(), image.pixels().data(), image.pixels().size_bytes());
    return out;
  });
  // clock "wall" (steady_clock) or "cpu" (this thread's CPU time, CLOCK_THREAD_CPUTIME_ID, as
  // Python's time.thread_time): on two cores shared with other jobs, a render's wall time
  // includes the time it waited for a core, its CPU time does not.
  // pixel "float32": the library's render into a fresh Image<Rgb32f> (the float canvas of
  // `scantrace render`), the reference render_img is held to; "float64": the render render_img
  // runs, into the recycled Image<Rgb64> (render_array), without Python: what the float64 pixels
  // cost in C++ alone (python/bench/bench_render_img.py prints both).
  m.def(
      "_cpp_render_seconds",
      [](const std::string& path, const std::string& shading, int n, const std::string& clock,
         const std::string& pixel) {
        if (clock != "wall" && clock != "cpu")
          throw_value_error("clock: expected 'wall' or 'cpu', got '" + clock + "'");
        if (pixel != "float32" && pixel != "float64")
          throw_value_error("pixel: expected 'float32' or 'float64', got '" + pixel + "'");
        const bool cpu = clock == "cpu", wide = pixel == "float64";
        const Scene scene = load_scene_file(path, Shading::gouraud);
        FillOptions opt;
        opt.shading = shading_argument(shading);
        py::gil_scoped_release free;
        const auto now = [cpu] {
          if (!cpu)
            return std::chrono::duration<double>(
                       std::chrono::steady_clock::now().time_since_epoch())
                .count();
          timespec t{};
          clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
          return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
        };
        std::vector<double> times;
        for (int i = 0; i < n; ++i) {
          const double t0 = now();
          if (wide) {
            std::shared_ptr<Image<Rgb64>> image = RecycledImage<Rgb64>::take();
            RenderScratch scratch;
            NoTracer none;
            render(*image, scene, opt, scratch, none);
            times.push_back(now() - t0);
            RecycledImage<Rgb64>::give_back(std::move(image));
            continue;
          }
          const RgbImage image = render(scene, opt);
          times.push_back(now() - t0);
          if (image.width() == 0) break;
        }
        return times;
      },
      py::arg("path"), py::arg("shading"), py::arg("n"), py::arg("clock") = "wall",
      py::arg("pixel") = "float32");
}

void bind_course(py::module_& m) {
  bind_course_functions(m);
  bind_scene_io(m);
  bind_cpp_reference(m);
}

}  // namespace scantrace::python
