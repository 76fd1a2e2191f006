#pragma once
// The composer's own points, sizes, rectangles and colours (docs/design.md §6). They have OpenCV's
// names and OpenCV's semantics on purpose — a Rect's intersection, contains() over [x, x + width),
// a Scalar in BGR order — because the OpenCV backend must draw exactly what the composer meant,
// and a frame drawn through it must stay byte for byte what the code drew when it called OpenCV
// itself. Nothing here includes OpenCV: the types convert to and from any type with the same
// members (cv::Point, cv::Size, cv::Rect are such types), so callers holding OpenCV's types keep
// working while the composer never sees them.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <type_traits>

namespace scantrace::viz {

template <class T>
concept HasXY = requires(const T& t) {
  t.x;
  t.y;
};
template <class T>
concept HasSize = requires(const T& t) {
  t.width;
  t.height;
};
// Integer points and sizes convert to each other exactly; a point in double becomes an integer
// one only by an explicit rounding (OpenCV would round silently).
template <class T>
concept IntXY = HasXY<T> && !HasSize<T> && std::is_integral_v<decltype(T::x)>;
template <class T>
concept RealXY = HasXY<T> && !HasSize<T> && std::is_floating_point_v<decltype(T::x)>;
template <class T>
concept IntSize = HasSize<T> && !HasXY<T> && std::is_integral_v<decltype(T::width)>;
template <class T>
concept IntRect = HasSize<T> && HasXY<T> && std::is_integral_v<decltype(T::width)>;

struct Point {
  int x = 0, y = 0;
  constexpr Point() = default;
  constexpr Point(int x_, int y_) : x(x_), y(y_) {}
  template <IntXY P>
  constexpr Point(const P& p) : x(static_cast<int>(p.x)), y(static_cast<int>(p.y)) {}
  template <HasXY P>
  requires(!HasSize<P>) constexpr operator P() const { return P(x, y); }
  friend constexpr Point operator+(Point a, Point b) { return {a.x + b.x, a.y + b.y}; }
  friend constexpr Point operator-(Point a, Point b) { return {a.x - b.x, a.y - b.y}; }
  friend constexpr Point operator-(Point a) { return {-a.x, -a.y}; }
  friend constexpr bool operator==(Point a, Point b) = default;
};

struct Point2d {
  double x = 0, y = 0;
  constexpr Point2d() = default;
  constexpr Point2d(double x_, double y_) : x(x_), y(y_) {}
  template <RealXY P>
  constexpr Point2d(const P& p) : x(p.x), y(p.y) {}
  template <RealXY P>
  constexpr operator P() const {
    return P(x, y);
  }
  constexpr double dot(Point2d o) const { return x * o.x + y * o.y; }
  constexpr double cross(Point2d o) const { return x * o.y - y * o.x; }
  friend constexpr Point2d operator+(Point2d a, Point2d b) { return {a.x + b.x, a.y + b.y}; }
  friend constexpr Point2d operator-(Point2d a, Point2d b) { return {a.x - b.x, a.y - b.y}; }
  friend constexpr Point2d operator*(Point2d a, double s) { return {a.x * s, a.y * s}; }
  friend constexpr bool operator==(Point2d a, Point2d b) = default;
};

struct Size {
  int width = 0, height = 0;
  constexpr Size() = default;
  constexpr Size(int w, int h) : width(w), height(h) {}
  template <IntSize S>
  constexpr Size(const S& s)
      : width(static_cast<int>(s.width)), height(static_cast<int>(s.height)) {}
  template <IntSize S>
  constexpr operator S() const {
    return S(width, height);
  }
  constexpr int area() const { return width * height; }
  friend constexpr bool operator==(Size a, Size b) = default;
};

// Pixels [x, x + width) x [y, y + height), as cv::Rect.
struct Rect {
  int x = 0, y = 0, width = 0, height = 0;
  constexpr Rect() = default;
  constexpr Rect(int x_, int y_, int w, int h) : x(x_), y(y_), width(w), height(h) {}
  constexpr Rect(Point p, Size s) : x(p.x), y(p.y), width(s.width), height(s.height) {}
  // The rectangle spanned by two corners, `b` excluded (cv::Rect(pt1, pt2)).
  constexpr Rect(Point a, Point b)
      : x(std::min(a.x, b.x)),
        y(std::min(a.y, b.y)),
        width(std::max(a.x, b.x) - std::min(a.x, b.x)),
        height(std::max(a.y, b.y) - std::min(a.y, b.y)) {}
  template <IntRect R>
  constexpr Rect(const R& r)
      : x(static_cast<int>(r.x)),
        y(static_cast<int>(r.y)),
        width(static_cast<int>(r.width)),
        height(static_cast<int>(r.height)) {}
  template <IntRect R>
  constexpr operator R() const {
    return R(x, y, width, height);
  }

  constexpr Point tl() const { return {x, y}; }
  constexpr Point br() const { return {x + width, y + height}; }
  constexpr Size size() const { return {width, height}; }
  constexpr int area() const { return width * height; }
  constexpr bool empty() const { return width <= 0 || height <= 0; }
  constexpr bool contains(Point p) const {
    return x <= p.x && p.x < x + width && y <= p.y && p.y < y + height;
  }
  // The intersection; an empty one is Rect() (cv::Rect's operator&).
  friend constexpr Rect operator&(const Rect& a, const Rect& b) {
    const int x0 = std::max(a.x, b.x), y0 = std::max(a.y, b.y);
    const int w = std::min(a.x + a.width, b.x + b.width) - x0;
    const int h = std::min(a.y + a.height, b.y + b.height) - y0;
    if (w <= 0 || h <= 0) return {};
    return {x0, y0, w, h};
  }
  friend constexpr Rect operator+(const Rect& r, Point p) {
    return {r.x + p.x, r.y + p.y, r.width, r.height};
  }
  friend constexpr Rect operator-(const Rect& r, Point p) {
    return {r.x - p.x, r.y - p.y, r.width, r.height};
  }
  friend constexpr bool operator==(const Rect& a, const Rect& b) = default;
};

// OpenCV's rounding of a double to int (cvRound: to nearest, ties to even), which an implicit
// cv::Point2d -> cv::Point conversion applied.
inline int cv_round(double v) {
  return static_cast<int>(std::lrint(v));
}
inline Point cv_round(Point2d p) {
  return {cv_round(p.x), cv_round(p.y)};
}

struct Rect2d {
  double x = 0, y = 0, width = 0, height = 0;
};

// A colour in OpenCV's channel order (blue, green, red), 0..255.
struct Scalar {
  std::array<double, 4> v{};
  constexpr Scalar() = default;
  constexpr Scalar(double b, double g, double r, double a = 0) : v{b, g, r, a} {}
  constexpr double operator[](int i) const { return v[static_cast<std::size_t>(i)]; }
  friend constexpr bool operator==(const Scalar& a, const Scalar& b) = default;
};

// One 8-bit BGR pixel.
struct Vec3b {
  std::array<std::uint8_t, 3> v{};
  constexpr Vec3b() = default;
  constexpr Vec3b(std::uint8_t b, std::uint8_t g, std::uint8_t r) : v{b, g, r} {}
  constexpr std::uint8_t operator[](int i) const { return v[static_cast<std::size_t>(i)]; }
  constexpr std::uint8_t& operator[](int i) { return v[static_cast<std::size_t>(i)]; }
  // To any three-byte pixel type built from its bytes (cv::Vec3b among them).
  template <class V>
  requires(!std::is_same_v<V, Vec3b> && sizeof(V) == 3 &&
           std::is_constructible_v<V, std::uint8_t, std::uint8_t, std::uint8_t>) constexpr
  operator V() const {
    return V(v[0], v[1], v[2]);
  }
  friend constexpr bool operator==(const Vec3b& a, const Vec3b& b) = default;
  template <class V>
  requires(!std::is_same_v<V, Vec3b> && sizeof(V) == 3) friend constexpr bool operator==(
      const Vec3b& a, const V& b) {
    return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
  }
};

// OpenCV's drawing constants, by value (the backend passes them through).
inline constexpr int FILLED = -1;
enum class LineType { plain = 8, aa = 16 };  // cv::LINE_8, cv::LINE_AA
inline constexpr LineType LINE_8 = LineType::plain, LINE_AA = LineType::aa;

}  // namespace scantrace::viz
