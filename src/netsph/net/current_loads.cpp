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
                      std::vector<Vec3d>& forces, const NetWater& w) {
  const double sn = net.real_solidity;
  for (std::size_t i = 0; i < net.knots.size(); ++i) {
    const NetKnot& k = net.knots[i];
    if (!w.knot_wet[i]) continue;
    const Vec3d u = w.knot[i] - k.velocity;
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
                       std::vector<Vec3d>& forces, const NetWater& w) {
  for (std::size_t i = 0; i < net.twines.size(); ++i) {
    const NetTwine& t = net.twines[i];
    const NetKnot& a = net.knots[t.a];
    const NetKnot& b = net.knots[t.b];
    const Vec3d d = b.position - a.position;
    const double length = norm(d);
    if (length <= t.diameter) continue;
    const Vec3d e = d / length;
    if (!w.twine_wet[i]) continue;
    const Vec3d u = w.twine[i] - (a.velocity + b.velocity) * 0.5;
    const Vec3d ut = e * dot(u, e);
    const Vec3d un = u - ut;
    const double area = t.diameter * (length - t.diameter);
    const Vec3d f = (un * (p.normal_drag * norm(un)) + ut * (p.tangential_drag * norm(ut))) *
                    (0.5 * p.water_density * area);
    forces[t.a] += f * 0.5;
    forces[t.b] += f * 0.5;
  }
}

/// Cylinder drag on the sinker bar in the current (and waves), per bottom knot, with the
/// water's velocity at the bar below the knot.
void add_sinker_loads(const NetModel& net, const CurrentLoadParameters& p,
                      std::vector<Vec3d>& forces, const NetWater& w) {
  for (std::size_t k = 0; k < net.knots.size(); ++k) {
    const NetKnot& knot = net.knots[k];
    if (knot.sinker_length <= 0 || !w.sinker_wet[k]) continue;
    forces[k] += sinker_drag(net, knot, w.sinker[k], p.water_density);
  }
}

}  // namespace

bool water_velocity(const CurrentLoadParameters& p, const Vec3d& x, Vec3d& u) {
  u = p.velocity;
  if (!p.waves) return true;
  const WaveSpec& w = *p.waves;
  const double z = x.z - w.still_level;
  if (z > w.target_elevation(x.x, p.time)) return false;
  // Below the bed (a net sagging into it): the velocity at the bed (wave_velocity's rule).
  double along = 0, up = 0;
  train_velocity(w.train, w.direction * (x.x - w.paddle_x), z, p.time, along, up);
  u += Vec3d{w.direction * along, 0, up};
  return true;
}

Vec3d sinker_point(const NetModel& net, const NetKnot& k) {
  Vec3d down = -net.up;
  if (k.row + 1 < net.rows) {
    const Vec3d d = k.position - net.knots[net.index(k.row + 1, k.column)].position;
    const double length = norm(d);
    if (length > 0) down = d / length;
  }
  return k.position + down * net.sinker_offset;
}

int sinker_sample_points(const NetModel& net, const NetKnot& k, SinkerSamples& s) {
  const Vec3d here = sinker_point(net, k);
  const auto bar_at = [&](int column) {
    return sinker_point(net, net.knots[net.index(k.row, column)]);
  };
  Vec3d* points = s.points;
  int n = 0;
  // The bar at the knot: below it in the inset layout; inside it in the crossings layout,
  // where the knot's particles leave no water to sample (the share's ends only, then).
  if (!net.crossings) points[n++] = here;
  for (const int side : {-1, 1}) {
    const int column = k.column + side;
    if (column >= 0 && column < net.columns) {
      points[n++] = (here + bar_at(column)) * 0.5;
    } else if (!net.crossings) {
      // Outward along the bar: away from the neighbour on the other side, if there is one.
      const int other = k.column - side;
      Vec3d out = net.across * static_cast<double>(side);
      if (other >= 0 && other < net.columns) {
        const Vec3d d = here - bar_at(other);
        if (norm(d) > 0) out = d / norm(d);
      }
      points[n++] = here + out * (0.5 * net.spacing_across);
    }
  }
  // The trapezoidal rule along the share: ends 1/4 each, the middle 1/2 (ends 1/2 each
  // without it).
  for (int i = 0; i < n; ++i) s.weights[i] = net.crossings ? 1.0 / n : (i == 0 ? 0.5 : 0.25);
  return s.count = n;
}

Vec3d sinker_drag(const NetModel& net, const NetKnot& k, const Vec3d& flow, double water_density) {
  if (k.sinker_length <= 0 || net.sinker_diameter <= 0) return {};
  const Vec3d u = flow - k.velocity;
  const Vec3d un = u - net.across * dot(u, net.across);
  const double area = net.sinker_diameter * k.sinker_length;
  return un * (0.5 * water_density * net.sinker_drag_coefficient * area * norm(un));
}

void sample_net_water(const NetModel& net, const CurrentLoadParameters& p, NetWater& out) {
  const std::size_t knots = net.knots.size(), twines = net.twines.size();
  out.knot.resize(knots), out.knot_wet.resize(knots);
  out.sinker.resize(knots), out.sinker_wet.resize(knots);
  out.twine.resize(twines), out.twine_wet.resize(twines);
  for (std::size_t i = 0; i < knots; ++i) {
    const NetKnot& k = net.knots[i];
    out.knot_wet[i] = water_velocity(p, k.position, out.knot[i]);
    out.sinker_wet[i] =
        k.sinker_length > 0 && water_velocity(p, sinker_point(net, k), out.sinker[i]);
  }
  for (std::size_t i = 0; i < twines; ++i) {
    const NetTwine& t = net.twines[i];
    const Vec3d middle = (net.knots[t.a].position + net.knots[t.b].position) * 0.5;
    out.twine_wet[i] = water_velocity(p, middle, out.twine[i]);
  }
}

void add_current_loads(const NetModel& net, const CurrentLoadParameters& p,
                       std::vector<Vec3d>& forces, const NetWater* water) {
  NetWater sampled;
  if (!water) {
    sample_net_water(net, p, sampled);
    water = &sampled;
  }
  switch (p.model) {
    case NetLoadModel::None:
      break;
    case NetLoadModel::Screen:
      add_screen_loads(net, p, forces, *water);
      break;
    case NetLoadModel::Morison:
      add_morison_loads(net, p, forces, *water);
      break;
  }
  add_sinker_loads(net, p, forces, *water);
}

}  // namespace netsph
