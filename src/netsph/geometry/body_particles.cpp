#include "netsph/geometry/body_particles.hpp"

#include <algorithm>
#include <cmath>

#include "netsph/core/real.hpp"

namespace netsph {
namespace {

/// Radii of the body-fitted layers of a round section of radius R: R - (i + 1/2) dp for
/// i = 0 .. max(1, round(R / dp)) - 1, limited to shell_layers when > 0. A radius below dp/4
/// stands for the centre (one point).
std::vector<double> layer_radii(double R, double dp, int shell_layers) {
  const long n = std::max(1L, std::lround(R / dp));
  std::vector<double> radii;
  for (long i = 0; i < n; ++i) {
    if (shell_layers > 0 && i >= shell_layers) break;
    radii.push_back(std::max(0.0, R - (static_cast<double>(i) + 0.5) * dp));
  }
  return radii;
}

/// Points evenly spread on a ring of radius r about c in the plane of unit vectors u, v:
/// round(2 pi r / dp) of them, or the centre alone for a ring too small to hold two (r < dp/4
/// or a single point). `stagger` turns the ring by half a spacing, so that successive rings'
/// points do not line up radially.
void add_ring(std::vector<Vec3d>& out, const Vec3d& c, const Vec3d& u, const Vec3d& v, double r,
              double dp, bool stagger) {
  const long n = std::lround(2 * kPi * r / dp);
  if (r < 0.25 * dp || n <= 1) {
    out.push_back(c);
    return;
  }
  const double spacing = 2 * kPi / static_cast<double>(n);
  const double phase = stagger ? 0.5 * spacing : 0.0;
  for (long k = 0; k < n; ++k) {
    const double a = phase + spacing * static_cast<double>(k);
    out.push_back(c + u * (r * std::cos(a)) + v * (r * std::sin(a)));
  }
}

/// A full or shell disc of radius R in the plane (u, v) through c.
void add_disc(std::vector<Vec3d>& out, const Vec3d& c, const Vec3d& u, const Vec3d& v, double R,
              double dp, int shell_layers) {
  bool stagger = false;
  for (const double r : layer_radii(R, dp, shell_layers)) {
    add_ring(out, c, u, v, r, dp, stagger);
    stagger = !stagger;
  }
}

/// Shells of a sphere of radius R, each a Fibonacci (golden-angle) spiral of
/// round(4 pi r^2 / dp^2) points: near-uniform spacing dp on every shell.
void add_sphere_shells(std::vector<Vec3d>& out, double R, double dp, int shell_layers) {
  const double golden = kPi * (3 - std::sqrt(5.0));
  int i = 0;
  for (const double r : layer_radii(R, dp, shell_layers)) {
    if (r < 0.25 * dp) {
      out.push_back({});
      continue;
    }
    const long n = std::max(1L, std::lround(4 * kPi * r * r / (dp * dp)));
    const double turn = (i++) * 0.5 * golden;  // shells start at different longitudes
    for (long k = 0; k < n; ++k) {
      const double z = 1 - (2 * static_cast<double>(k) + 1) / static_cast<double>(n);
      const double rho = std::sqrt(std::max(0.0, 1 - z * z));
      const double phi = static_cast<double>(k) * golden + turn;
      out.push_back(Vec3d(rho * std::cos(phi), rho * std::sin(phi), z) * r);
    }
  }
}

/// Cylinder (axis local x) in 3D: axial layers on the dp grid, centred; layers within
/// shell_layers dp of a cap are full discs, the others rings near the mantle only.
std::vector<Vec3d> cylinder_3d(const Shape& s, double dp, int shell_layers) {
  const double half = s.half.x;
  const long layers = std::max(1L, std::lround(2 * half / dp));
  std::vector<Vec3d> out;
  for (long j = 0; j < layers; ++j) {
    const double x = (static_cast<double>(j) - 0.5 * static_cast<double>(layers - 1)) * dp;
    const double cap_depth = half - std::fabs(x);
    const bool cap = shell_layers == 0 || cap_depth <= shell_layers * dp + 1e-6 * dp;
    add_disc(out, {x, 0, 0}, {0, 1, 0}, {0, 0, 1}, s.radius, dp, cap ? 0 : shell_layers);
  }
  return out;
}

}  // namespace

std::vector<Vec3d> body_particles(const Shape& s, double dp, int shell_layers, int dims,
                                  const std::vector<Vec3d>& plane) {
  std::vector<Vec3d> out;
  if (dims == 3) {
    if (s.type == ShapeType::Sphere) {
      add_sphere_shells(out, s.radius, dp, shell_layers);
      return out;
    }
    if (s.type == ShapeType::Cylinder) return cylinder_3d(s, dp, shell_layers);
    return body_lattice(s, dp, shell_layers, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
  }
  // 2D: the section by the simulation plane. A sphere's is a disc, and so is a cylinder's
  // when its axis (local x) is normal to the plane; everything else is polygonal.
  if (round_section_2d(s, plane)) {
    add_disc(out, {}, plane[0], plane[1], s.radius, dp, shell_layers);
    return out;
  }
  return body_lattice(s, dp, shell_layers, plane);
}

}  // namespace netsph
