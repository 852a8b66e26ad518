#include "netsph/app/scene_report.hpp"

#include <spdlog/spdlog.h>

namespace netsph::app {

void log_scene(const Simulation& sim) {
  const Scene& s = sim.scene();
  const FluidModel& m = sim.model();
  const CaseSpec& spec = sim.spec();
  const auto& p = sim.particles();
  spdlog::info("{}D, dp = {:g} m, h = {:g} m ({} kernel), c0 = {:.4g} m/s, rho0 = {:g} kg/m^3",
               m.dims, spec.simulation.dp, static_cast<double>(m.kernel.h),
               m.kernel_type == KernelType::Wendland ? "Wendland" : "cubic spline", s.sound_speed,
               static_cast<double>(m.eos.rho0));
  spdlog::info("particles: {} fluid, {} wall, {} body, {} open-boundary buffer, {} total",
               p.count(ParticleKind::Fluid), p.count(ParticleKind::Wall),
               p.count(ParticleKind::Body), p.count(ParticleKind::Buffer), p.size());
  for (const auto& b : s.bodies) {
    spdlog::info("  body {:<12} {:>9} particles, {} , mass {:.4g} kg{}", b.name, b.count,
                 b.motion == BodyMotion::Fixed
                     ? "fixed"
                     : (b.motion == BodyMotion::Floating ? "floating" : "prescribed"),
                 b.inertia.mass, m.dims == 2 ? "/m" : "");
  }
  for (const auto& src : s.sources)
    spdlog::info("  {:<16} {:>10} particles", src.name, src.particles);
  spdlog::info("domain [{:.4g}, {:.4g}, {:.4g}] .. [{:.4g}, {:.4g}, {:.4g}] m{}", s.domain_min.x,
               s.domain_min.y, s.domain_min.z, s.domain_max.x, s.domain_max.y, s.domain_max.z,
               spec.domain.given ? "" : " (default: particles' bounding box + margin)");
  for (const auto& w : s.warnings) spdlog::warn("{}", w);
}

}  // namespace netsph::app
