// common/deform/mat.h — the 2 x 2 and 3 x 3 matrices of a deformation's
// Jacobian: products, determinants, the cofactor matrix and the inverse.
//
// A Jacobian is stored by columns, the partial derivatives: J = [Xs Xt Xu]
// (3-D) or J = [fx fy] (2-D), so J a = a.x Xs + a.y Xt + a.z Xu.
#pragma once

#include "spline/vec.h"

namespace gllab::deform {

using spline::Vec2;
using spline::Vec3;

struct Mat2 {
  Vec2 c0{1, 0}, c1{0, 1};  // columns; the default is the identity
};

struct Mat3 {
  Vec3 c0{1, 0, 0}, c1{0, 1, 0}, c2{0, 0, 1};  // columns; the default is the identity
};

constexpr Vec2 operator*(const Mat2& a, Vec2 v) { return v.x * a.c0 + v.y * a.c1; }
constexpr Vec3 operator*(const Mat3& a, Vec3 v) { return v.x * a.c0 + v.y * a.c1 + v.z * a.c2; }
constexpr Mat3 operator*(const Mat3& a, const Mat3& b) { return {a * b.c0, a * b.c1, a * b.c2}; }
constexpr Mat2 operator*(const Mat2& a, const Mat2& b) { return {a * b.c0, a * b.c1}; }

constexpr double det(const Mat2& a) { return cross(a.c0, a.c1); }
/// The triple product c0 . (c1 x c2): the signed volume of the parallelepiped
/// the columns span.
constexpr double det(const Mat3& a) { return dot(a.c0, cross(a.c1, a.c2)); }

constexpr Mat3 transpose(const Mat3& a) {
  return {{a.c0.x, a.c1.x, a.c2.x}, {a.c0.y, a.c1.y, a.c2.y}, {a.c0.z, a.c1.z, a.c2.z}};
}

/// The cofactor matrix cof(A) = det(A) A^-T, columns (c1 x c2, c2 x c0,
/// c0 x c1). It maps the cross product of two vectors as A maps the vectors:
///   (A a) x (A b) = cof(A) (a x b),
/// so it carries a surface normal through the map A, with its orientation,
/// and needs no division (it is defined when det A = 0, too).
constexpr Mat3 cofactor(const Mat3& a) {
  return {cross(a.c1, a.c2), cross(a.c2, a.c0), cross(a.c0, a.c1)};
}

/// A^-1 = cof(A)^T / det A. The caller checks det A != 0.
constexpr Mat3 inverse(const Mat3& a) {
  const Mat3 t = transpose(cofactor(a));
  const double d = det(a);
  return {t.c0 / d, t.c1 / d, t.c2 / d};
}
constexpr Mat2 inverse(const Mat2& a) {
  const double d = det(a);
  return {Vec2{a.c1.y, -a.c0.y} / d, Vec2{-a.c1.x, a.c0.x} / d};
}

}  // namespace gllab::deform
