#include "netsph/solver/output_particles.hpp"

#include <cmath>
#include <limits>

#include "netsph/backend/cpu/probe_pass.hpp"

namespace netsph {

GlobalMeasures measure_particles(const ParticleSet& p, double mass,
                                 std::span<const std::uint8_t> keep) {
  GlobalMeasures g;
  double ke = 0, vmax2 = 0, rmin = std::numeric_limits<double>::infinity(), rmax = -rmin;
  std::size_t nf = 0, nw = 0, nb = 0;
  const auto n = static_cast<std::int64_t>(p.size());
  const bool all = keep.empty();
#pragma omp parallel for reduction(+ : ke, nf, nw, nb) reduction(max : vmax2, rmax) \
    reduction(min : rmin)
  for (std::int64_t i = 0; i < n; ++i) {
    if (!all && !keep[i]) continue;
    nw += p.kind[i] == ParticleKind::Wall;
    nb += p.kind[i] == ParticleKind::Buffer;
    if (!is_fluid(p.kind[i])) continue;
    const double v2 = norm2(Vec3d(p.vel[i]));
    ke += 0.5 * mass * v2;
    vmax2 = std::max(vmax2, v2);
    rmin = std::min(rmin, static_cast<double>(p.rho[i]));
    rmax = std::max(rmax, static_cast<double>(p.rho[i]));
    ++nf;
  }
  g.fluid = nf;
  g.walls = nw;
  g.buffer = nb;
  g.kinetic_energy = ke;
  g.fluid_mass = mass * static_cast<double>(nf);
  g.max_speed = std::sqrt(vmax2);
  g.min_density = nf ? rmin : 0;
  g.max_density = nf ? rmax : 0;
  return g;
}

GlobalMeasures measure(const Simulation& sim) {
  return measure_particles(sim.particles(), sim.model().mass);
}

bool in_snapshot_region(const CaseSpec& spec, const Vec3d& x) {
  const auto& r = spec.output.snapshot_region;
  if (!r) return true;
  const bool y = spec.simulation.dimensions == 2 || (x.y >= r->min.y && x.y <= r->max.y);
  return x.x >= r->min.x && x.x <= r->max.x && x.z >= r->min.z && x.z <= r->max.z && y;
}

std::size_t snapshot_particle_count(const Simulation& sim) {
  const ParticleSet& p = sim.particles();
  if (!sim.spec().output.snapshot_region) return p.size();
  std::size_t n = 0;
  for (const Vec3d& x : p.pos) n += in_snapshot_region(sim.spec(), x);
  return n;
}

void SimulationParticles::sample(std::span<const Vec3d> points, std::span<ShepardValue> values) {
  // The grid is the one sorted at the start of the last step: its cells are searched with a
  // skin that covers the particles' motion over a step (neighbors/cell_grid.hpp).
  sample_points(sim_.model(), sim_.grid(), sim_.particles(), points, values);
}

std::uint64_t SimulationParticles::count(ParticleSelection which) {
  return which == ParticleSelection::All ? sim_.particles().size() : snapshot_particle_count(sim_);
}

void SimulationParticles::pieces(ParticleSelection which,
                                 const std::function<void(const ParticleSet&)>& take) {
  const ParticleSet& p = sim_.particles();
  if (which == ParticleSelection::All || !sim_.spec().output.snapshot_region) {
    take(p);
    return;
  }
  // The particles inside output.snapshot_region, copied into a set of their own.
  std::vector<std::uint32_t> inside;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (in_snapshot_region(sim_.spec(), p.pos[i])) inside.push_back(static_cast<std::uint32_t>(i));
  ParticleSet region;
  const auto pick = [&inside](auto& out, const auto& in) {
    out.resize(inside.size());
    for (std::size_t k = 0; k < inside.size(); ++k) out[k] = in[inside[k]];
  };
  pick(region.pos, p.pos), pick(region.vel, p.vel), pick(region.rho, p.rho);
  pick(region.kind, p.kind), pick(region.id, p.id), pick(region.group, p.group);
  pick(region.ghost, p.ghost);
  region.next_id = p.next_id;
  take(region);
}

}  // namespace netsph
