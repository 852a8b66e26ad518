#pragma once
// Unit quaternions for rigid-body orientation (Hamilton convention, q = w + xi + yj + zk).
// rotate(q, v) maps body-frame vectors to the world frame.
#include <cmath>

#include "netsph/core/host_device.hpp"
#include "netsph/core/vec3.hpp"

namespace netsph {

struct Quat {
  double w = 1, x = 0, y = 0, z = 0;

  /// Rotation by `angle` (rad) about the unit vector `axis`.
  static Quat from_axis_angle(const Vec3d& axis, double angle) {
    const double n = norm(axis);
    if (!(n > 0)) return {};
    const double s = std::sin(0.5 * angle) / n;
    return {std::cos(0.5 * angle), axis.x * s, axis.y * s, axis.z * s};
  }
  /// The rotation taking the body axes x, y, z to the orthonormal right-handed world
  /// directions ex, ey, ez (Shepperd's method: the largest of the four squares first).
  static Quat from_frame(const Vec3d& ex, const Vec3d& ey, const Vec3d& ez) {
    const double m00 = ex.x, m11 = ey.y, m22 = ez.z, trace = m00 + m11 + m22;
    Quat q;
    if (trace > 0) {
      const double s = 0.5 / std::sqrt(trace + 1);
      q = {0.25 / s, (ey.z - ez.y) * s, (ez.x - ex.z) * s, (ex.y - ey.x) * s};
    } else if (m00 > m11 && m00 > m22) {
      const double s = 2 * std::sqrt(1 + m00 - m11 - m22);
      q = {(ey.z - ez.y) / s, 0.25 * s, (ey.x + ex.y) / s, (ez.x + ex.z) / s};
    } else if (m11 > m22) {
      const double s = 2 * std::sqrt(1 + m11 - m00 - m22);
      q = {(ez.x - ex.z) / s, (ey.x + ex.y) / s, 0.25 * s, (ez.y + ey.z) / s};
    } else {
      const double s = 2 * std::sqrt(1 + m22 - m00 - m11);
      q = {(ex.y - ey.x) / s, (ez.x + ex.z) / s, (ez.y + ey.z) / s, 0.25 * s};
    }
    return q;
  }
  /// The rotation by the rotation vector phi (axis phi/|phi|, angle |phi|).
  NETSPH_HD static Quat from_rotation_vector(const Vec3d& phi) {
    const double a = std::sqrt(dot(phi, phi));
    if (a < 1e-12) return {1, 0.5 * phi.x, 0.5 * phi.y, 0.5 * phi.z};  // first order
    const double s = std::sin(0.5 * a) / a;
    return {std::cos(0.5 * a), phi.x * s, phi.y * s, phi.z * s};
  }
};

NETSPH_HD Quat operator*(const Quat& a, const Quat& b) {
  return {
      a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
      a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

NETSPH_HD Quat normalized(const Quat& q) {
  const double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  return {q.w / n, q.x / n, q.y / n, q.z / n};
}

/// v rotated by q (body frame -> world frame).
NETSPH_HD Vec3d rotate(const Quat& q, const Vec3d& v) {
  // v' = v + 2 u x (u x v + w v), u = (x, y, z)
  const Vec3d u{q.x, q.y, q.z};
  const Vec3d t = cross(u, v) * 2.0;
  return v + t * q.w + cross(u, t);
}

/// v rotated by the inverse of q (world frame -> body frame).
NETSPH_HD Vec3d rotate_inverse(const Quat& q, const Vec3d& v) {
  return rotate(Quat{q.w, -q.x, -q.y, -q.z}, v);
}

}  // namespace netsph
