#pragma once
// One interaction pass on the CPU: for every particle, the sums over its neighbours that give
// dv/dt and drho/dt (sph/pair_interaction.hpp), gathered per particle so that no two threads
// write the same memory and results do not depend on the thread count.
#include <span>
#include <vector>

#include "netsph/backend/cpu/interaction_view.hpp"
#include "netsph/neighbours/cell_grid.hpp"
#include "netsph/sph/fluid_model.hpp"
#include "netsph/sph/particle_set.hpp"

namespace netsph {

struct RateReductions {
  double max_acc = 0;      ///< max |dv/dt| over fluid particles (gravity included), m/s^2
  double max_visc_dt = 0;  ///< max |h v_ab.r_ab/(r^2+eta^2)|, 1/s
};

/// Sums for particle shifting (sph/shifting.hpp), filled for fluid particles when requested.
struct ShiftingSums {
  std::vector<Vec3f> grad_c;  ///< sum_b V_b grad_a W_ab
  std::vector<Real> div_r;    ///< -sum_b V_b r_ab . grad_a W_ab (2 or 3 inside the fluid)
};

/// Fills acc (fluid particles: with gravity; body particles: the fluid's force per unit mass,
/// no gravity; others: zero) and drho (zero for buffer particles, whose state the open
/// boundaries impose). `shifting` may be null.
RateReductions compute_rates(const FluidModel& m, const CellGrid& grid, const InteractionView& v,
                             std::span<const ParticleKind> kind, std::vector<Vec3f>& acc,
                             std::vector<Real>& drho, ShiftingSums* shifting = nullptr);

}  // namespace netsph
