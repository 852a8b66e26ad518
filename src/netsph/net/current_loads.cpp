#include "netsph/net/current_loads.hpp"

#include <algorithm>
#include <cmath>

#include "netsph/net/screen_model.hpp"

namespace netsph {
namespace {

/// The deformed net's unit normal at a knot, from the neighbours across and up (one-sided on
/// the edges), on the side of the undeformed normal.
Vec3d knot_normal(const NetModel& net, int row, int column) {
  auto at = [&](int r, int c) {
    return net.knots[net.index(std::clamp(r, 0, net.rows - 1), std::clamp(c, 0, net.columns - 1))]
        .position;
  };
  const Vec3d across = at(row, column + 1) - at(row, column - 1);
  const Vec3d up = at(row + 1, column) - at(row - 1, column);
  Vec3d n = cross(up, across);
  // A net one knot wide or tall has no second tangent: keep the undeformed normal.
  const double length = norm(n);
  if (length <= 0 || net.rows < 2 || net.columns < 2) return net.normal;
  n = n / length;
  return dot(n, net.normal) < 0 ? -n : n;
}

void add_screen_loads(const NetModel& net, const CurrentLoadParameters& p,
                      std::vector<Vec3d>& forces) {
  const double sn = net.real_solidity;
  for (const NetKnot& k : net.knots) {
    const Vec3d u = p.velocity - k.velocity;
    const double speed = norm(u);
    if (speed <= 0) continue;
    Vec3d n = knot_normal(net, k.row, k.column);
    if (dot(n, u) < 0) n = -n;  // lift points along the normal's cross-flow part
    const double cos_theta = std::min(1.0, dot(n, u) / speed);
    const double reynolds = speed * net.twine_diameter / (p.kinematic_viscosity * (1 - sn));
    const ScreenForceCoefficients c = screen_coefficients_at_cos(p.screen, sn, cos_theta, reynolds);
    const Vec3d drag_dir = u / speed;
    Vec3d lift_dir = n - drag_dir * cos_theta;  // (u x n) x u / |u|^2
    const double lift_norm = norm(lift_dir);
    lift_dir = lift_norm > 1e-12 ? lift_dir / lift_norm : Vec3d{};
    const double q = 0.5 * p.water_density * k.screen_area * speed * speed;
    forces[&k - net.knots.data()] += (drag_dir * c.drag + lift_dir * c.lift) * q;
  }
}

void add_morison_loads(const NetModel& net, const CurrentLoadParameters& p,
                       std::vector<Vec3d>& forces) {
  for (const NetTwine& t : net.twines) {
    const NetKnot& a = net.knots[t.a];
    const NetKnot& b = net.knots[t.b];
    const Vec3d d = b.position - a.position;
    const double length = norm(d);
    if (length <= t.diameter) continue;
    const Vec3d e = d / length;
    const Vec3d u = p.velocity - (a.velocity + b.velocity) * 0.5;
    const Vec3d ut = e * dot(u, e);
    const Vec3d un = u - ut;
    const double area = t.diameter * (length - t.diameter);
    const Vec3d f = (un * (p.normal_drag * norm(un)) + ut * (p.tangential_drag * norm(ut))) *
                    (0.5 * p.water_density * area);
    forces[t.a] += f * 0.5;
    forces[t.b] += f * 0.5;
  }
}

/// Cylinder drag on the sinker bar (along the net's across direction), per bottom knot.
void add_sinker_loads(const NetModel& net, const CurrentLoadParameters& p,
                      std::vector<Vec3d>& forces) {
  if (net.sinker_diameter <= 0) return;
  for (const NetKnot& k : net.knots) {
    if (k.sinker_length <= 0) continue;
    const Vec3d u = p.velocity - k.velocity;
    const Vec3d un = u - net.across * dot(u, net.across);
    const double area = net.sinker_diameter * k.sinker_length;
    forces[&k - net.knots.data()] +=
        un * (0.5 * p.water_density * net.sinker_drag_coefficient * area * norm(un));
  }
}

}  // namespace

void add_current_loads(const NetModel& net, const CurrentLoadParameters& p,
                       std::vector<Vec3d>& forces) {
  switch (p.model) {
    case NetLoadModel::None:
      break;
    case NetLoadModel::Screen:
      add_screen_loads(net, p, forces);
      break;
    case NetLoadModel::Morison:
      add_morison_loads(net, p, forces);
      break;
  }
  add_sinker_loads(net, p, forces);
}

}  // namespace netsph
