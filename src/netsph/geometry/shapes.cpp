#include "netsph/geometry/shapes.hpp"

#include <algorithm>
#include <cmath>

#include "netsph/core/real.hpp"

namespace netsph {
namespace {

/// Nearest surface point of a cylinder with axis `axis` (0, 1, 2), radius r, half length h.
Vec3d cylinder_surface(const Vec3d& p, int axis, double r, double h) {
  Vec3d radial = p;
  radial[axis] = 0;
  const double rho = norm(radial);
  // On the axis any radial direction will do.
  Vec3d dir = axis == 0 ? Vec3d(0, 0, 1) : Vec3d(1, 0, 0);
  if (rho > 1e-15) dir = radial / rho;
  const bool inside = rho <= r && std::fabs(p[axis]) <= h;
  Vec3d q;
  if (inside) {
    if (r - rho <= h - std::fabs(p[axis])) {  // the mantle is nearer than a cap
      q = dir * r;
      q[axis] = p[axis];
    } else {
      q = p;
      q[axis] = p[axis] >= 0 ? h : -h;
    }
    return q;
  }
  // Outside: clamp into the solid, which lands on the surface.
  q = dir * std::min(rho, r);
  q[axis] = std::clamp(p[axis], -h, h);
  return q;
}

bool inside_cylinder(const Vec3d& p, int axis, double r, double h) {
  Vec3d radial = p;
  radial[axis] = 0;
  return norm2(radial) <= r * r && std::fabs(p[axis]) <= h;
}

}  // namespace

bool Shape::inside(const Vec3d& p) const {
  switch (type) {
    case ShapeType::Box:
      return std::fabs(p.x) <= half.x && std::fabs(p.y) <= half.y && std::fabs(p.z) <= half.z;
    case ShapeType::Cylinder:
      return inside_cylinder(p, 0, radius, half.x);
    case ShapeType::Sphere:
      return norm2(p) <= radius * radius;
    case ShapeType::Cruciform:
      return inside_cylinder(p, 1, radius, half.y) || inside_cylinder(p, 2, radius, half.z);
  }
  return false;
}

Vec3d Shape::nearest_surface_point(const Vec3d& p) const {
  switch (type) {
    case ShapeType::Box: {
      // Inside: move to the nearest face; outside: clamp into the box.
      if (!inside(p)) {
        return {std::clamp(p.x, -half.x, half.x), std::clamp(p.y, -half.y, half.y),
                std::clamp(p.z, -half.z, half.z)};
      }
      int best = 0;
      double gap = 1e300;
      for (int a = 0; a < 3; ++a) {
        const double g = half[a] - std::fabs(p[a]);
        if (g < gap) gap = g, best = a;
      }
      Vec3d q = p;
      q[best] = p[best] >= 0 ? half[best] : -half[best];
      return q;
    }
    case ShapeType::Cylinder:
      return cylinder_surface(p, 0, radius, half.x);
    case ShapeType::Sphere: {
      const double r = norm(p);
      return r > 1e-15 ? p * (radius / r) : Vec3d(radius, 0, 0);
    }
    case ShapeType::Cruciform: {
      // The union's surface: the nearest point of either arm's surface that is not buried
      // inside the other arm.
      const Vec3d a = cylinder_surface(p, 1, radius, half.y);
      const Vec3d b = cylinder_surface(p, 2, radius, half.z);
      const double eps = 1e-9 * radius;
      auto buried_in = [&](const Vec3d& q, int axis, double h) {
        Vec3d radial = q;
        radial[axis] = 0;
        return norm(radial) < radius - eps && std::fabs(q[axis]) < h - eps;
      };
      const bool a_ok = !buried_in(a, 2, half.z), b_ok = !buried_in(b, 1, half.y);
      if (a_ok && b_ok) return norm2(a - p) <= norm2(b - p) ? a : b;
      if (a_ok) return a;
      if (b_ok) return b;
      return norm2(a - p) >= norm2(b - p) ? a : b;
    }
  }
  return p;
}

bool round_section_2d(const Shape& s, const std::vector<Vec3d>& plane) {
  const auto across = [](const Vec3d& a) { return std::fabs(dot(a, {1, 0, 0})) < 1e-9; };
  return s.type == ShapeType::Sphere ||
         (s.type == ShapeType::Cylinder && across(plane[0]) && across(plane[1]));
}

Shape plane_section_shape(const Shape& s, const std::vector<Vec3d>& plane) {
  return s.type == ShapeType::Cylinder && round_section_2d(s, plane) ? Shape::sphere(2 * s.radius)
                                                                     : s;
}

Vec3d Shape::bounding_half() const {
  switch (type) {
    case ShapeType::Box:
      return half;
    case ShapeType::Cylinder:
      return {half.x, radius, radius};
    case ShapeType::Sphere:
      return {radius, radius, radius};
    case ShapeType::Cruciform:
      return {radius, half.y, half.z};
  }
  return {};
}

double Shape::measure(int dims) const {
  const double r = radius;
  if (dims == 2) {  // the y = 0 section
    switch (type) {
      case ShapeType::Box:
        return 4 * half.x * half.z;
      case ShapeType::Cylinder:
        return 4 * half.x * r;  // axis x in the plane: a rectangle
      case ShapeType::Sphere:
        return kPi * r * r;
      case ShapeType::Cruciform:
        // The z arm is a 2r x 2h rectangle; the y arm's section (a disc of radius r) lies
        // inside it.
        return 4 * r * half.z;
    }
  }
  switch (type) {
    case ShapeType::Box:
      return 8 * half.x * half.y * half.z;
    case ShapeType::Cylinder:
      return kPi * r * r * 2 * half.x;
    case ShapeType::Sphere:
      return 4.0 / 3.0 * kPi * r * r * r;
    case ShapeType::Cruciform:
      // Two cylinders of length 2h minus their Steinmetz intersection 16 r^3 / 3.
      return kPi * r * r * 2 * (half.y + half.z) - 16.0 / 3.0 * r * r * r;
  }
  return 0;
}

Vec3d Shape::inertia_per_density(int dims) const {
  const double m = measure(dims);
  if (dims == 2) {
    // About the y axis, per unit depth, of the section.
    switch (type) {
      case ShapeType::Box:
        return {0, m * (4 * half.x * half.x + 4 * half.z * half.z) / 12, 0};
      case ShapeType::Cylinder:
        return {0, m * (4 * half.x * half.x + 4 * radius * radius) / 12, 0};
      case ShapeType::Sphere:
        return {0, m * radius * radius / 2, 0};
      case ShapeType::Cruciform:
        return {0, m * (4 * radius * radius + 4 * half.z * half.z) / 12, 0};
    }
  }
  switch (type) {
    case ShapeType::Box: {
      const Vec3d l = half * 2.0;
      return {m * (l.y * l.y + l.z * l.z) / 12, m * (l.x * l.x + l.z * l.z) / 12,
              m * (l.x * l.x + l.y * l.y) / 12};
    }
    case ShapeType::Cylinder: {
      const double r2 = radius * radius, l = 2 * half.x;
      return {m * r2 / 2, m * (3 * r2 + l * l) / 12, m * (3 * r2 + l * l) / 12};
    }
    case ShapeType::Sphere:
      return Vec3d(1, 1, 1) * (0.4 * m * radius * radius);
    case ShapeType::Cruciform: {
      // Numerical: a 60^3 midpoint sample of the bounding box (the Steinmetz overlap makes
      // the closed form long; 1% is plenty for knots).
      const Vec3d b = bounding_half();
      const int n = 60;
      Vec3d inertia{};
      const double cell = 8 * b.x * b.y * b.z / (n * n * n);
      for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
          for (int i = 0; i < n; ++i) {
            const Vec3d p{-b.x + (i + 0.5) * 2 * b.x / n, -b.y + (j + 0.5) * 2 * b.y / n,
                          -b.z + (k + 0.5) * 2 * b.z / n};
            if (!inside(p)) continue;
            inertia +=
                Vec3d(p.y * p.y + p.z * p.z, p.x * p.x + p.z * p.z, p.x * p.x + p.y * p.y) * cell;
          }
      return inertia;
    }
  }
  return {};
}

std::vector<Vec3d> body_lattice(const Shape& s, double dp, int shell_layers,
                                const std::vector<Vec3d>& axes) {
  const Vec3d b = s.bounding_half();
  const std::size_t na = axes.size();
  int n[3] = {0, 0, 0};
  double offset[3] = {0, 0, 0};
  for (std::size_t a = 0; a < na; ++a) {
    // Half extent along this axis (exact for axis-aligned axes); its layer count's parity sets
    // the half-dp offset.
    const Vec3d e = axes[a];
    const double half = std::fabs(e.x) * b.x + std::fabs(e.y) * b.y + std::fabs(e.z) * b.z;
    const long layers = std::max(1L, std::lround(2 * half / dp));
    offset[a] = layers % 2 == 0 ? 0.5 : 0.0;
    n[a] = static_cast<int>(layers / 2 + 1);
  }
  std::vector<Vec3d> pts;
  const double tol = 1e-6 * dp;
  for (int k = -n[2]; k <= n[2]; ++k)
    for (int j = -n[1]; j <= n[1]; ++j)
      for (int i = -n[0]; i <= n[0]; ++i) {
        const int idx[3] = {i, j, k};
        Vec3d p{};
        for (std::size_t a = 0; a < na; ++a) p += axes[a] * ((idx[a] + offset[a]) * dp);
        if (!s.inside(p)) continue;
        if (shell_layers > 0 && s.depth(p) > shell_layers * dp + tol) continue;
        pts.push_back(p);
      }
  return pts;
}

}  // namespace netsph

namespace netsph {

Shape resolvable_shape(const Shape& s, double dp, int dims) {
  Shape r = s;
  switch (s.type) {
    case ShapeType::Box:
      for (int a = 0; a < 3; ++a)
        if (!(dims == 2 && a == 1)) r.half[a] = std::max(r.half[a], dp);
      break;
    case ShapeType::Cylinder:
      r.half.x = std::max(r.half.x, dp);
      r.radius = std::max(r.radius, dp);
      break;
    case ShapeType::Sphere:
    case ShapeType::Cruciform:
      r.radius = std::max(r.radius, dp);
      break;
  }
  return r;
}

}  // namespace netsph
