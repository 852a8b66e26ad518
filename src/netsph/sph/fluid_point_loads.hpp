#pragma once
// Forces that modelled parts too thin to resolve (a net's sinker bar, solver/net_coupling.hpp)
// put on the water, given back to the SPH fluid so that momentum is conserved: a force F_s at
// point x_s is spread over the fluid particles within the kernel support by kernel weight,
//
//   a_i += W(x_i - x_s) F_s / D_s,   D_s = sum_j m_j W(x_j - x_s)   (fluid particles j),
//
// so that sum_i m_i a_i = F_s exactly: the Shepard weights of the sampler (sph/shepard.hpp,
// where D_s is the sums' `density`) used the other way round, as in the regularised
// point-force coupling of immersed-boundary methods (Peskin 2002, Acta Numerica; in SPH e.g. the
// DEM-SPH unresolved coupling of Robinson, Ramaioli & Luding 2014). The CPU step and the
// device step both add it per particle through point_loads_acceleration, one gather over the
// loads in their order, so the sum does not depend on the thread count. Each particle in the
// loads' box loops over all loads: meant for a net's sinker bar (tens to a few hundred points
// h apart), not for thousands over a whole cage, which would want the loads binned by cell.
// The loads are added after the time step is chosen, so they do not enter its force limit:
// under 1 m/s^2 for the reduced Bi 2014 net's bar; they grow as 1/h^2, but at the paper's
// dp = 1.2 mm the limit they would set is still about 1e-3 s against the acoustic 1.2e-4 s.
#include <cmath>
#include <cstdint>
#include <type_traits>

#include "netsph/core/host_device.hpp"
#include "netsph/core/periodic_image.hpp"
#include "netsph/core/real.hpp"
#include "netsph/core/vec3.hpp"
#include "netsph/sph/kernels.hpp"

namespace netsph {

struct FluidPointLoad {
  Vec3d point{};       ///< where the force acts, m
  Vec3d per_weight{};  ///< F_s / D_s, N m^3/kg: times W(r) an acceleration, m/s^2
};
static_assert(std::is_trivially_copyable_v<FluidPointLoad>, "copied to the device as bytes");

/// A batch of point loads as the particle passes read it: the loads (`count` of them) and the
/// box that holds their supports (centre +- reach), which lets most particles skip the loop.
struct FluidPointLoadSet {
  const FluidPointLoad* loads = nullptr;
  std::uint32_t count = 0;
  Vec3d centre{};
  Vec3d reach{};  ///< half extent of the loads' points plus the kernel support, m
};

/// The batch of `loads` for a kernel of support radius `support`.
inline FluidPointLoadSet point_load_set(const FluidPointLoad* loads, std::uint32_t count,
                                        double support) {
  FluidPointLoadSet set{loads, count, {}, {}};
  if (count == 0) return set;
  Vec3d lo = loads[0].point, hi = lo;
  for (std::uint32_t s = 1; s < count; ++s) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = loads[s].point[a] < lo[a] ? loads[s].point[a] : lo[a];
      hi[a] = loads[s].point[a] > hi[a] ? loads[s].point[a] : hi[a];
    }
  }
  set.centre = (lo + hi) * 0.5;
  set.reach = (hi - lo) * 0.5 + Vec3d{support, support, support};
  return set;
}

/// The acceleration the loads give a fluid particle at x (the formula above); offsets are taken
/// at their nearest periodic image (`period` 0 on axes that are not periodic).
template <class Kernel>
NETSPH_HD Vec3f point_loads_acceleration(const FluidPointLoadSet& set, const KernelScale& kernel,
                                         Real support2, const Vec3d& period, const Vec3d& x) {
  const Vec3d to_box = nearest_image_offset(x - set.centre, period);
  if (!(std::fabs(to_box.x) <= set.reach.x && std::fabs(to_box.y) <= set.reach.y &&
        std::fabs(to_box.z) <= set.reach.z)) {
    return {};
  }
  Vec3d a{};
  for (std::uint32_t s = 0; s < set.count; ++s) {
    const Vec3f d(nearest_image_offset(x - set.loads[s].point, period));
    const Real r2 = d.x * d.x + d.y * d.y + d.z * d.z;
    if (r2 >= support2) continue;
    a += set.loads[s].per_weight * static_cast<double>(kernel_value<Kernel>(kernel, std::sqrt(r2)));
  }
  return Vec3f(a);
}

}  // namespace netsph
