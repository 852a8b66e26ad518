#pragma once
// Simulation: one run of a case. It owns the particles, the neighbour grid and the per-step
// work arrays, and advances the state with the symplectic scheme and variable dt:
//
//   step():  open boundaries: buffer -> fluid, new inlet particles, outflow removed
//            wrap periodic axes; sort by cell (drops particles that left the domain)
//            open-boundary buffer state (imposed / extrapolated); mDBC wall state
//            view of state n  -> rates a^n, drho^n (+ body contacts)  -> dt (CFL)
//            save state n     -> body forces -> bodies' stage -> water loads (sinker bars'
//                                reaction) -> predictor (half step), bodies included
//            [re-sort if the half step moved a particle past the grid skin]
//            view of half step -> rates (+ shifting sums) -> body forces -> bodies' stage ->
//                                water loads -> corrector
//            checks: non-finite state, dt below the floor
//
// run_simulation (run/runner.hpp) adds the outputs (snapshots, series.csv, summary.json) and
// the progress display.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "netsph/backend/cpu/contact.hpp"
#include "netsph/backend/cpu/ghost_pass.hpp"
#include "netsph/backend/cpu/integrate.hpp"
#include "netsph/backend/cpu/interaction_view.hpp"
#include "netsph/backend/cpu/rates.hpp"
#include "netsph/backend/device/device_run.hpp"
#include "netsph/case/case_spec.hpp"
#include "netsph/core/error.hpp"
#include "netsph/io/checkpoint_file.hpp"
#include "netsph/neighbours/cell_grid.hpp"
#include "netsph/setup/scene.hpp"
#include "netsph/solver/net_coupling.hpp"
#include "netsph/solver/step_partition.hpp"
#include "netsph/sph/lost_particle.hpp"
#include "netsph/sph/particle_tally.hpp"
#include "netsph/sph/shepard.hpp"
#include "netsph/sph/shifting.hpp"
#include "netsph/sph/time_step.hpp"
#include "netsph/waves/active_absorption.hpp"

namespace netsph {

/// Thrown by step() when the state becomes unusable; run_stepped (run/runner.cpp) catches it,
/// writes what it can and reports it.
class SimulationUnstable : public Error {
 public:
  using Error::Error;
};

struct StepDiagnostics {
  TimeStepLimits dt_limits;        ///< of the last step
  double max_speed = 0;            ///< m/s, fluid, end of step
  std::size_t lost_total = 0;      ///< particles removed for leaving the domain, since the start
  int resorts = 0;                 ///< extra sorts because the half step exceeded the grid skin
  OpenBoundaryCounts open;         ///< open-boundary events since the start
  std::size_t mdbc_fallbacks = 0;  ///< mDBC ghosts solved at zeroth order, last step
  /// The last particles that left the domain (not through an outlet): up to 5, for the report
  /// of a run stopped for losing fluid.
  using Lost = LostParticle;
  std::vector<Lost> last_lost;
};

/// Stops a run (SimulationUnstable) when fluid leaves the domain too fast: more than 1% of the
/// initial fluid (at least 10 particles) in one step, or more than
/// simulation.max_lost_fraction in all. `last_lost`: the last few, for the report.
void check_lost_fluid(const CaseSpec& spec, double time, std::int64_t steps,
                      std::size_t lost_this_step, std::size_t lost_total, std::size_t initial_fluid,
                      std::span<const StepDiagnostics::Lost> last_lost);

/// "id N at (x, y, z) m moving (u, v, w) m/s; ..." for each particle of `lost` (positions just
/// after they left the domain, so the face they crossed can be read off): empty when none is
/// known (the device backends count lost particles but do not keep them).
std::string describe_lost(std::span<const StepDiagnostics::Lost> lost);

/// Where the particle work of a step runs: the CPU backend (OpenMP, backend/cpu), the CUDA
/// device (the device-shaped step, backend/device on the CUDA executor), or that same step on
/// the host executor (slow: it exists to check the CUDA backend's logic where there is no GPU).
enum class StepBackend { Cpu, Cuda, HostDevice };

class Simulation {
 public:
  /// Throws netsph::Error for StepBackend::Cuda when netsph was built without CUDA or finds no
  /// usable device.
  explicit Simulation(const CaseSpec& spec, StepBackend backend = StepBackend::Cpu);
  /// With the particles `build` makes of the case (with its nets' knots as bodies): one
  /// process's part of the scene in a distributed run (build_scene_part).
  Simulation(const CaseSpec& spec, StepBackend backend,
             const std::function<Scene(const CaseSpec&)>& build);
  ~Simulation();

  /// Advances one symplectic step. Throws SimulationUnstable.
  void step();

  const CaseSpec& spec() const { return spec_; }
  const Scene& scene() const { return scene_; }
  const FluidModel& model() const { return scene_.model; }
  /// The grid of the last sort (on the device backends: copied back on first use after a step).
  const CellGrid& grid() const {
    sync_from_device();
    return grid_;
  }
  /// The particles, sorted by cell (on the device backends: copied back on first use after a
  /// step, so outputs cost a transfer only when they are written).
  const ParticleSet& particles() const {
    sync_from_device();
    return p_;
  }
  /// On the device backends, the measures of the particles (sph/particle_tally.hpp) reduced
  /// on the device, without copying them back; nullopt on the CPU backend.
  std::optional<ParticleTally> tally_on_device() const;
  /// On the device backends, samples the fluid at `points` on the device (the CPU's probe
  /// sampling, backend/cpu/probe_pass.hpp) and returns true; false on the CPU backend.
  bool sample_on_device(std::span<const Vec3d> points, std::span<ShepardValue> values) const;
  /// How many times the particles were copied back from the device (outputs, checkpoints,
  /// diagnostics); 0 on the CPU backend.
  std::int64_t device_downloads() const { return device_downloads_; }
  /// The number of particles, without a transfer from the device.
  std::size_t particle_count() const { return device_ ? device_->size() : p_.size(); }
  StepBackend backend() const { return backend_; }
  const std::vector<RigidBody>& bodies() const { return scene_.bodies; }
  /// The nets coupled with the fluid (knot positions as of the last stage).
  const std::vector<CoupledNet>& nets() const { return nets_; }
  std::vector<RigidBody>& bodies() { return scene_.bodies; }
  /// For set-up and tests on the CPU backend: on the device backends a change here does not
  /// reach the device (the next step overwrites it).
  ParticleSet& particles() {
    sync_from_device();
    return p_;
  }
  double time() const { return time_; }
  /// The paddle's active absorber ([waves] absorption = "active"), null without one.
  const PaddleAbsorber* absorber() const { return absorber_.get(); }
  std::int64_t steps() const { return steps_; }
  double last_dt() const { return diag_.dt_limits.dt; }
  const StepDiagnostics& diagnostics() const { return diag_; }
  double dt_floor() const { return dt_floor_; }
  /// Fluid particles of the case at the start (the reference of the lost-fluid check).
  std::size_t initial_fluid() const { return initial_fluid_; }
  bool shifting_enabled() const { return shift_on_; }

  /// Pressure of every particle from the equation of state.
  std::vector<float> pressures() const;
  /// Bytes held per particle by all per-particle arrays and the grid.
  double bytes_per_particle() const;
  /// The device step's phase profile (backend/device/phase_profile.hpp), on the device
  /// backends only (the CPU step is profiled with perf: docs/PERFORMANCE.md): on restarts its
  /// sums, off stops timing.
  void set_device_profiling(bool on);
  /// Seconds per phase of the device step since profiling was switched on; none on the CPU.
  std::optional<DevicePhaseTimes> device_phase_times() const;

  /// Makes this one process of a distributed run (distributed/distributed_simulation.hpp):
  /// dt, the bodies' loads and the largest speed come from the particles `partition` says
  /// this process owns, reduced over the processes; the caller exchanges particles between
  /// steps and checks for lost fluid over all of them. CPU backend only.
  /// `partition` must outlive the simulation.
  void set_partition(StepPartition* partition);
  const StepPartition* partition() const { return partition_; }

  /// For a distributed run's tests: this simulation takes `particles` (every process's own)
  /// and the time, step count, diagnostics, bodies and nets of `stepped` (one process's
  /// simulation of the same case), and sorts them so that grid() matches.
  void adopt_state(const Simulation& stepped, const StepDiagnostics& diagnostics,
                   ParticleSet&& particles);
  /// For a distributed run's outputs: the time, step count, next particle id, bodies and nets
  /// of `stepped` and the run's `diagnostics`.
  void adopt_global_state(const Simulation& stepped, const StepDiagnostics& diagnostics);
  /// Sorts the particles by cell as a step does first, so that grid() matches them (one
  /// process of a distributed run, after particles came and went in its first exchange).
  void sort_by_cell() { sort_particles(false); }

  /// Adds the state a restart needs to `c` (solver/simulation_checkpoint.cpp): that of
  /// save_global_state and the particles' (particle_state).
  void save_state(CheckpointData& c) const;
  /// Everything a restart needs but the particles' arrays (the time, bodies, nets, the next
  /// particle id...): a distributed run's checkpoint takes the particles from the processes.
  void save_global_state(CheckpointData& c) const;
  /// Sets the arrays of `c` to those of the particles first..first + count - 1 of `p` (count
  /// cut at its end); the checkpoint's particles are those of every call
  /// (write_checkpoint_file's pieces) in turn.
  static void particle_state(const ParticleSet& p, CheckpointData& c, std::size_t first = 0,
                             std::size_t count = std::numeric_limits<std::size_t>::max());
  /// Calls add() with the arrays of the particles `p` in blocks of `rows` (at least one call):
  /// a checkpoint written from them never holds a second copy of every particle.
  static void particle_state_blocks(const ParticleSet& p,
                                    const std::function<void(const CheckpointData&)>& add,
                                    std::size_t rows = std::size_t{1} << 18);
  /// The checkpoint's particles in `region` (read_checkpoint_file's rows): what one process
  /// of a distributed restart reads of the file.
  static CheckpointRows particle_rows(const AxisRange& region);
  /// Replaces the state with a checkpoint's, written by save_state for the same case; the
  /// steps that follow are then bit for bit those the saved run would have taken. `keep`:
  /// only the particles there (one process's region of a distributed run).
  void restore_state(const CheckpointData& c, const AxisRange& keep = {});

 private:
  // The device backends (simulation_device.cpp): the step runs in device_, bodies and nets stay
  // here (the step calls back into advance_bodies), particles come back on demand.
  void start_device();
  void device_step();
  void sync_from_device() const;

  void sort_particles(bool mid_step);
  /// The interaction view of the current state; `half_step` selects the walls' velocity.
  void build_view(bool half_step);
  /// The view's continuity velocity of solids under a mirror slip condition (their own);
  /// part of build_view, and called on its own after mDBC has set the solids' entries.
  void set_view_continuity_velocity(bool half_step);
  double compute_dt(const RateReductions& r);
  void update_wall_kinematics(double dt);
  /// [waves] absorption = "active" (solver/paddle_absorption.cpp): the absorber and its
  /// gauge, set up once; at each step's start the elevation measured at the gauge, less the
  /// target, updates the paddle's correction velocity; paddle_correction(w) is that velocity
  /// for wall w (zero for the others, and without absorption).
  void setup_absorber();
  void update_absorber();
  Vec3f paddle_correction(std::size_t wall) const;
  void apply_open_boundary_state();
  /// The state of mDBC wall and body particles from their ghost nodes; reads the fluid's from
  /// view_ (built before) and refreshes the solids' entries in it.
  void apply_mdbc();
  /// Positions (and, where they show it, velocities) and ghost vectors of body particles from
  /// the bodies' states; returns the largest body-particle displacement from the step start.
  double place_body_particles(bool from_step_start);
  /// Fluid and contact force and torque on every body from the last rates pass.
  void reduce_body_forces();
  /// Advances every body's state to the half step (predictor) or the full step, and adds what
  /// the modelled parts put on the water to the fluid's accelerations (add_water_loads).
  void advance_bodies(bool corrector, double dt);
  /// acc_ of the fluid particles += the stage's water_loads_ (sph/fluid_point_loads.hpp).
  void add_water_loads();
  /// The fluid at `points` as the stage has it (its positions and cell table), summed over the
  /// processes of a distributed run: what the nets' sinker bars take their flow from.
  void sample_fluid_at_stage(std::span<const Vec3d> points, std::span<ShepardValue> values);
  Vec3f body_point_velocity(std::size_t i) const;
  [[noreturn]] void fail_non_finite(std::int64_t index) const;
  /// On the first step: a simulation.dt_min above the first step's dt is the case's mistake,
  /// not a collapse; says so (netsph::Error) instead of blaming the particles.
  void check_dt_min_reachable(double first_dt) const;
  /// With a partition: owned_ from the present positions (exact right after the exchange).
  void mark_owned();
  /// With a partition: the first non-finite particle this process owns (or whose position is
  /// not finite), -1 if none.
  std::int64_t first_owned_non_finite() const;
  /// Stops the run when fluid leaves the domain too fast (SimulationSpec::max_lost_fraction).
  void check_lost(std::size_t lost_this_step) const;
  /// "particle id N (kind) at (x, y, z) m, velocity (...) m/s, |a| ..." of the fluid particle
  /// with the largest acceleration in the last rates pass.
  std::string fastest_accelerating() const;

  CaseSpec spec_;  ///< the case, with one [[body]] per net knot appended
  std::vector<CoupledNet> nets_;
  Scene scene_;
  ParticleSet& p_;
  mutable CellGrid grid_;  // mutable: the device backends copy its cell table back on demand
  InteractionView view_;
  StepStart start_;
  std::vector<Vec3f> acc_;
  std::vector<Real> drho_;
  std::vector<std::uint32_t> order_;
  std::vector<char> kept_;  // scratch of sort_particles: which particles the sort kept
  std::size_t initial_fluid_ = 0;
  std::vector<WallKinematics> walls_;  // by wall index
  ContactModel contact_model_;
  std::vector<Vec3f> contact_;               // contact acceleration of body particles
  std::vector<FluidPointLoad> water_loads_;  // the stage's sinker reactions on the water
  bool shift_on_ = false;
  ShiftingParams shift_params_;
  ShiftingSums shift_sums_;
  // Ghost-node scratch (mDBC walls, open-boundary buffers).
  std::vector<std::uint32_t> ghost_targets_;
  std::vector<Vec3d> ghost_points_;
  // Scratch for reordering, reused so the time loop allocates nothing once warm.
  std::vector<Vec3d> scratch_d3_;
  std::vector<Vec3f> scratch_f3_;
  std::vector<Real> scratch_f_;
  std::vector<ParticleKind> scratch_kind_;
  std::vector<std::uint32_t> scratch_u32_;

  double time_ = 0;
  std::int64_t steps_ = 0;
  double dt_floor_ = 0;
  StepDiagnostics diag_;

  StepPartition* partition_ = nullptr;
  std::vector<std::uint8_t> owned_;  // with a partition: which particles this process owns

  // The paddle's active absorption: the absorber, and its gauge's sample points up a vertical
  // line with their heights and the scratch of each measurement.
  std::unique_ptr<PaddleAbsorber> absorber_;
  std::vector<Vec3d> absorber_points_;
  std::vector<double> absorber_z_, absorber_coverage_;
  std::vector<ShepardValue> absorber_values_;
  std::vector<ShepardSums> absorber_sums_;  // the CPU step's sums, kept: no allocation per step

  StepBackend backend_ = StepBackend::Cpu;
  std::unique_ptr<DeviceRun> device_;
  // Particles and grid are behind the device's by a step (copied back by sync_from_device).
  mutable bool device_ahead_ = false;
  mutable std::int64_t device_downloads_ = 0;
  // The device has sorted its particles (stepped) since it was built: its cell table is valid.
  bool device_stepped_ = false;
  mutable std::vector<std::uint32_t> device_cells_;
};

}  // namespace netsph
