#include "netsph/distributed/distributed_stepper.hpp"

#include <cstring>
#include <exception>
#include <limits>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "netsph/sph/fluid_sampler.hpp"

namespace netsph {

namespace {

// What process 0 asks the others to take part in (the first byte of a broadcast).
enum class Read : char {
  Measure = 'm',
  Sample = 's',
  Count = 'c',
  Pieces = 'p',
  Done = 'd',
  Failed = 'f',  // followed by the error's message
};

std::string command(Read r, ParticleSelection which = ParticleSelection::All) {
  return {static_cast<char>(r), static_cast<char>(which)};
}

ParticleSelection selection_of(const std::string& c) {
  return static_cast<ParticleSelection>(c.at(1));
}

}  // namespace

/// Process 0's reads: each names itself to the serving processes, then takes part.
class DistributedStepper::Reads final : public OutputParticles {
 public:
  explicit Reads(DistributedStepper& s) : s_(s) {}
  GlobalMeasures measure() override {
    say(command(Read::Measure));
    return s_.measure_all();
  }
  void sample(std::span<const Vec3d> points, std::span<ShepardValue> values) override {
    std::string c = command(Read::Sample);
    c.resize(2 + points.size_bytes());
    std::memcpy(c.data() + 2, points.data(), points.size_bytes());
    say(c);
    s_.sample_all(points, values);
  }
  std::uint64_t count(ParticleSelection which) override {
    say(command(Read::Count, which));
    return s_.count_all(which);
  }
  void pieces(ParticleSelection which,
              const std::function<void(const ParticleSet&)>& take) override {
    say(command(Read::Pieces, which));
    s_.pieces_all(which, take);
  }

 private:
  void say(std::string c) { s_.coll_.broadcast(c, 0); }
  DistributedStepper& s_;
};

DistributedStepper::DistributedStepper(const CaseSpec& spec, Collectives& coll,
                                       const CheckpointData* resume, RebalancePolicy rebalance)
    : coll_(coll), sim_(spec, coll, resume, rebalance) {
  // The view: process 0's scene without its particles, and the counts of removed fluid, buffer
  // particles and bodies' overlaps summed over the parts (the case's own, as one process would
  // report them).
  const Scene& part = sim_.local().scene();
  std::vector<double> counts = {static_cast<double>(part.removed_overlaps),
                                static_cast<double>(part.removed_in_bodies)};
  for (const std::size_t n : part.buffer_counts) counts.push_back(static_cast<double>(n));
  coll_.sum(counts);
  const std::vector<Bytes> overlaps = coll_.gather(part.solid_overlaps.pack());
  if (coll_.rank() != 0) return;
  Scene whole = part.without_particles();
  whole.solid_overlaps = {};
  for (const Bytes& b : overlaps) whole.solid_overlaps.add(SolidOverlaps::unpack(b));
  whole.removed_overlaps = static_cast<std::size_t>(counts[0]);
  whole.removed_in_bodies = static_cast<std::size_t>(counts[1]);
  for (std::size_t z = 0; z < whole.buffer_counts.size(); ++z)
    whole.buffer_counts[z] = static_cast<std::size_t>(counts[2 + z]);
  report_particle_counts(whole, spec);
  view_ = std::make_unique<Simulation>(spec, StepBackend::Cpu,
                                       [&whole](const CaseSpec&) { return std::move(whole); });
  if (resume) view_->restore_state(*resume, AxisRange::nothing());
  reads_ = std::make_unique<Reads>(*this);
}

DistributedStepper::~DistributedStepper() = default;

void DistributedStepper::refresh_view() {
  if (view_) view_->adopt_global_state(sim_.local(), sim_.diagnostics());
}

OutputParticles& DistributedStepper::particles() {
  if (!reads_) throw Error("distributed", "only process 0 reads the particles for the outputs");
  return *reads_;
}

void DistributedStepper::outputs_written() {
  std::string done = command(Read::Done);
  coll_.broadcast(done, 0);
}

void DistributedStepper::outputs_failed(const std::string& message) {
  std::string failed = command(Read::Failed) + message;
  coll_.broadcast(failed, 0);
}

void DistributedStepper::serve_outputs() {
  for (;;) {
    std::string c;
    coll_.broadcast(c, 0);
    switch (static_cast<Read>(c.at(0))) {
      case Read::Measure:
        measure_all();
        break;
      case Read::Sample: {
        std::vector<Vec3d> points((c.size() - 2) / sizeof(Vec3d));
        if (!points.empty()) std::memcpy(points.data(), c.data() + 2, c.size() - 2);
        std::vector<ShepardValue> values(points.size());
        sample_all(points, values);
        break;
      }
      case Read::Count:
        count_all(selection_of(c));
        break;
      case Read::Pieces:
        pieces_all(selection_of(c), {});
        break;
      case Read::Done:
        return;
      case Read::Failed:
        throw Error("outputs of process 0", c.substr(2));
      default:
        throw Error("distributed", fmt::format("unknown request '{}' from process 0", c.at(0)));
    }
  }
}

GlobalMeasures DistributedStepper::measure_all() {
  GlobalMeasures g = sim_.measure_own();
  std::vector<double> sums = {static_cast<double>(g.fluid), static_cast<double>(g.walls),
                              static_cast<double>(g.buffer), g.kinetic_energy};
  coll_.sum(sums);
  // Extremes over the processes that hold fluid.
  const double none = -std::numeric_limits<double>::infinity();
  const double max_speed = coll_.max(g.max_speed);
  const double max_density = coll_.max(g.fluid ? g.max_density : none);
  const double min_density = -coll_.max(g.fluid ? -g.min_density : none);
  GlobalMeasures all;
  all.fluid = static_cast<std::size_t>(sums[0]);
  all.walls = static_cast<std::size_t>(sums[1]);
  all.buffer = static_cast<std::size_t>(sums[2]);
  all.kinetic_energy = sums[3];
  all.fluid_mass = sim_.local().model().mass * sums[0];
  all.max_speed = max_speed;
  all.max_density = all.fluid ? max_density : 0;
  all.min_density = all.fluid ? min_density : 0;
  return all;
}

void DistributedStepper::sample_all(std::span<const Vec3d> points, std::span<ShepardValue> values) {
  std::vector<ShepardSums> own(points.size());
  sim_.sample_own(points, own);
  sum_over_processes(own, [&](std::span<double> v) { coll_.sum(v); });
  for (std::size_t k = 0; k < own.size(); ++k) values[k] = shepard_value(own[k]);
}

std::uint64_t DistributedStepper::count_all(ParticleSelection which) {
  return coll_.sum(sim_.count_own(which));
}

void DistributedStepper::pieces_all(ParticleSelection which,
                                    const std::function<void(const ParticleSet&)>& take) {
  // Process 0 unpacks each process's particles as they come and hands them on, in blocks of
  // rows: it holds one process's bytes and a block, not a second copy of the process's share.
  // Should take() fail (a full disk), the gather still runs to its end, so that no process is
  // left waiting in it, and the error is thrown after.
  ParticleSet piece;
  std::exception_ptr failed;
  coll_.gather_each(sim_.pack_own(which), [&](int, const Bytes& b) {
    const std::size_t rows = ParticleExchange::packed_count(b);
    std::size_t first = 0;
    do {  // at least one piece a process, if empty
      if (failed) return;
      piece = ParticleSet{};
      ParticleExchange::unpack(b, piece, first, block_rows_);
      try {
        take(piece);
      } catch (...) {
        failed = std::current_exception();
      }
      first += block_rows_;
    } while (first < rows);
  });
  if (failed) std::rethrow_exception(failed);
}

double DistributedStepper::bytes_per_particle() const {
  // This process's memory over the particles it owns: the halo's copies count against them.
  const Simulation& local = sim_.local();
  const double owned = static_cast<double>(std::max<std::size_t>(sim_.owned_count(), 1));
  return local.bytes_per_particle() * static_cast<double>(local.particle_count()) / owned;
}

void DistributedStepper::finish() {
  const double mine[3] = {sim_.work_seconds(), sim_.wait_seconds(), sim_.exchange_seconds()};
  Bytes b(sizeof mine);
  std::memcpy(b.data(), mine, sizeof mine);
  const std::vector<Bytes> all = coll_.gather(b);
  if (all.empty()) return;
  std::string line;
  for (std::size_t r = 0; r < all.size(); ++r) {
    double t[3];
    std::memcpy(t, all[r].data(), sizeof t);
    line += fmt::format("{}process {}: {:.1f} s working, {:.1f} s waiting, {:.1f} s exchanging",
                        line.empty() ? "" : "; ", r, t[0], t[1], t[2]);
  }
  spdlog::info("distributed run: {}; slabs cut again {} time{}", line, sim_.rebalances(),
               sim_.rebalances() == 1 ? "" : "s");
}

}  // namespace netsph
