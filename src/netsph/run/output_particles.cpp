#include "netsph/run/output_particles.hpp"

#include <cmath>
#include <optional>

#include "netsph/backend/cpu/probe_pass.hpp"

namespace netsph {

// The CPU's reduction of the tallies (the device step reduces with the same merge).
#pragma omp declare reduction(merge:ParticleTally                         \
                              : omp_out = merge_tallies(omp_out, omp_in)) \
    initializer(omp_priv = ParticleTally{})

ParticleTally tally_particles(const ParticleSet& p, double mass,
                              std::span<const std::uint8_t> keep) {
  ParticleTally t;
  const auto n = static_cast<std::int64_t>(p.size());
  const bool all = keep.empty();
#pragma omp parallel for reduction(merge : t)
  for (std::int64_t i = 0; i < n; ++i) {
    if (!all && !keep[i]) continue;
    t = merge_tallies(t, tally_particle(p.kind[i], p.vel[i], p.rho[i], mass));
  }
  return t;
}

GlobalMeasures measures_of(const ParticleTally& t, double mass) {
  GlobalMeasures g;
  g.fluid = t.fluid;
  g.walls = t.walls;
  g.buffer = t.buffer;
  g.kinetic_energy = t.kinetic_energy;
  g.fluid_mass = mass * static_cast<double>(t.fluid);
  g.max_speed = std::sqrt(t.max_speed2);
  g.min_density = t.fluid ? t.min_density : 0;
  g.max_density = t.fluid ? t.max_density : 0;
  return g;
}

GlobalMeasures measure_particles(const ParticleSet& p, double mass,
                                 std::span<const std::uint8_t> keep) {
  return measures_of(tally_particles(p, mass, keep), mass);
}

GlobalMeasures measure(const Simulation& sim) {
  // On the device backends the device reduces its particles: a series row costs no transfer.
  if (const std::optional<ParticleTally> t = sim.tally_on_device())
    return measures_of(*t, sim.model().mass);
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
  // On the device backends the device samples its particles (a probe costs no transfer).
  if (sim_.sample_on_device(points, values)) return;
  // The grid is the one sorted at the start of the last step: its cells are searched with a
  // skin that covers the particles' motion over a step (neighbours/cell_grid.hpp).
  sample_points(sim_.model(), sim_.grid(), sim_.particles(), points, values);
}

std::uint64_t SimulationParticles::count(ParticleSelection which) {
  return which == ParticleSelection::All ? sim_.particle_count() : snapshot_particle_count(sim_);
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
