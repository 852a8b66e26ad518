#pragma once
// The case-file schema (its keys in case_schema.cpp) and the CaseReader class, shared by
// case_reader.cpp (the top-level tables: [simulation], [fluid], [domain], [[fill]], [output]),
// case_reader_boundaries.cpp
// ([[wall]], [[inlet]], [[outlet]]), case_reader_bodies.cpp ([[body]]) and
// case_reader_nets.cpp ([[net]], [current]), case_reader_probes.cpp ([[probe]]) and
// case_reader_waves.cpp ([waves], [[damping]], [[gauge]]). Private to the
// case module (includes toml++).
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "netsph/case/case_spec.hpp"
#include "netsph/case/toml_table_reader.hpp"

namespace netsph::case_detail {

// ---- bounds on numbers the physics overflows beyond ---------------------------------------
// "Finite" is not enough: gravity = [0, 0, -1e308] passed and the run failed at t = 0 with a
// non-finite state; end_time = 1e308 was accepted. Each bound below is far outside any case
// netsph is for (water, nets and cages, laboratory to farm scale) and inside what its float
// fields and double clocks carry; the reader names the key, the value and the range.

/// |g| beyond 1000 m/s^2 (100 g) is no gravity water meets; c0 = coef sqrt(|g| H) and the
/// hydrostatic pressure rho g H stay far inside a float's range.
inline constexpr double kMostGravity = 1e3;
/// A velocity beyond 1000 m/s would need c0 beyond 10000 m/s (kMostSoundSpeed) to stay
/// weakly compressible (Mach < 0.1); no flow netsph models comes near it.
inline constexpr double kMostSpeed = 1e3;
/// c0 beyond 10000 m/s: water's real sound speed is 1480 m/s and WCSPH uses ~10 x the flow
/// speed, far less; rho0 c0^2 (the EOS's stiffness) stays inside a float.
inline constexpr double kMostSoundSpeed = 1e4;
/// A simulated time beyond 10^6 s (11.6 days) needs, at the largest dt a case could take,
/// more steps than a run ever makes; beyond about 10^9 s a step of 1e-6 s is smaller than half
/// the clock's double spacing, so time + dt == time and the run would never end.
inline constexpr double kLongestEndTime = 1e6;
/// dp below 1 micrometre leaves the continuum and underflows a float particle mass and volume
/// (dp^3); above 1 km the kernel and the domain's cell count lose meaning.
inline constexpr double kSmallestDp = 1e-6;
inline constexpr double kLargestDp = 1e3;
/// Coordinates beyond 100 km: positions are doubles but the interaction view keeps them as
/// floats relative to the grid's origin (1e-7 of the domain's size), and a domain of 1e308 m
/// overflows its cell count.
inline constexpr double kFarthestCoordinate = 1e5;
/// A solid's density beyond 100000 kg/m^3 (osmium, the densest element, is 22590), as the
/// fluid's.
inline constexpr double kMostDensity = 1e5;

inline NumberRule gravity_rule() {
  return NumberRule::closed(-kMostGravity, kMostGravity, "m/s^2");
}
inline NumberRule velocity_rule() {
  return NumberRule::closed(-kMostSpeed, kMostSpeed, "m/s");
}
inline NumberRule coordinate_rule() {
  return NumberRule::closed(-kFarthestCoordinate, kFarthestCoordinate, "m");
}

// ---- schema: allowed keys per table, in the order the reference documents them ----------

struct TableKeys {
  std::string_view table;
  std::vector<std::string_view> keys;
};

const std::vector<TableKeys>& schema();
const std::vector<std::string_view>& keys_of(std::string_view table);
/// "[fluid]" or "[[fill]]": how a top-level table is written.
std::string header_of(std::string_view table);
/// For a key that is close to nothing in its own table: maybe it was put in the wrong one.
std::string home_hint(std::string_view key);

/// A parameter given for a model it does not belong to is an error rather than silently
/// ignored: the user believes it has an effect.
void reject_foreign_parameter(const TomlTableReader& r, std::string_view key,
                              std::string_view model, std::string_view owners,
                              std::string_view own_keys);

/// `values` (read from the array `node` under `key`) must be strictly increasing: a
/// time or height table.
void check_increasing(const TomlTableReader& r, std::string_view key, const toml::node& node,
                      const std::vector<double>& values);

/// Quantities derived from several keys (2h, layers * dp): rounded, so that 0.06 is not
/// printed as 0.060000000000000005.
std::string format_derived(double v);

/// A damping zone's rate (1/s) when the case leaves it out: the rate that damps the wave of
/// `w` to 1% over the zone's `length` (m) and back (case_reader_waves.cpp derives it).
double default_damping_rate(const WaveSpec& w, double length, double g);

/// A name that becomes a file name (a probe's probes/<name>.csv, a net's <name>.xdmf): letters,
/// digits, '_', '-' and '.', not "." or "..".
bool plain_file_name(const std::string& name);

inline constexpr std::string_view kPlaneReason = "2D runs in the x-z plane (z up)";
/// Why y faces and the y axis are rejected in 2D (completes "... is not allowed ").
inline constexpr std::string_view kNotIn2D = "in 2D because 2D runs in the x-z plane (z up)";

// ---- the reader ---------------------------------------------------------------------------

class CaseReader {
 public:
  CaseReader(const toml::table& root, const TomlSource& source) : root_(root), source_(source) {}

  CaseSpec read(const std::string& default_name);

 private:
  bool is_2d() const { return spec_.simulation.dimensions == 2; }
  /// Axes that carry geometry: x, z in 2D; x, y, z in 3D.
  std::vector<int> used_axes() const { return is_2d() ? std::vector{0, 2} : std::vector{0, 1, 2}; }
  /// The fewest particle layers that span the kernel support 2h: ceil(2 h / dp).
  int support_layers() const;
  /// "2h = 0.06 m (3 dp at h_over_dp = 1.5)"
  std::string support_text() const;

  [[noreturn]] void fail_root(const std::string& message) const;

  void check_top_level() const;
  const toml::table* find_table(std::string_view name) const;
  std::vector<const toml::table*> find_array_of_tables(std::string_view name) const;

  // case_reader.cpp
  void read_simulation(const std::string& default_name);
  void read_fluid();
  void read_viscosity(const TomlTableReader& fluid);
  void read_density_diffusion(const TomlTableReader& fluid);
  void read_shifting(const TomlTableReader& fluid);
  void read_domain();
  std::array<bool, 3> read_periodic(const TomlTableReader& r) const;
  void read_fills();
  FillSpec read_fill(const toml::table& table, int number) const;
  void check_fill_in_domain(const TomlTableReader& r, const BoxSpec& box) const;
  /// A fill's or wall's box holds at least one and at most 2^31 - 21 lattice spacings
  /// (simulation.dp) on every axis.
  void check_box_fits_lattice(const TomlTableReader& r, const BoxSpec& box) const;
  /// A wall along a periodic axis, across the whole period, needs a period of whole dp.
  void check_wall_seamless(const TomlTableReader& r, const WallSpec& wall) const;
  void read_output();
  void read_force_window(const TomlTableReader& r);
  void read_snapshot_region(const TomlTableReader& r);

  BoxSpec read_box(const TomlTableReader& r, std::string_view what) const;
  Vec3d read_position(const TomlTableReader& r, std::string_view key,
                      std::string_view meaning) const;
  Vec3d read_in_plane_vector(const TomlTableReader& r, std::string_view key, const NumberRule& rule,
                             Vec3d fallback) const;
  /// The same check for a vector read some other way (`node` is its array).
  void check_in_plane(const TomlTableReader& r, std::string_view key, const toml::node& node,
                      const Vec3d& v) const;
  /// `velocity_key = [u, v, w]` (constant) or `history_key = { times, velocities }`, which
  /// exclude each other: the [[wall]] `velocity`/`motion` and [[body]]
  /// `velocity`/`motion_history` pairs. Empty when neither is given.
  VelocityHistory read_velocity_history(const TomlTableReader& r, std::string_view velocity_key,
                                        std::string_view history_key) const;

  // case_reader_boundaries.cpp
  void read_walls();
  WallSpec read_wall(const toml::table& table, int number) const;
  std::array<bool, 6> read_faces(const TomlTableReader& r) const;
  void check_wall_layers(const TomlTableReader& r, const WallSpec& wall) const;
  void read_open_boundaries(bool inlet);
  OpenBoundarySpec read_open_boundary(const toml::table& table, bool inlet, int number);
  Face read_open_face(const TomlTableReader& r, std::string_view kind) const;
  void read_open_velocity(const TomlTableReader& r, bool inlet, OpenBoundarySpec& ob) const;
  void read_profile(const TomlTableReader& r, OpenBoundarySpec& ob) const;
  void check_buffer(const TomlTableReader& r, const OpenBoundarySpec& ob);
  /// An open boundary on a periodic axis needs one on the opposite face too.
  void check_periodic_open_faces() const;
  void check_face_free(const TomlTableReader& r, const OpenBoundarySpec& ob,
                       const std::string& label);
  /// No wall's particle layers lie in an open boundary's buffer (a wall face on the open face).
  void check_buffer_clear_of_walls(const TomlTableReader& r, const OpenBoundarySpec& ob,
                                   std::string_view kind) const;
  /// Names are unique among all walls, inlets, outlets and bodies.
  void register_name(const toml::table& table, const std::string& name, std::string_view kind,
                     const std::string& label, const SourceLocation& where);

  // case_reader_bodies.cpp
  void read_bodies();
  BodySpec read_body(const toml::table& table, int number) const;
  void read_body_shape(const TomlTableReader& r, BodySpec& body) const;
  /// A body whose `longest` length (set by `key`) exceeds [domain]'s diagonal cannot fit in it.
  void check_body_fits_domain(const TomlTableReader& r, double longest, std::string_view key) const;
  Quat read_body_orientation(const TomlTableReader& r, const BodySpec& body) const;
  /// A non-zero direction, normalised; y must be 0 in 2D unless `along_y_in_2d`, which
  /// requires x = z = 0 instead.
  Vec3d read_direction(const TomlTableReader& r, std::string_view key, const toml::node& node,
                       bool along_y_in_2d, std::string_view along_y_reason) const;
  Quat read_rotation(const TomlTableReader& r) const;
  void read_body_motion(const TomlTableReader& r, BodySpec& body) const;
  void read_body_boundary(const TomlTableReader& r, BodySpec& body) const;
  void read_body_reference(const TomlTableReader& r, BodySpec& body) const;
  /// `key` (a position) must lie inside [domain] when the case gives one.
  void check_in_domain(const TomlTableReader& r, std::string_view key, const Vec3d& point) const;
  /// `key` (an x position: a zone across the whole tank) must lie within [domain]'s x range.
  void check_x_in_domain(const TomlTableReader& r, std::string_view key, double x) const;
  void register_body_name(const toml::table& table, const BodySpec& body, int number);

  // case_reader_nets.cpp
  /// Before the other tables: a 2D case with a net fails on the net, not on what 3D keys the
  /// rest of it has (a wall's y faces).
  void reject_nets_in_2d() const;
  void read_nets();
  NetSpec read_net(const toml::table& table, int number) const;
  void read_net_orientation(const TomlTableReader& r, NetSpec& net) const;
  void read_net_material(const TomlTableReader& r, NetSpec& net) const;
  void read_net_edges(const TomlTableReader& r, NetSpec& net) const;
  void read_net_sinker(const TomlTableReader& r, NetSpec& net) const;
  void read_net_point_loads(const TomlTableReader& r, NetSpec& net) const;
  void read_current();

  // case_reader_probes.cpp
  void read_probes();
  ProbeSpec read_probe(const toml::table& table, int number) const;
  /// dp may be left out of a standalone net case (nets, no fluid); everything else needs it.
  void require_dp() const;
  /// A standalone net case (nets, no fluid) with walls, open boundaries or bodies: an error,
  /// not tables silently left out of its run.
  void reject_fluid_tables_without_fluid() const;

  // case_reader_waves.cpp
  void read_waves();
  /// [waves] in a standalone net case: no paddle, the water's depth and level given.
  void read_standalone_waves(const TomlTableReader& r);
  /// Where the waves' current comes from, for messages: "[current] velocity x = U m/s" or the
  /// inlet's velocity.
  std::string wave_current_source() const;
  void read_wave_paddle_wall(const TomlTableReader& r, const toml::node& maker);
  /// paddle = "flap": the [[body]] that is the paddle, which the reader sets turning
  /// (case_reader_flap.cpp).
  void read_wave_flap_body(const TomlTableReader& r, const toml::node& maker);
  /// The flap's rate of turn from the paddle's sampled motion, and the tank's checks on it.
  void set_flap_motion(const TomlTableReader& r, const SampledPaddle& s);
  /// The still-water level and depth from the fill in front of the paddle.
  void read_wave_levels(const TomlTableReader& r, const toml::node& maker);
  /// The paddle spans the water's depth (and, in 3D, its width).
  void check_paddle_geometry(const TomlTableReader& r, const toml::node& maker) const;
  void read_wave_train(const TomlTableReader& r);
  /// type = "displacement": the record's wave components, and its Hm0, period and length
  /// (case_reader_displacement.cpp).
  std::vector<WaveComponent> read_displacement_record(const TomlTableReader& r);
  /// [waves] with relaxation_zone: the zone, the current from the inlet, the water's levels
  /// (case_reader_relaxation.cpp).
  void read_relaxation_wavemaker(const TomlTableReader& r);
  /// waves.absorption: the paddle's active absorption, set up from the wave and its travel.
  void read_absorption(const TomlTableReader& r);
  /// No wall's x face within the kernel's reach of the absorber's gauge.
  void check_absorber_gauge_clear(const TomlTableReader& r, const toml::node& node) const;
  /// waves.generation: first or second order, and where second order applies.
  void read_generation(const TomlTableReader& r);
  /// Sets the paddle wall's motion and checks that the tank holds its travel.
  void set_paddle_motion(const TomlTableReader& r);
  /// No wall's lid over the water below the wave crests.
  void check_free_surface(const TomlTableReader& r) const;
  void read_damping();
  void read_gauges();
  /// Inside [domain], over a fill, clear of the walls' particle layers and kernels and of the
  /// paddle's travel.
  void check_gauge_position(const TomlTableReader& r, const GaugeSpec& gauge) const;
  /// No damping zone reaches the paddle.
  void check_damping_clear_of_paddle(const TomlTableReader& r, const DampingSpec& zone) const;

  struct NamedEntry {
    std::string name;
    std::string label;  ///< "wall[2]"
    SourceLocation where;
  };

  const toml::table& root_;
  const TomlSource& source_;
  CaseSpec spec_;
  bool shifting_given_ = false;
  std::vector<NamedEntry> names_;
  /// The open boundary on each domain face, if any ("inlet[1]" and its position).
  std::array<std::optional<NamedEntry>, 6> open_faces_{};
  /// Buffer width on each domain face with an open boundary (0: none yet).
  std::array<double, 6> open_widths_{};
};

}  // namespace netsph::case_detail
