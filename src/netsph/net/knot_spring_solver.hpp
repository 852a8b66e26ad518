#pragma once
// Knot-spring dynamics: m x'' = twine forces + constant forces (gravity, buoyancy, sinker,
// point loads) + external loads (a current model, or the SPH fluid's force on resolved
// knots). Anchored knots do not move.
//
// Time integration: explicit velocity Verlet, sub-cycled inside each outer (fluid) step with
// a sub-step derived from stability, dt_sub = 0.5 (sqrt(1 + zeta^2) - zeta) 2 / omega_max,
// where omega_max^2 <= max_i (2 sum_j k_j) / m_i (Gershgorin's bound on the stiffness matrix
// over the mass) with each twine's tangent stiffness k_j. The margin 0.5 (not 0.9) is there
// because the tension-only kink at eps = 0 is not smooth: an undamped hanging net whose
// twines keep going slack and taut gained energy without bound at 0.9 and stayed bounded at
// 0.5 (tests/unit/knot_spring_test.cpp). Why not an implicit solve: a sub-step
// costs O(knots + twines), about a thousand flops for the paper's 225-knot net, against the
// fluid step's 1e6-1e8 particles, so a hundred sub-steps are still free; it keeps the
// tension-only switch exact (no Newton iteration across the kink at eps = 0) and the energy
// behaviour of a symplectic scheme. The outer step is never shortened by the twines.
#include <functional>
#include <vector>

#include "netsph/net/net_model.hpp"

namespace netsph {

class KnotSpringSolver {
 public:
  /// External loads on every knot at the current state (forces has one entry per knot,
  /// zeroed before the call).
  using LoadFunction = std::function<void(const NetModel& net, std::vector<Vec3d>& forces)>;

  explicit KnotSpringSolver(NetModel& net);

  /// The largest stable sub-step at the present strains, s.
  double stable_step() const;

  /// Advances by dt (any length) in equal sub-steps no longer than stable_step(); returns the
  /// number of sub-steps. `loads` may be empty.
  int advance(double dt, const LoadFunction& loads);

  /// Twine forces (tension and damping) on every knot.
  void twine_forces(std::vector<Vec3d>& forces) const;
  /// Total force on every knot: twines, constant forces and `loads`.
  void total_forces(const LoadFunction& loads, std::vector<Vec3d>& forces) const;

  double kinetic_energy() const;
  double twine_energy() const;
  /// Potential of the constant forces, -sum F . x (J), so that kinetic + twine + this is
  /// conserved without damping and loads.
  double constant_force_potential() const;

  /// Sum of all forces on the anchored knots (twines, constant forces, `loads`), N: what load
  /// cells on the anchors read, with the sign of the load; at rest it balances the net's
  /// drag, weights and buoyancies.
  Vec3d anchor_force(const LoadFunction& loads = {}) const;
  /// Largest twine strain and tension.
  double max_strain() const;
  double max_tension() const;

  NetModel& net() { return net_; }
  const NetModel& net() const { return net_; }

 private:
  NetModel& net_;
  double max_damping_ratio_ = 0;
  std::vector<Vec3d> forces_;
  mutable std::vector<Vec3d> scratch_;     ///< loads, reused between calls
  mutable std::vector<double> stiffness_;  ///< per-knot stiffness bound, reused
};

}  // namespace netsph
