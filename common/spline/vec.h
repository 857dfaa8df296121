// common/spline/vec.h — the small vectors the spline core computes with.
//
// Points are Vec3 everywhere; a 2D point has z = 0 (files remember whether a
// curve was 2D). Trim curves live in the (u, v) domain as Vec2. Homogeneous
// (rational) points are Vec4 = (w*x, w*y, w*z, w), the form GLU takes.
#pragma once

#include <cmath>

namespace gllab::spline {

struct Vec2 {
  double x = 0, y = 0;
};

struct Vec3 {
  double x = 0, y = 0, z = 0;
};

struct Vec4 {
  double x = 0, y = 0, z = 0, w = 0;
};

// --- Vec2 ---------------------------------------------------------------------
constexpr Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
constexpr Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
constexpr Vec2 operator-(Vec2 a) { return {-a.x, -a.y}; }
constexpr Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
constexpr Vec2 operator*(Vec2 a, double s) { return {s * a.x, s * a.y}; }
constexpr Vec2 operator/(Vec2 a, double s) { return {a.x / s, a.y / s}; }
constexpr Vec2& operator+=(Vec2& a, Vec2 b) { return a = a + b; }
constexpr Vec2& operator-=(Vec2& a, Vec2 b) { return a = a - b; }
constexpr bool operator==(Vec2 a, Vec2 b) { return a.x == b.x && a.y == b.y; }
constexpr bool operator!=(Vec2 a, Vec2 b) { return !(a == b); }
constexpr double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
/// The z component of the 3D cross product: > 0 when b turns left of a.
constexpr double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
inline double norm(Vec2 a) { return std::hypot(a.x, a.y); }

// --- Vec3 ---------------------------------------------------------------------
constexpr Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
constexpr Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
constexpr Vec3 operator-(Vec3 a) { return {-a.x, -a.y, -a.z}; }
constexpr Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
constexpr Vec3 operator*(Vec3 a, double s) { return {s * a.x, s * a.y, s * a.z}; }
constexpr Vec3 operator/(Vec3 a, double s) { return {a.x / s, a.y / s, a.z / s}; }
constexpr Vec3& operator+=(Vec3& a, Vec3 b) { return a = a + b; }
constexpr Vec3& operator-=(Vec3& a, Vec3 b) { return a = a - b; }
constexpr Vec3& operator*=(Vec3& a, double s) { return a = s * a; }
constexpr bool operator==(Vec3 a, Vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }
constexpr bool operator!=(Vec3 a, Vec3 b) { return !(a == b); }
constexpr double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm(Vec3 a) { return std::sqrt(dot(a, a)); }
/// a / |a|; the zero vector stays zero (callers that need a direction check first).
inline Vec3 normalized(Vec3 a) {
  const double n = norm(a);
  return n > 0 ? a / n : a;
}
constexpr Vec3 lerp(Vec3 a, Vec3 b, double t) { return (1 - t) * a + t * b; }

// --- Vec4 (homogeneous) ------------------------------------------------------
constexpr Vec4 operator+(Vec4 a, Vec4 b) { return {a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w}; }
constexpr Vec4 operator-(Vec4 a, Vec4 b) { return {a.x - b.x, a.y - b.y, a.z - b.z, a.w - b.w}; }
constexpr Vec4 operator*(double s, Vec4 a) { return {s * a.x, s * a.y, s * a.z, s * a.w}; }
constexpr Vec4 operator*(Vec4 a, double s) { return s * a; }
constexpr Vec4& operator+=(Vec4& a, Vec4 b) { return a = a + b; }
constexpr bool operator==(Vec4 a, Vec4 b) { return a.x == b.x && a.y == b.y && a.z == b.z && a.w == b.w; }

/// (w*P, w): the premultiplied form GLU's *_VERTEX_4 maps take.
constexpr Vec4 homogeneous(Vec3 p, double w) { return {w * p.x, w * p.y, w * p.z, w}; }
/// P = (x/w, y/w, z/w). The caller guarantees w != 0.
constexpr Vec3 project(Vec4 h) { return {h.x / h.w, h.y / h.w, h.z / h.w}; }
constexpr Vec3 xyz(Vec4 h) { return {h.x, h.y, h.z}; }

}  // namespace gllab::spline
