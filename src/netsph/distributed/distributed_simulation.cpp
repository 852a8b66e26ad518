#include "netsph/distributed/distributed_simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <optional>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "netsph/distributed/scene_parts.hpp"

namespace netsph {
namespace {

/// Collective: rethrows on every process the error of the first that failed, if any did.
void rethrow_if_any_failed(Collectives& coll, const Error* error) {
  const int first = coll.min(error ? coll.rank() : coll.size());
  if (first == coll.size()) return;
  std::string where = error ? error->where() : std::string(), text = error ? error->message() : "";
  coll.broadcast(where, first);
  coll.broadcast(text, first);
  throw Error(where, text);
}

/// Collective: this process's part of the case (scene_parts.hpp), each particle on one
/// process. A restored run keeps the checkpoint's particles in its region (the caller read
/// the whole checkpoint).
std::unique_ptr<Simulation> own_part(const CaseSpec& spec, Collectives& coll,
                                     const CheckpointData* resume) {
  const AxisRange region = set_up_region(spec, coll.size(), coll.rank());
  std::unique_ptr<Simulation> sim;
  // Errors before the bounds' reduction come from the case alone (alike on every process);
  // those after it may come from one process's particles.
  std::optional<Error> error;
  try {
    const WholeBounds whole = [&coll](Vec3d& lo, Vec3d& hi) {
      for (int a = 0; a < 3; ++a) lo[a] = -coll.max(-lo[a]), hi[a] = coll.max(hi[a]);
    };
    sim = std::make_unique<Simulation>(spec, StepBackend::Cpu, [&](const CaseSpec& s) {
      return build_scene_part(s, region, whole);
    });
    if (resume) sim->restore_state(*resume, region);
  } catch (const Error& e) {
    error = e;
  } catch (const std::exception& e) {  // out of memory in one part, say: stop all, not hang
    error = Error("distributed set-up", e.what());
  }
  rethrow_if_any_failed(coll, error ? &*error : nullptr);
  return sim;
}

std::vector<ZoneGeometry> zone_geometries(const Simulation& sim) {
  std::vector<ZoneGeometry> zones;
  for (const OpenBoundaryZone& z : sim.scene().zones) zones.push_back(z.geometry());
  return zones;
}

SlabPartition make_slabs(const Simulation& sim, Collectives& coll, const GhostReach& ghosts,
                         const std::vector<ZoneGeometry>& zones) {
  SlabPartition s = balanced_slabs(sim.particles(), sim.grid(), sim.scene().domain_min,
                                   sim.scene().domain_max, coll);
  s.halo = halo_width(s, ghosts, sim.grid(), sim.model().support, zones);
  return s;
}

Bytes pack_lost(const std::vector<StepDiagnostics::Lost>& lost) {
  Bytes b(lost.size() * sizeof(StepDiagnostics::Lost));
  if (!lost.empty()) std::memcpy(b.data(), lost.data(), b.size());
  return b;
}

}  // namespace

DistributedSimulation::DistributedSimulation(const CaseSpec& spec, Collectives& coll,
                                             const CheckpointData* resume,
                                             RebalancePolicy rebalance)
    : coll_(coll),
      local_(own_part(spec, coll, resume)),
      zones_(zone_geometries(*local_)),
      ghost_reach_(ghost_reach(local_->particles(), zones_, coll)),
      slabs_(make_slabs(*local_, coll, ghost_reach_, zones_)),
      exchange_(slabs_, coll),
      rebalance_(rebalance) {
  Simulation& sim = *local_;
  // Each part counted its own fluid at the start (a restored run's too, before the restore).
  initial_fluid_ = coll_.sum(std::uint64_t{sim.initial_fluid()});
  // A restored run's counts so far are the whole run's: every process starts from them and
  // adds only its own events.
  lost_total_ = sim.diagnostics().lost_total;
  open_base_ = sim.diagnostics().open;
  count_base_ = coll_.sum(std::uint64_t{sim.particles().size()}) + open_base_.removed +
                lost_total_ - open_base_.created;
  diag_ = sim.diagnostics();
  sim.set_partition(this);
  // The parts go to the owners of the balanced slabs, and the halo is sent.
  exchange_.own_all(sim.particles());
  check_lost(exchange_.exchange(sim.particles(), sim.grid()));
  // Sorted as a step would, so that outputs before the first step find the particles with
  // the grid (sample_own).
  sim.sort_by_cell();
  std::vector<double> held = {static_cast<double>(sim.particles().size()),
                              static_cast<double>(exchange_.owned_count())};
  coll_.sum(held);
  if (coll_.rank() == 0) {
    std::string cuts;
    for (double c : slabs_.cuts) cuts += fmt::format("{}{:.4g}", cuts.empty() ? "" : ", ", c);
    spdlog::info("distributed over {} processes: slabs along {} cut at {} m, halo {:.4g} m",
                 coll_.size(), "xyz"[slabs_.axis], cuts, slabs_.halo);
    spdlog::info("halo: {:.0f} copies, {:.1f}% of the case's particles", held[0] - held[1],
                 100 * (held[0] - held[1]) / std::max(held[1], 1.0));
    for (int r = 0; r < slabs_.ranks(); ++r) {
      if (slabs_.cuts[r + 1] - slabs_.cuts[r] < slabs_.halo) {
        spdlog::warn(
            "slab {} is {:.4g} m long, shorter than the halo ({:.4g} m): each process "
            "holds more copies than particles of its own; fewer processes would do",
            r, slabs_.cuts[r + 1] - slabs_.cuts[r], slabs_.halo);
        break;
      }
    }
  }
}

DistributedSimulation::~DistributedSimulation() = default;

void DistributedSimulation::step() {
  ExchangeReport moved;
  if (exchange_due_) moved = exchange_particles();
  std::string message;
  bool failed = false;
  const auto t0 = std::chrono::steady_clock::now();
  try {
    local_->step();
  } catch (const SimulationUnstable& e) {
    failed = true;
    message = e.message();
  }
  step_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // The step's collectives all come before the checks that throw (solver/simulation.cpp), so
  // every process gets here; the first to fail speaks for all.
  const int first = coll_.min(failed ? coll_.rank() : coll_.size());
  if (first < coll_.size()) {
    coll_.broadcast(message, first);
    throw SimulationUnstable("solver", first == coll_.rank() || coll_.size() == 1
                                           ? message
                                           : fmt::format("{} (process {})", message, first));
  }
  // The exchange's losses and the step's open-boundary events, over all processes: the
  // diagnostics are the whole run's as of this step.
  check_lost(moved);
  exchange_due_ = true;
}

ExchangeReport DistributedSimulation::exchange_particles() {
  // Before the step rather than after the last: between steps the particles stay where the
  // step left them, with the grid it sorted them into, for the outputs (as on one process,
  // whose step drops the particles that left the domain when it sorts them).
  exchange_due_ = false;
  Simulation& sim = *local_;
  const auto t0 = std::chrono::steady_clock::now();
  const ExchangeReport report = exchange_.exchange(sim.particles(), sim.grid());
  exchange_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (rebalance_.check_every > 0 && sim.steps() % rebalance_.check_every == 0) {
    const auto t1 = std::chrono::steady_clock::now();
    rebalance_if_needed();
    exchange_seconds_ +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  }
  return report;
}

double DistributedSimulation::own_work() const {
  const ParticleSet& p = local_->particles();
  double w = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (exchange_.owned(p.id[i])) w += particle_work(p.kind[i]);
  return w;
}

void DistributedSimulation::rebalance_if_needed() {
  // Each process's own work, known to all.
  std::vector<double> shares(coll_.size(), 0.0);
  shares[coll_.rank()] = own_work();
  coll_.sum(shares);
  const double before = work_imbalance(shares);
  if (!(before > rebalance_.threshold)) return;
  // The whole run's work along the axis: every process's own particles, summed.
  Simulation& sim = *local_;
  const ParticleSet& p = sim.particles();
  const double lo = slabs_.cuts.front(), hi = slabs_.cuts.back();
  WorkHistogram work(lo, hi, sim.grid().cell_size()[slabs_.axis]);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (exchange_.owned(p.id[i]))
      work.add(std::clamp(slabs_.coordinate(p.pos[i]), lo, hi), p.kind[i]);
  }
  coll_.sum(work.bins);
  const std::vector<double> cuts = equal_work_cuts(work, hi, coll_.size());
  if (cuts == slabs_.cuts) return;  // the best cut on cell boundaries already
  // The new slabs' work, from the same histogram (the cuts lie on its bin boundaries).
  std::vector<double> after(coll_.size(), 0.0);
  for (std::size_t k = 0; k < work.bins.size(); ++k) {
    const double centre = lo + (static_cast<double>(k) + 0.5) * work.cell;
    const auto slab = std::upper_bound(cuts.begin() + 1, cuts.end() - 1, centre) - cuts.begin() - 1;
    after[slab] += work.bins[k];
  }
  slabs_.cuts = cuts;
  slabs_.halo = halo_width(slabs_, ghost_reach_, sim.grid(), sim.model().support, zones_);
  exchange_.slabs_changed();
  check_lost(exchange_.exchange(sim.particles(), sim.grid()));
  ++rebalances_;
  if (coll_.rank() == 0) {
    std::string at;
    for (double c : cuts) at += fmt::format("{}{:.4g}", at.empty() ? "" : ", ", c);
    spdlog::debug(
        "step {}: slabs cut again at {} m: the busiest process's own work {:.3f} of "
        "the mean, now {:.3f}",
        sim.steps(), at, before, work_imbalance(after));
  }
}

namespace {

/// Adds the seconds from its construction to its destruction to `sum`.
class ScopeTimer {
 public:
  explicit ScopeTimer(double& sum) : sum_(sum), t0_(std::chrono::steady_clock::now()) {}
  ~ScopeTimer() {
    sum_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
  }
  ScopeTimer(const ScopeTimer&) = delete;
  ScopeTimer& operator=(const ScopeTimer&) = delete;

 private:
  double& sum_;
  std::chrono::steady_clock::time_point t0_;
};

}  // namespace

double DistributedSimulation::global_max(double v) const {
  const ScopeTimer wait(wait_seconds_);
  return coll_.max(v);
}

void DistributedSimulation::global_sum(std::span<double> v) const {
  const ScopeTimer wait(wait_seconds_);
  coll_.sum(v);
}

void DistributedSimulation::number_created(ParticleSet& p, std::size_t first,
                                           const OpenBoundaryEvents& events) {
  // The processes that own the parents speak for the particles created from them; every
  // process holding a copy of a parent created the same particle, and numbers it by its
  // parent's rank among all parents of the step.
  std::vector<std::uint32_t> parents;
  for (const std::uint32_t parent : events.created_from)
    if (exchange_.owned(parent)) parents.push_back(parent);
  Bytes mine(parents.size() * sizeof(std::uint32_t));
  if (!parents.empty()) std::memcpy(mine.data(), parents.data(), mine.size());
  std::vector<Bytes> received;
  {
    const ScopeTimer wait(wait_seconds_);
    received = coll_.exchange(std::vector<Bytes>(coll_.size(), mine));
  }
  for (int r = 0; r < coll_.size(); ++r) {
    if (r == coll_.rank()) continue;
    const std::size_t at = parents.size();
    parents.resize(at + received[r].size() / sizeof(std::uint32_t));
    if (!received[r].empty())
      std::memcpy(parents.data() + at, received[r].data(), received[r].size());
  }
  std::sort(parents.begin(), parents.end());
  // Every process entered the step with the same next id.
  const std::uint32_t base = p.next_id - static_cast<std::uint32_t>(events.created_from.size());
  for (std::size_t k = 0; k < events.created_from.size(); ++k) {
    const std::uint32_t parent = events.created_from[k];
    const auto it = std::lower_bound(parents.begin(), parents.end(), parent);
    if (it == parents.end() || *it != parent) {
      throw Error("distributed", fmt::format("particle {} created a buffer particle on process {} "
                                             "but not on its owner: the halo is too thin",
                                             parent, coll_.rank()));
    }
    const std::uint32_t id = base + static_cast<std::uint32_t>(it - parents.begin());
    p.id[first + k] = id;
    if (exchange_.owned(parent)) exchange_.set_owned(id, true);
  }
  p.next_id = base + static_cast<std::uint32_t>(parents.size());
  for (const std::uint32_t id : events.removed) exchange_.set_owned(id, false);
}

void DistributedSimulation::check_lost(const ExchangeReport& report) {
  // Losses and open-boundary events (each process counted its own) over all processes.
  const OpenBoundaryCounts& open = local_->diagnostics().open;
  const OpenBoundaryCounts& base = open_base_;
  const auto events = [](std::size_t now, std::size_t before) {
    return static_cast<double>(now - before);
  };
  std::vector<double> counts = {
      static_cast<double>(report.lost), events(open.entered_fluid, base.entered_fluid),
      events(open.created, base.created), events(open.removed, base.removed),
      events(open.absorbed, base.absorbed)};
  coll_.sum(counts);
  const auto lost = static_cast<std::uint64_t>(counts[0]);
  const auto total = [](double sum, std::size_t before) {
    return before + static_cast<std::size_t>(sum);
  };
  diag_ = local_->diagnostics();
  diag_.open = {total(counts[1], base.entered_fluid), total(counts[2], base.created),
                total(counts[3], base.removed), total(counts[4], base.absorbed)};
  lost_total_ += lost;
  diag_.lost_total = lost_total_;
  // The last to leave, as process 0 reports them (gathered only when some left).
  if (lost > 0) {
    const std::vector<Bytes> all = coll_.gather(pack_lost(report.last_lost));
    for (const Bytes& b : all) {
      const std::size_t n = b.size() / sizeof(StepDiagnostics::Lost);
      for (std::size_t k = 0; k < n; ++k) {
        StepDiagnostics::Lost l;
        std::memcpy(&l, b.data() + k * sizeof l, sizeof l);
        remember_lost(last_lost_, l);
      }
    }
  }
  diag_.last_lost = last_lost_;
  check_lost_fluid(local_->spec(), local_->time(), local_->steps(), lost, lost_total_,
                   initial_fluid_, last_lost_);
}

void DistributedSimulation::gather_into(Simulation* whole) const {
  ParticleSet p;
  p.next_id = local_->particles().next_id;
  coll_.gather_each(exchange_.pack_owned(local_->particles()),
                    [&p](int, const Bytes& b) { ParticleExchange::unpack(b, p); });
  if (whole) whole->adopt_state(*local_, diag_, std::move(p));
}

}  // namespace netsph
