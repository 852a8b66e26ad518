#pragma once
// A 3-vector usable on host and device. 2D runs use the x-z plane with y = 0 (x is the
// flow direction, z points up), so every formula is written once, in 3D.
#include <cmath>

#include "netsph/core/host_device.hpp"

namespace netsph {

template <typename T>
struct Vec3 {
  T x{}, y{}, z{};

  NETSPH_HD constexpr Vec3() = default;
  NETSPH_HD constexpr Vec3(T x_, T y_, T z_) : x(x_), y(y_), z(z_) {}
  template <typename U>
  NETSPH_HD constexpr explicit Vec3(const Vec3<U>& o)
      : x(static_cast<T>(o.x)), y(static_cast<T>(o.y)), z(static_cast<T>(o.z)) {}

  NETSPH_HD constexpr T& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
  NETSPH_HD constexpr T operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }

  NETSPH_HD constexpr Vec3& operator+=(const Vec3& o) {
    x += o.x, y += o.y, z += o.z;
    return *this;
  }
  NETSPH_HD constexpr Vec3& operator-=(const Vec3& o) {
    x -= o.x, y -= o.y, z -= o.z;
    return *this;
  }
  NETSPH_HD constexpr Vec3& operator*=(T s) {
    x *= s, y *= s, z *= s;
    return *this;
  }
};

template <typename T>
NETSPH_HD constexpr Vec3<T> operator+(Vec3<T> a, const Vec3<T>& b) {
  return a += b;
}
template <typename T>
NETSPH_HD constexpr Vec3<T> operator-(Vec3<T> a, const Vec3<T>& b) {
  return a -= b;
}
template <typename T>
NETSPH_HD constexpr Vec3<T> operator-(const Vec3<T>& a) {
  return {-a.x, -a.y, -a.z};
}
template <typename T>
NETSPH_HD constexpr Vec3<T> operator*(Vec3<T> a, T s) {
  return a *= s;
}
template <typename T>
NETSPH_HD constexpr Vec3<T> operator*(T s, Vec3<T> a) {
  return a *= s;
}
template <typename T>
NETSPH_HD constexpr Vec3<T> operator/(Vec3<T> a, T s) {
  return a *= (T(1) / s);
}
template <typename T>
NETSPH_HD constexpr bool operator==(const Vec3<T>& a, const Vec3<T>& b) {
  return a.x == b.x && a.y == b.y && a.z == b.z;
}

/// By value: a reference would make the operands addressable, which keeps GCC from
/// vectorising `omp simd` loops that call it (sph/pair_interaction.hpp).
template <typename T>
NETSPH_HD constexpr T dot(Vec3<T> a, Vec3<T> b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <typename T>
NETSPH_HD constexpr Vec3<T> cross(const Vec3<T>& a, const Vec3<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <typename T>
NETSPH_HD constexpr T norm2(const Vec3<T>& a) {
  return dot(a, a);
}
template <typename T>
NETSPH_HD T norm(const Vec3<T>& a) {
  return std::sqrt(dot(a, a));
}

using Vec3f = Vec3<float>;
using Vec3d = Vec3<double>;

}  // namespace netsph
