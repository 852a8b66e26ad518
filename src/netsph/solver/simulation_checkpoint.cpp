// Simulation::save_state / restore_state: everything a step reads that is not rebuilt from the
// case, so that a run restarted from a checkpoint continues bit for bit (same threads, same
// build): the particles in their sorted order, time, step count, dt floor, diagnostics, the
// rigid bodies' states (and last forces, for the outputs) and the nets' knots. The scene
// (walls, zones, body shapes), the grid and every scratch array come from the case again.
#include <algorithm>
#include <cmath>
#include <string_view>

#include <fmt/format.h>

#include "netsph/solver/simulation.hpp"

namespace netsph {
namespace {

template <class V, class T>
void put3(std::vector<T>& out, const V& v) {
  out.push_back(v.x), out.push_back(v.y), out.push_back(v.z);
}

bool all_finite(std::span<const double> v) {
  return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

/// The particles just read from a checkpoint, checked before a step runs on them. A file
/// damaged after it was written (a disk or copy error, bytes overwritten inside an intact HDF5
/// structure) reads without an HDF5 error; left alone, its garbage would stop the run a step
/// later as "unstable" with advice about the time step. What a step can leave in a checkpoint
/// is far inside these bounds: finite values, every particle in the domain (those outside it
/// are removed; a margin of the domain's largest size allows for any drift before that), speeds
/// below the sound speed (100 times it here) and densities within a few percent of the
/// reference (a factor 10 here). Throws netsph::Error naming the file and the first bad particle.
void check_restored_particles(const CheckpointData& c, const Scene& scene,
                              std::span<const double> pos, std::span<const float> vel,
                              std::span<const float> ghost, std::span<const float> rho,
                              std::span<const std::uint8_t> kind,
                              std::span<const std::uint32_t> id) {
  const std::size_t n = rho.size();
  const Vec3d lo = scene.domain_min, hi = scene.domain_max;
  const double margin = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  const double max_speed = 100 * scene.sound_speed;
  const double rho0 = scene.model.eos.rho0;
  for (std::size_t i = 0; i < n; ++i) {
    const double* x = pos.data() + 3 * i;
    const float* v = vel.data() + 3 * i;
    const float* g = ghost.data() + 3 * i;
    const double speed = std::sqrt(double(v[0]) * v[0] + double(v[1]) * v[1] + double(v[2]) * v[2]);
    std::string what;
    if (kind[i] > static_cast<std::uint8_t>(ParticleKind::Body)) {
      what = fmt::format("kind {}, which no particle has", kind[i]);
    } else if (!all_finite({x, 3})) {
      what = fmt::format("position ({:.4g}, {:.4g}, {:.4g}) m, not finite", x[0], x[1], x[2]);
    } else if (x[0] < lo.x - margin || x[0] > hi.x + margin || x[1] < lo.y - margin ||
               x[1] > hi.y + margin || x[2] < lo.z - margin || x[2] > hi.z + margin) {
      what = fmt::format(
          "position ({:.4g}, {:.4g}, {:.4g}) m, far outside the domain [{:.4g}, {:.4g}, "
          "{:.4g}]-[{:.4g}, {:.4g}, {:.4g}] m",
          x[0], x[1], x[2], lo.x, lo.y, lo.z, hi.x, hi.y, hi.z);
    } else if (!(speed <= max_speed)) {
      what = fmt::format("velocity ({:.4g}, {:.4g}, {:.4g}) m/s, {}", v[0], v[1], v[2],
                         std::isfinite(speed) ? "over 100 times the sound speed" : "not finite");
    } else if (!(rho[i] > 0.1 * rho0 && rho[i] < 10 * rho0)) {
      what =
          fmt::format("density {:.4g} kg/m^3, {} (reference {:.4g} kg/m^3)", rho[i],
                      std::isfinite(rho[i]) ? "off by more than a factor 10" : "not finite", rho0);
    } else if (!std::isfinite(g[0]) || !std::isfinite(g[1]) || !std::isfinite(g[2])) {
      what = "a ghost-node vector that is not finite";
    }
    if (what.empty()) continue;
    const std::string_view kind_text = name_of(static_cast<ParticleKind>(kind[i]));
    throw Error(c.source, fmt::format("the checkpoint is corrupt (damaged after it was "
                                      "written): particle id {} ({}) has {}. It cannot be "
                                      "continued: put back a good copy of the file, or start "
                                      "the run again",
                                      id[i], kind_text, what));
  }
}

}  // namespace

void Simulation::particle_state(const ParticleSet& p, CheckpointData& c, std::size_t first,
                                std::size_t count) {
  first = std::min(first, p.size());
  const std::size_t end = first + std::min(count, p.size() - first);
  auto& pos = c.f64["particles.pos"];
  auto& vel = c.f32["particles.vel"];
  auto& ghost = c.f32["particles.ghost"];
  auto& rho = c.f32["particles.rho"];
  auto& kind = c.u8["particles.kind"];
  pos.clear(), vel.clear(), ghost.clear(), rho.clear(), kind.clear();
  pos.reserve(3 * (end - first)), vel.reserve(3 * (end - first)), ghost.reserve(3 * (end - first));
  kind.reserve(end - first);
  for (std::size_t i = first; i < end; ++i) {
    put3(pos, p.pos[i]), put3(vel, p.vel[i]), put3(ghost, p.ghost[i]);
    kind.push_back(static_cast<std::uint8_t>(p.kind[i]));
  }
  rho.assign(p.rho.begin() + first, p.rho.begin() + end);
  c.u32["particles.id"].assign(p.id.begin() + first, p.id.begin() + end);
  c.u32["particles.group"].assign(p.group.begin() + first, p.group.begin() + end);
}

void Simulation::particle_state_blocks(const ParticleSet& p,
                                       const std::function<void(const CheckpointData&)>& add,
                                       std::size_t rows) {
  rows = std::max<std::size_t>(rows, 1);
  CheckpointData block;
  std::size_t first = 0;
  do {
    particle_state(p, block, first, rows);
    add(block);
    first += rows;
  } while (first < p.size());
}

CheckpointRows Simulation::particle_rows(const AxisRange& region) {
  CheckpointRows rows;
  rows.arrays = {"particles.pos",  "particles.vel", "particles.ghost", "particles.rho",
                 "particles.kind", "particles.id",  "particles.group"};
  rows.key_width = 3;
  if (!(region.lo < region.hi)) return rows;  // no row: the positions are not read to find none
  // A row whose position is not finite lies in no slab: every process reads it, so that
  // restore_state reports a damaged checkpoint rather than the particle going missing.
  rows.keep = [region](std::span<const double> x) {
    return region.contains({x[0], x[1], x[2]}) || !std::isfinite(x[region.axis]);
  };
  return rows;
}

void Simulation::save_state(CheckpointData& c) const {
  sync_from_device();
  particle_state(p_, c);
  save_global_state(c);
}

void Simulation::save_global_state(CheckpointData& c) const {
  sync_from_device();
  c.u32["particles.next_id"] = {p_.next_id};

  c.f64["sim.time"] = {time_};
  c.f64["sim.steps"] = {static_cast<double>(steps_)};
  c.f64["sim.dt_floor"] = {dt_floor_};
  const StepDiagnostics& d = diag_;
  c.f64["diag"] = {d.dt_limits.force,
                   d.dt_limits.acoustic,
                   d.dt_limits.viscous,
                   d.dt_limits.dt,
                   d.max_speed,
                   static_cast<double>(d.lost_total),
                   static_cast<double>(d.resorts),
                   static_cast<double>(d.open.entered_fluid),
                   static_cast<double>(d.open.created),
                   static_cast<double>(d.open.removed),
                   static_cast<double>(d.open.absorbed),
                   static_cast<double>(d.mdbc_fallbacks)};

  auto& bodies = c.f64["bodies"];
  for (const RigidBody& b : scene_.bodies) {
    put3(bodies, b.state.com);
    bodies.push_back(b.state.q.w), bodies.push_back(b.state.q.x);
    bodies.push_back(b.state.q.y), bodies.push_back(b.state.q.z);
    put3(bodies, b.state.vel), put3(bodies, b.state.omega);
    put3(bodies, b.fluid_force), put3(bodies, b.fluid_torque);
    put3(bodies, b.contact_force), put3(bodies, b.contact_torque);
  }
  // The modelled loads (a net's sinker bar) apart: checkpoints before 2026-12-03 lack them.
  auto& modelled = c.f64["bodies.modelled"];
  for (const RigidBody& b : scene_.bodies)
    put3(modelled, b.modelled_force), put3(modelled, b.modelled_torque);
  auto& knots = c.f64["nets.knots"];
  for (const CoupledNet& net : nets_)
    for (const NetKnot& k : net.model.knots) put3(knots, k.position), put3(knots, k.velocity);
  // Each net's count of sinker reactions given at the bar and its first knot (2026-12-03 on).
  auto& at_bar = c.f64["nets.reactions_at_bar"];
  for (const CoupledNet& net : nets_) {
    at_bar.push_back(static_cast<double>(net.reactions_at_bar));
    at_bar.push_back(static_cast<double>(net.first_knot_reacting_at_bar));
  }
  // The paddle's active absorption: its correction and the elevations its delay still needs.
  if (absorber_) c.f64["waves.absorber"] = absorber_->state();
}

void Simulation::restore_state(const CheckpointData& c, const AxisRange& keep) {
  const auto fail = [&](const std::string& what) {
    throw Error(c.source, what + ": the checkpoint was written for another case");
  };
  const std::vector<double>& pos = c.reals("particles.pos");
  const std::size_t n = pos.size() / 3;
  const auto& vel = c.f32.at("particles.vel");
  const auto& ghost = c.f32.at("particles.ghost");
  const auto& rho = c.f32.at("particles.rho");
  const auto& kind = c.u8.at("particles.kind");
  const auto& id = c.u32.at("particles.id");
  const auto& group = c.u32.at("particles.group");
  if (vel.size() != 3 * n || ghost.size() != 3 * n || rho.size() != n || kind.size() != n ||
      id.size() != n || group.size() != n) {
    fail("particle arrays of different lengths");
  }
  const std::vector<double>& bodies = c.reals("bodies");
  constexpr std::size_t kPerBody = 25;
  if (bodies.size() != kPerBody * scene_.bodies.size())
    fail(fmt::format("{} bodies in the checkpoint, {} in the case", bodies.size() / kPerBody,
                     scene_.bodies.size()));
  const std::vector<double>& knots = c.reals("nets.knots");
  std::size_t knot_count = 0;
  for (const CoupledNet& net : nets_) knot_count += net.model.knots.size();
  if (knots.size() != 6 * knot_count) fail("the nets' knots differ");
  check_restored_particles(c, scene_, pos, vel, ghost, rho, kind, id);
  const auto corrupt = [&](const std::string& what) {
    throw Error(c.source, "the checkpoint is corrupt (damaged after it was written): " + what +
                              " not finite. It cannot be continued: put back a good copy of "
                              "the file, or start the run again");
  };
  for (std::size_t b = 0; b < scene_.bodies.size(); ++b)
    if (!all_finite({bodies.data() + kPerBody * b, kPerBody}))
      corrupt("the state of body '" + scene_.bodies[b].name + "' is");
  if (!all_finite(knots)) corrupt("the nets' knots are");
  if (!all_finite(c.reals("sim.time")) || !all_finite(c.reals("sim.dt_floor")))
    corrupt("the time is");

  const auto position = [&](std::size_t i) {
    return Vec3d{pos[3 * i], pos[3 * i + 1], pos[3 * i + 2]};
  };
  std::size_t kept = n;
  if (!keep.everything()) {
    kept = 0;
    for (std::size_t i = 0; i < n; ++i) kept += keep.contains(position(i));
  }
  p_ = ParticleSet{};
  p_.reserve_more(kept);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3d x = position(i);
    if (!keep.everything() && !keep.contains(x)) continue;
    p_.pos.push_back(x);
    p_.vel.push_back({vel[3 * i], vel[3 * i + 1], vel[3 * i + 2]});
    p_.ghost.push_back({ghost[3 * i], ghost[3 * i + 1], ghost[3 * i + 2]});
    p_.rho.push_back(rho[i]);
    p_.kind.push_back(static_cast<ParticleKind>(kind[i]));
    p_.id.push_back(id[i]);
    p_.group.push_back(group[i]);
  }
  p_.next_id = c.u32.at("particles.next_id").at(0);

  time_ = c.real("sim.time");
  steps_ = static_cast<std::int64_t>(c.real("sim.steps"));
  dt_floor_ = c.real("sim.dt_floor");
  // A dt_min given now (a restart may change it with --set) replaces the checkpoint's floor;
  // without one the floor stays 1e-4 of the run's first step.
  if (spec_.simulation.dt_min > 0) dt_floor_ = spec_.simulation.dt_min;
  const std::vector<double>& d = c.reals("diag");
  if (d.size() != 12) fail("diagnostics of another version");
  diag_.dt_limits = {d[0], d[1], d[2], d[3]};
  diag_.max_speed = d[4];
  diag_.lost_total = static_cast<std::size_t>(d[5]);
  diag_.resorts = static_cast<int>(d[6]);
  diag_.open = {static_cast<std::size_t>(d[7]), static_cast<std::size_t>(d[8]),
                static_cast<std::size_t>(d[9]), static_cast<std::size_t>(d[10])};
  diag_.mdbc_fallbacks = static_cast<std::size_t>(d[11]);

  const auto vec = [](const double* v) { return Vec3d{v[0], v[1], v[2]}; };
  for (std::size_t b = 0; b < scene_.bodies.size(); ++b) {
    const double* v = bodies.data() + kPerBody * b;
    RigidBody& body = scene_.bodies[b];
    body.state.com = vec(v);
    body.state.q = {v[3], v[4], v[5], v[6]};
    body.state.vel = vec(v + 7), body.state.omega = vec(v + 10);
    body.fluid_force = vec(v + 13), body.fluid_torque = vec(v + 16);
    body.contact_force = vec(v + 19), body.contact_torque = vec(v + 22);
    body.start = body.state;
  }
  if (const auto m = c.f64.find("bodies.modelled"); m != c.f64.end()) {
    if (m->second.size() != 6 * scene_.bodies.size()) fail("the bodies differ");
    for (std::size_t b = 0; b < scene_.bodies.size(); ++b) {
      scene_.bodies[b].modelled_force = vec(m->second.data() + 6 * b);
      scene_.bodies[b].modelled_torque = vec(m->second.data() + 6 * b + 3);
    }
  }
  std::size_t k = 0;
  for (CoupledNet& net : nets_) {
    for (NetKnot& knot : net.model.knots) {
      knot.position = vec(knots.data() + 6 * k), knot.velocity = vec(knots.data() + 6 * k + 3);
      ++k;
    }
  }
  // Older checkpoints lack the count: it then starts again from the restart.
  if (const auto a = c.f64.find("nets.reactions_at_bar"); a != c.f64.end()) {
    if (a->second.size() != 2 * nets_.size()) fail("the nets differ");
    for (std::size_t i = 0; i < nets_.size(); ++i) {
      nets_[i].reactions_at_bar = static_cast<std::size_t>(a->second[2 * i]);
      nets_[i].first_knot_reacting_at_bar = static_cast<std::size_t>(a->second[2 * i + 1]);
    }
  }
  if (absorber_) {
    const auto a = c.f64.find("waves.absorber");
    if (a == c.f64.end()) fail("the paddle's active absorption is missing");
    absorber_->restore(a->second);
  }
  // The device backends continue from the restored particles and bodies.
  if (device_) start_device();
}

}  // namespace netsph
