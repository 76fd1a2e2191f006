#include "io/mat_scene.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <matio.h>

#include "io/json_input.hpp"
#include "io/mat5_layout.hpp"
#include "io/memory_budget.hpp"

namespace scantrace {
namespace {

// A numeric MATLAB matrix converted to double, in MATLAB's column-major order: element (r, c)
// (0-based here) is data[r + c * rows].
struct Matrix {
  std::size_t rows = 0, cols = 0;
  std::vector<double> data;
  double at(std::size_t r, std::size_t c) const { return data[r + c * rows]; }
};

struct MatCloser {
  void operator()(mat_t* m) const { Mat_Close(m); }
};
struct VarFreer {
  void operator()(matvar_t* v) const { Mat_VarFree(v); }
};

const char* class_name(matio_classes c) {
  switch (c) {
    case MAT_C_CELL:
      return "a cell array";
    case MAT_C_STRUCT:
      return "a struct";
    case MAT_C_OBJECT:
      return "an object";
    case MAT_C_CHAR:
      return "a char array";
    case MAT_C_SPARSE:
      return "a sparse matrix";
    case MAT_C_FUNCTION:
      return "a function handle";
    case MAT_C_OPAQUE:
      return "an opaque object";
    default:
      return "of an unsupported class";
  }
}

template <class T>
void convert(const matvar_t& v, std::vector<double>& out) {
  const T* p = static_cast<const T*>(v.data);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = static_cast<double>(p[i]);
}

// matio reports problems through a log function, by default to stderr: a second, differently
// worded line after ours. Its last message is kept instead and added to a "damaged file" error.
thread_local std::string last_matio_message;

void keep_matio_message(int, char* message) {
  last_matio_message = message ? message : "";
}

std::string row_name(const char* var, std::size_t row) {
  return std::string(var) + "(" + std::to_string(row + 1) + ",:)";
}

class MatReader {
 public:
  MatReader(const std::filesystem::path& file, ColorClamping* clamping)
      : name_(file.string()), clamping_(clamping) {
    static const int quiet = Mat_LogInitFunc("scantrace", keep_matio_message);
    (void)quiet;
    last_matio_message.clear();
    // The whole file is read first (a FIFO or a device refused, its size against the memory
    // budget), and a v5 file's layout checked: matio reads a variable's values by the count its
    // dimensions declare, whatever its data element holds (io/mat5_layout.hpp).
    const std::string bytes = json_input::read_text_file(file);
    refuse_unless_v5(bytes);
    if (const auto problem = mat5_layout_problem(bytes)) fail(problem->element, problem->problem);
    mat_.reset(Mat_Open(name_.c_str(), MAT_ACC_RDONLY));
    if (!mat_) fail("", "not a readable MATLAB .mat file");
  }

  Scene read() {
    const Matrix vertices = matrix("vertices_2d", "L x 2 (one [x, y] row per vertex)", 2);
    const std::size_t n = vertices.rows;
    const Matrix faces = matrix("faces", "K x 3 (one row of 1-based vertex indices per face)", 3);
    const Matrix colors = matrix("vertex_colors", "L x 3 (one [r, g, b] row per vertex)", 3);
    const Matrix depth = column("depth");
    if (colors.rows != n)
      fail("vertex_colors",
           "has " + std::to_string(colors.rows) + " rows but vertices_2d has " + std::to_string(n));
    if (depth.data.size() != n)
      fail("depth", "has " + std::to_string(depth.data.size()) + " entries but vertices_2d has " +
                        std::to_string(n) + " rows");

    Scene s;
    s.vertices.resize(n);
    s.vcolors.resize(n);
    s.depth = depth.data;
    // The 2021 course's MATLAB code uses the coordinates as 1-based pixel indices, as it does
    // the face indices (img(floor(y + 0.5), floor(x + 0.5), :)): its pixel (1, 1) is scantrace's
    // pixel (0, 0), centred at the point (0, 0). Without the - 1 every 2021 render is one pixel
    // right and down of that course's, and `diff` calls a correct image `shifted`.
    for (std::size_t i = 0; i < n; ++i) {
      s.vertices[i] = {vertices.at(i, 0) - 1, vertices.at(i, 1) - 1};
      s.vcolors[i] = {colors.at(i, 0), colors.at(i, 1), colors.at(i, 2)};
      if (clamping_) clamp(s.vcolors[i], row_name("vertex_colors", i));
    }
    // MATLAB indices are 1-based: faces(k,:) = [1 2 3] is scantrace's faces[k-1] = {0, 1, 2}.
    s.faces.resize(faces.rows);
    for (std::size_t k = 0; k < faces.rows; ++k)
      for (std::size_t c = 0; c < 3; ++c) {
        const double v = faces.at(k, c);
        if (!(v == std::floor(v)))
          fail(row_name("faces", k), "vertex index " + number(v) + " is not an integer");
        if (v < 1 || v > static_cast<double>(n))
          fail(row_name("faces", k), "vertex index " + number(v) + " is out of range 1.." +
                                         std::to_string(n) + " (MATLAB indices start at 1)");
        s.faces[k][c] = static_cast<int>(v) - 1;
      }
    if (const auto problem = validate(s)) fail(matlab_element(problem->element), problem->problem);
    return s;
  }

 private:
  [[noreturn]] void fail(const std::string& element, const std::string& problem) const {
    throw InputError(name_, element, problem);
  }

  // matio would open v4 and v7.3 files too, but neither can be checked before it reads them.
  // A v7.3 file is HDF5, and HDF5 is not hardened against crafted files: CI's 12-second fuzz run
  // found a heap-buffer-overflow inside libhdf5 (a memcpy past a 280-byte block of its own, below
  // matio's Mat_VarReadInfo) and a leak of its metadata cache, and HDF5's CVE list is long. A v4
  // file has no header at all (any bytes are a v4 file to matio) and matio reads its values by
  // the count its dimensions declare. MATLAB saves v7 (a compressed v5) unless told otherwise,
  // and the course's scene is v5: one line says how to re-save the others.
  void refuse_unless_v5(std::string_view bytes) const {
    switch (mat_file_version(bytes)) {
      case MatFileVersion::v5:
        return;
      case MatFileVersion::v73:
        fail("", "is a MATLAB v7.3 (HDF5) file, which scantrace does not read (HDF5 is not safe "
                 "on untrusted files); re-save it as v7: save('scene.mat', ..., '-v7')");
      case MatFileVersion::other:
        fail("", "is not a MATLAB v5/v7 .mat file (no v5 header; v4 and v7.3 files are not read); "
                 "re-save it as v7: save('scene.mat', ..., '-v7')");
    }
  }

  static std::string damaged() {
    return std::string("cannot be read (damaged file?)") +
           (last_matio_message.empty() ? "" : " (matio: " + last_matio_message + ")");
  }

  static std::string number(double v) {
    std::string s = std::to_string(v);
    // 5012.000000 -> 5012; 2.500000 -> 2.5
    if (s.find('.') != std::string::npos) {
      s.erase(s.find_last_not_of('0') + 1);
      if (s.back() == '.') s.pop_back();
    }
    return s;
  }

  // validate() names scantrace's arrays ("vcolors[3]"); the user knows the file's variables.
  static std::string matlab_element(const std::string& element) {
    const auto open = element.find('[');
    if (open == std::string::npos || element.back() != ']') return element;
    const std::string array = element.substr(0, open);
    const std::size_t index = std::stoull(element.substr(open + 1));
    if (array == "vertices") return row_name("vertices_2d", index);
    if (array == "vcolors") return row_name("vertex_colors", index);
    if (array == "depth") return "depth(" + std::to_string(index + 1) + ")";
    return element;
  }

  void clamp(Color& c, const std::string& element) const {
    bool changed = false;
    for (double* v : {&c.r, &c.g, &c.b})
      if (std::isfinite(*v) && (*v < 0.0 || *v > 1.0)) {
        *v = std::clamp(*v, 0.0, 1.0);
        changed = true;
      }
    if (changed && clamping_->clamped++ == 0) clamping_->first = element;
  }

  // The variable `var` as a real numeric matrix of any class, converted to double.
  Matrix numeric(const char* var) {
    // The header first: class and size are checked before the data is read (and allocated).
    std::unique_ptr<matvar_t, VarFreer> info(Mat_VarReadInfo(mat_.get(), var));
    if (!info)
      fail(var, "missing variable (a scene .mat holds vertices_2d, faces, vertex_colors, depth)");
    check_numeric(*info, var);
    if (info->rank != 2)
      fail(var, "has " + std::to_string(info->rank) + " dimensions, expected a matrix");
    Matrix m{info->dims[0], info->dims[1], {}};
    const std::uint64_t count = static_cast<std::uint64_t>(m.rows) * m.cols;
    check_memory(count * (sizeof(double) + 8), "variable " + std::string(var), name_, var);
    info.reset();

    std::unique_ptr<matvar_t, VarFreer> v(Mat_VarRead(mat_.get(), var));
    if (!v) fail(var, damaged());
    check_numeric(*v, var);
    if (v->rank != 2 || v->dims[0] != m.rows || v->dims[1] != m.cols) fail(var, damaged());
    m.data.resize(count);
    if (count == 0) return m;
    if (!v->data || v->nbytes < count * static_cast<std::uint64_t>(v->data_size))
      fail(var, damaged());
    switch (v->class_type) {
      case MAT_C_DOUBLE:
        convert<double>(*v, m.data);
        break;
      case MAT_C_SINGLE:
        convert<float>(*v, m.data);
        break;
      case MAT_C_INT8:
        convert<std::int8_t>(*v, m.data);
        break;
      case MAT_C_UINT8:
        convert<std::uint8_t>(*v, m.data);
        break;
      case MAT_C_INT16:
        convert<std::int16_t>(*v, m.data);
        break;
      case MAT_C_UINT16:
        convert<std::uint16_t>(*v, m.data);
        break;
      case MAT_C_INT32:
        convert<std::int32_t>(*v, m.data);
        break;
      case MAT_C_UINT32:
        convert<std::uint32_t>(*v, m.data);
        break;
      case MAT_C_INT64:
        convert<std::int64_t>(*v, m.data);
        break;
      case MAT_C_UINT64:
        convert<std::uint64_t>(*v, m.data);
        break;
      default:  // check_numeric() let only the classes above through
        fail(var, damaged());
    }
    return m;
  }

  void check_numeric(const matvar_t& v, const char* var) const {
    switch (v.class_type) {
      case MAT_C_DOUBLE:
      case MAT_C_SINGLE:
      case MAT_C_INT8:
      case MAT_C_UINT8:
      case MAT_C_INT16:
      case MAT_C_UINT16:
      case MAT_C_INT32:
      case MAT_C_UINT32:
      case MAT_C_INT64:
      case MAT_C_UINT64:
        break;
      default:
        fail(var, std::string("is ") + class_name(v.class_type) + ", expected a numeric matrix");
    }
    if (v.isComplex) fail(var, "is complex, expected a real matrix");
    if (v.rank < 0 || !v.dims) fail(var, damaged());
  }

  Matrix matrix(const char* var, const char* shape, std::size_t cols) {
    Matrix m = numeric(var);
    if (m.cols != cols)
      fail(var,
           "is " + std::to_string(m.rows) + "x" + std::to_string(m.cols) + ", expected " + shape);
    return m;
  }

  Matrix column(const char* var) {
    Matrix m = numeric(var);
    if (m.cols != 1 && m.rows != 1)
      fail(var, "is " + std::to_string(m.rows) + "x" + std::to_string(m.cols) +
                    ", expected L x 1 (one depth per vertex)");
    return m;
  }

  std::string name_;
  ColorClamping* clamping_;
  std::unique_ptr<mat_t, MatCloser> mat_;
};

}  // namespace

Scene load_mat_scene(const std::filesystem::path& file, ColorClamping* clamping) {
  return within_memory(file.string(), [&] { return MatReader(file, clamping).read(); });
}

}  // namespace scantrace
