#include "netsph/net/knot_spring_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace netsph {

KnotSpringSolver::KnotSpringSolver(NetModel& net) : net_(net) {
  // The damping ratio each twine was built with, for the stability margin.
  for (const NetTwine& t : net_.twines) {
    const double m = twine_modal_mass(net_.knots[t.a], net_.knots[t.b]);
    const double k = t.law.c1 / t.rest;
    if (m > 0 && k > 0)
      max_damping_ratio_ = std::max(max_damping_ratio_, t.damping / (2 * std::sqrt(k * m)));
  }
}

double KnotSpringSolver::stable_step() const {
  std::vector<double>& stiffness = stiffness_;
  stiffness.assign(net_.knots.size(), 0.0);
  for (const NetTwine& t : net_.twines) {
    // Ahead of the present strain, so that a tightening twine does not outrun the step.
    const double strain = std::max(0.0, twine_strain(net_, t)) * 1.5;
    const double k = twine_tangent_stiffness(t.law, strain, t.rest);
    stiffness[t.a] += 2 * k;
    stiffness[t.b] += 2 * k;
  }
  double omega2 = 0;
  for (std::size_t i = 0; i < net_.knots.size(); ++i) {
    if (net_.knots[i].fixed || net_.knots[i].mass <= 0) continue;
    omega2 = std::max(omega2, stiffness[i] / net_.knots[i].mass);
  }
  if (omega2 <= 0) return std::numeric_limits<double>::infinity();
  const double zeta = max_damping_ratio_;
  return 0.5 * (std::sqrt(1 + zeta * zeta) - zeta) * 2 / std::sqrt(omega2);
}

void KnotSpringSolver::twine_forces(std::vector<Vec3d>& forces) const {
  forces.assign(net_.knots.size(), Vec3d{});
  for (const NetTwine& t : net_.twines) {
    const NetKnot& a = net_.knots[t.a];
    const NetKnot& b = net_.knots[t.b];
    const Vec3d f =
        twine_force_on_a(t.law, t.rest, t.damping, a.position, b.position, a.velocity, b.velocity);
    forces[t.a] += f;
    forces[t.b] -= f;
  }
}

void KnotSpringSolver::total_forces(const LoadFunction& loads, std::vector<Vec3d>& forces) const {
  twine_forces(forces);
  for (std::size_t i = 0; i < net_.knots.size(); ++i) forces[i] += net_.knots[i].constant_force;
  if (loads) {
    scratch_.assign(net_.knots.size(), Vec3d{});
    loads(net_, scratch_);
    for (std::size_t i = 0; i < forces.size(); ++i) forces[i] += scratch_[i];
  }
}

int KnotSpringSolver::advance(double dt, const LoadFunction& loads) {
  if (dt <= 0) return 0;
  const double limit = stable_step();
  const int steps = std::isfinite(limit) ? std::max(1, static_cast<int>(std::ceil(dt / limit))) : 1;
  const double h = dt / steps;
  auto& knots = net_.knots;
  total_forces(loads, forces_);
  for (int s = 0; s < steps; ++s) {
    // Kick, drift, kick (velocity Verlet); velocity-dependent forces (damping, drag) use the
    // half-step velocity in the second kick.
    for (std::size_t i = 0; i < knots.size(); ++i) {
      NetKnot& k = knots[i];
      if (k.fixed) continue;
      k.velocity += forces_[i] * (0.5 * h / k.mass);
      k.position += k.velocity * h;
    }
    total_forces(loads, forces_);
    for (std::size_t i = 0; i < knots.size(); ++i) {
      NetKnot& k = knots[i];
      if (k.fixed) continue;
      k.velocity += forces_[i] * (0.5 * h / k.mass);
    }
  }
  return steps;
}

double KnotSpringSolver::kinetic_energy() const {
  double e = 0;
  for (const NetKnot& k : net_.knots) e += 0.5 * k.mass * norm2(k.velocity);
  return e;
}

double KnotSpringSolver::twine_energy() const {
  double e = 0;
  for (const NetTwine& t : net_.twines) {
    e += netsph::twine_energy(t.law, twine_strain(net_, t), t.rest);
  }
  return e;
}

double KnotSpringSolver::constant_force_potential() const {
  double e = 0;
  for (const NetKnot& k : net_.knots) {
    if (!k.fixed) e -= dot(k.constant_force, k.position);
  }
  return e;
}

Vec3d KnotSpringSolver::anchor_force(const LoadFunction& loads) const {
  std::vector<Vec3d> f;
  total_forces(loads, f);
  Vec3d sum{};
  for (std::size_t i = 0; i < net_.knots.size(); ++i) {
    if (net_.knots[i].fixed) sum += f[i];
  }
  return sum;
}

double KnotSpringSolver::max_strain() const {
  double m = 0;
  for (const NetTwine& t : net_.twines) {
    m = std::max(m, twine_strain(net_, t));
  }
  return m;
}

double KnotSpringSolver::max_tension() const {
  return max_twine_tension(net_);
}

}  // namespace netsph
