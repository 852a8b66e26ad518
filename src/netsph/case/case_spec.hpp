#pragma once
// CaseSpec: a case file after validation. Every quantity is in SI units and every default is
// filled in, so nothing downstream needs to know about TOML. docs/case-reference.md documents
// each key; case_reader.cpp is the only code that maps keys to these fields.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "netsph/core/enum_names.hpp"
#include "netsph/core/physics_options.hpp"
#include "netsph/core/quaternion.hpp"
#include "netsph/core/vec3.hpp"
#include "netsph/waves/irregular_waves.hpp"
#include "netsph/waves/paddle_motion.hpp"
#include "netsph/waves/wave_train.hpp"

namespace netsph {

/// Where an item was defined, so that later stages can point at the case file too.
struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;
  std::string str() const;  ///< "file:line:column" (or just "file" when line is 0)
};

/// [simulation]
struct SimulationSpec {
  std::string name;        ///< case name; default: file stem
  int dimensions = 3;      ///< 2 (x-z plane) or 3
  double dp = 0;           ///< particle spacing, m (required, > 0)
  double h_over_dp = 1.5;  ///< smoothing length h = h_over_dp * dp; [1, 3]
  KernelType kernel = KernelType::Wendland;
  double end_time = 0;  ///< s (required, > 0)
  double cfl = 0.2;     ///< Courant number for the variable dt; (0, 1]
  double dt_min = 0;    ///< s; a dt below it stops the run as unstable. 0: 1e-4 x initial dt
  double dt_max = 0;    ///< s; 0: no cap
  /// The run stops as unstable once this fraction of the initial fluid particles has left the
  /// domain (other than through an outlet), or when more than a hundredth of the fluid leaves
  /// in a single step; [0, 1], 1: never on the total.
  double max_lost_fraction = 0.05;
};

/// [fluid]
struct FluidSpec {
  double density = 1000.0;  ///< reference density rho0, kg/m^3
  double sound_speed = 0;   ///< c0, m/s; 0: use sound_speed_coef
  double sound_speed_coef =
      20;              ///< c0 = coef * sqrt(|g| * H), H = deepest fill (used when sound_speed = 0)
  double gamma = 7.0;  ///< Tait exponent
  double background_pressure = 0;  ///< Pa, added to the equation of state (closed flows)
  Vec3d gravity{0, 0, -9.81};      ///< m/s^2
  /// Gravity on nets and floating bodies when the fluid itself runs without gravity (a closed
  /// duct with no free surface, where c0 can be set from the flow speed alone). They then get
  /// their weight less the buoyancy of the volume they stand for as a constant force, since the
  /// fluid has no hydrostatic pressure to give it. Only with gravity = [0, 0, 0].
  std::optional<Vec3d> structure_gravity;
  ViscosityModel viscosity = ViscosityModel::Artificial;
  double alpha = 0.01;                ///< artificial viscosity coefficient
  double kinematic_viscosity = 1e-6;  ///< nu, m^2/s, for the laminar model
  DensityDiffusion density_diffusion = DensityDiffusion::Molteni;
  double delta = 0.1;  ///< delta-SPH coefficient
  /// fluid.shifting = { model, coefficient, surface_threshold }. Default: "fickian" when the
  /// case has an [[inlet]] or [[outlet]], "none" otherwise.
  ShiftingModel shifting = ShiftingModel::None;
  double shifting_coefficient = 2.0;  ///< A in dr = -A h |v| dt grad(C); (0, 10]
  /// Free-surface threshold on div(r): no shifting below it, damped above it. 0: 1.85 in 2D,
  /// 2.75 in 3D (sph/shifting.hpp).
  double shifting_surface_threshold = 0;
};

/// [domain]. Particles that leave it are removed (and counted in the warnings), except along
/// periodic axes, where they re-enter at the opposite face.
struct DomainSpec {
  bool given = false;  ///< false: bounding box of all particles plus a margin of 2h
  Vec3d min{}, max{};
  std::array<bool, 3>
      periodic{};  ///< periodic = ["x", "y", "z"] (subset; y not in 2D); needs min/max

  /// The domain's length along `axis` where that axis is periodic, else 0.
  double period(int axis) const { return given && periodic[axis] ? max[axis] - min[axis] : 0.0; }
};

struct BoxSpec {
  Vec3d min{}, max{};
};

/// [[fill]]: a box of fluid on the dp lattice, hydrostatic density below `surface_z`.
struct FillSpec {
  BoxSpec box;
  Vec3d velocity{};  ///< initial velocity, m/s
  std::optional<double>
      surface_z;  ///< free-surface height for the hydrostatic density; default: box top
  SourceLocation where;
};

/// Face order used by WallSpec::faces.
enum Face : int { kXMin = 0, kXMax = 1, kYMin = 2, kYMax = 3, kZMin = 4, kZMax = 5 };
inline constexpr std::array kFaceNames = {
    EnumName<Face>{"xmin", kXMin}, EnumName<Face>{"xmax", kXMax}, EnumName<Face>{"ymin", kYMin},
    EnumName<Face>{"ymax", kYMax}, EnumName<Face>{"zmin", kZMin}, EnumName<Face>{"zmax", kZMax}};
constexpr std::string_view name_of(Face v) {
  return name_of(kFaceNames, v);
}
static_assert(one_to_one(kFaceNames));

/// Prescribed velocity over time, piecewise linear between (time, velocity) points, held
/// constant before the first and after the last. One point = a constant velocity.
struct VelocityHistory {
  std::vector<double> times;      ///< s, strictly increasing
  std::vector<Vec3d> velocities;  ///< m/s, one per time
  bool moving() const { return !velocities.empty(); }
  Vec3d at(double t) const;  ///< zero when empty
};

/// [[wall]]: layers of boundary particles outside the chosen faces of a box.
struct WallSpec {
  std::string name;             ///< default "wall<N>"
  BoxSpec box;                  ///< the fluid side of the wall (the inner surface of a tank)
  std::array<bool, 6> faces{};  ///< which faces of the box carry wall particles
  int layers = 3;  ///< particle layers; default ceil(2 h / dp), enough to cover the kernel support
  WallModel model = WallModel::Mdbc;
  /// mDBC only. Default: the wall's own velocity (DualSPHysics' published mDBC); no_slip is
  /// meant for laminar viscosity (with artificial viscosity, which acts only on approaching
  /// pairs, the mirrored velocities drag near-wall fluid backwards: docs/VALIDATION.md).
  WallSlip slip = WallSlip::WallVelocity;
  /// velocity = [u, v, w] (constant) or motion = { times = [...], velocities = [[...], ...] }.
  VelocityHistory motion;
  SourceLocation where;
};

/// [[inlet]] and [[outlet]]: open boundaries after Tafuni et al. (2018). A buffer of `layers`
/// particle layers lies inside the domain along one domain face; the fill particles that start
/// there become buffer particles.
struct OpenBoundarySpec {
  std::string name;   ///< default "inlet<N>" / "outlet<N>"
  Face face = kXMin;  ///< a face of [domain] (required)
  int layers = 4;     ///< buffer width in particle layers (default max(4, ceil(2h/dp))); >= 2h
  /// Inlet: imposed normal velocity into the domain, uniform (m/s) unless a profile is given.
  /// Outlet: unset = extrapolated from the fluid; set = imposed (outwards).
  std::optional<double> velocity;
  /// Inlet profile over z: piecewise linear through (z, u) points (m, m/s); replaces velocity.
  std::vector<double> profile_z, profile_u;
  BufferDensity density = BufferDensity::Extrapolated;
  /// Free-surface height: hydrostatic density below it; the inlet creates no particles above
  /// it. Default: the highest fill surface.
  std::optional<double> surface_z;
  SourceLocation where;
};

/// [[body]]: a rigid body made of boundary particles. The case's shape names map to these:
///   box {size}                  -> Box, lengths = size
///   plate {thickness, width, height}, square_plate {side, thickness}
///                               -> Box, lengths = (thickness, width, height): thickness along the
///                               normal
///   circular_plate {diameter, thickness} -> Cylinder of length = thickness along the normal
///   cylinder {diameter, length} -> Cylinder along `axis`
///   sphere {diameter}           -> Sphere
///   cruciform {twine_length, twine_diameter} -> Cruciform facing `normal`
struct BodySpec {
  std::string name;        ///< default "body<N>"
  std::string group;       ///< force group (series.csv columns); default: the name
  std::string shape_name;  ///< as written in the case, for reports
  BodyShape shape = BodyShape::Box;
  Vec3d lengths{};      ///< Box: full lengths in the local frame, m
  double diameter = 0;  ///< Cylinder, Sphere, Cruciform (twine diameter), m
  double length = 0;    ///< Cylinder length (local x), Cruciform twine (arm) length, m
  Vec3d center{};       ///< m
  /// Local frame -> world frame. Built from `normal` (plates, discs, cruciforms: local x),
  /// `axis` (cylinders: local x) and an optional extra `rotation`.
  Quat orientation{};
  BodyMotion motion = BodyMotion::Fixed;
  double density = 0;          ///< kg/m^3 (floating; 0 when mass is given)
  std::optional<double> mass;  ///< kg (kg/m in 2D)
  Vec3d initial_velocity{};    ///< floating, m/s
  VelocityHistory velocity;    ///< prescribed translation
  /// Prescribed rotation about a fixed axis through `hinge` (world frame, rad/s; set by
  /// [waves] for a flap paddle, whose motion is this rotation alone): none when empty.
  VelocityHistory angular_velocity;
  Vec3d hinge{};  ///< m: a point on the prescribed rotation's axis
  WallModel model = WallModel::Mdbc;
  WallSlip slip = WallSlip::WallVelocity;
  int layers = 0;  ///< shell thickness in particle layers; 0: ceil(2h/dp); -1: solid
  std::optional<double> reference_velocity;  ///< m/s, for Cd = F / (0.5 rho U^2 A)
  std::optional<double> reference_area;      ///< m^2 (m in 2D)
  SourceLocation where;
};

/// A sinker: a bar along the net's bottom edge, shared among the bottom knots by the length
/// each one carries (net/net_generator.cpp).
struct SinkerSpec {
  double length = 0;              ///< m; 0: no sinker
  double diameter = 0;            ///< m
  double density = 0;             ///< kg/m^3
  double drag_coefficient = 1.2;  ///< cylinder Cd on diameter x length (standalone current)
};

/// A point load on one knot: row 0 is the bottom row, column 0 the left column (seen from
/// upstream, looking along the normal).
struct NetPointLoad {
  int row = 0;
  int column = 0;
  Vec3d force{};  ///< N
};

/// [[net]]: a rectangular net panel of knots joined by twines (net/net_generator.hpp).
struct NetSpec {
  std::string name;           ///< default "net<N>"
  Vec3d center{};             ///< centre of the outline, m
  Vec3d normal{1, 0, 0};      ///< unit normal of the net plane (faces the flow)
  Vec3d up{0, 0, 1};          ///< the outline's height direction (projected onto the net plane)
  double width = 0;           ///< outline width, m
  double height = 0;          ///< outline height, m
  double twine_length = 0;    ///< real twine (bar) length l0, m
  double twine_diameter = 0;  ///< real twine diameter d0, m
  double mesh_grouping = 1;   ///< lambda: numerical twine lambda l0, lambda d0
  KnotShape knot_shape = KnotShape::SquarePlate;
  EquivalentKnotRule equivalent_knot = EquivalentKnotRule::Exact;
  KnotLayout layout = KnotLayout::Crossings;
  EdgeKnots edges = EdgeKnots::Full;
  std::string material = "nylon";  ///< for reports
  double material_density = 1140;  ///< kg/m^3
  double youngs_modulus = 0;       ///< Pa (used when axial_stiffness is 0)
  double axial_stiffness = 0;      ///< EA of one real twine, N; 0: from youngs_modulus
  /// Nonlinear twine law T = c1 eps + c2 eps^2 (N) of one real twine; replaces EA when set.
  std::optional<std::array<double, 2>> tension_law;
  double damping_ratio = 0.5;         ///< zeta of each twine's axial mode
  std::array<bool, 4> fixed_edges{};  ///< bottom, top, left, right
  /// Every knot anchored: a rigid net whose loads are measured (Shi et al. 2024, 3.2).
  bool rigid = false;
  /// Current speed for the net's Cd = Fx / (0.5 rho U^2 A_outline), m/s. Default: the inlet's
  /// velocity when the case has one uniform [[inlet]] (coupled nets), else none.
  std::optional<double> reference_velocity;
  SinkerSpec sinker;
  std::vector<NetPointLoad> point_loads;
  SourceLocation where;
};

/// [current]: a uniform current loading standalone nets (no SPH fluid).
struct CurrentSpec {
  bool given = false;
  Vec3d velocity{};  ///< m/s
  NetLoadModel model = NetLoadModel::Screen;
  ScreenCoefficients screen = ScreenCoefficients::S3KristiansenFaltinsen;
  double normal_drag = 1.2;      ///< Morison Cn (Bessonneau & Marichal 1998)
  double tangential_drag = 0.1;  ///< Morison Ct
  SourceLocation where;
};

/// [[probe]]: where the fluid is sampled (Shepard-corrected SPH interpolation,
/// sph/shepard.hpp) during a run, written to probes/<name>.csv, with time averages over the
/// force window in probes/<name>_mean.csv.
enum class ProbeType { Point, Line, Plane };
inline constexpr std::array kProbeTypeNames = {EnumName<ProbeType>{"point", ProbeType::Point},
                                               EnumName<ProbeType>{"line", ProbeType::Line},
                                               EnumName<ProbeType>{"plane", ProbeType::Plane}};
constexpr std::string_view name_of(ProbeType v) {
  return name_of(kProbeTypeNames, v);
}
static_assert(one_to_one(kProbeTypeNames));

struct ProbeSpec {
  std::string name;  ///< file name stem; default "probe<N>"
  ProbeType type = ProbeType::Point;
  /// Point: a = the point. Line: a -> b. Plane: the axis-aligned rectangle with corners a, b
  /// (equal on exactly one axis, the plane's normal; y in 2D).
  Vec3d a{}, b{};
  int points = 0;      ///< line: points from a to b, both included (>= 2)
  double spacing = 0;  ///< plane: distance between points on both in-plane axes, m
  double every = 0;    ///< s between rows of probes/<name>.csv
  SourceLocation where;
  /// The sampled points, in output order (plane: first in-plane axis fastest).
  std::vector<Vec3d> sample_points() const;
};

/// [waves]: waves made by a piston paddle, a [[wall]] that the reader sets moving (its
/// `motion` becomes the paddle's velocity, sampled: waves/wave_train.hpp), and the still-water
/// level that gauges and damping zones refer to. The paddle is a wall with one vertical face in
/// x: on its xmin face the waves travel in +x, on its xmax face in -x. In a standalone net case
/// (no fluid) there is no paddle: the waves travel in +x from `origin_x` over water of the
/// given depth, on the [current]'s x velocity, and load the nets with their orbital velocity.
enum class WaveKind : std::uint8_t { Regular, Jonswap, Displacement };
inline constexpr std::array kWaveKindNames = {
    EnumName<WaveKind>{"regular", WaveKind::Regular},
    EnumName<WaveKind>{"jonswap", WaveKind::Jonswap},
    EnumName<WaveKind>{"displacement", WaveKind::Displacement}};
static_assert(one_to_one(kWaveKindNames));
constexpr std::string_view name_of(WaveKind v) {
  return name_of(kWaveKindNames, v);
}
/// The theory of a regular wave's target surface: linear (Airy) or Stokes second order.
enum class WaveTheory : std::uint8_t { Linear, Stokes2 };
inline constexpr std::array kWaveTheoryNames = {
    EnumName<WaveTheory>{"linear", WaveTheory::Linear},
    EnumName<WaveTheory>{"stokes2", WaveTheory::Stokes2}};
static_assert(one_to_one(kWaveTheoryNames));
constexpr std::string_view name_of(WaveTheory v) {
  return name_of(kWaveTheoryNames, v);
}

enum class WaveAbsorption : std::uint8_t { None, Active };
inline constexpr std::array kWaveAbsorptionNames = {
    EnumName<WaveAbsorption>{"none", WaveAbsorption::None},
    EnumName<WaveAbsorption>{"active", WaveAbsorption::Active}};
static_assert(one_to_one(kWaveAbsorptionNames));

/// [waves] absorption = "active": the paddle's active absorption (waves/active_absorption.hpp),
/// set up by the reader from the wave and the paddle's travel.
struct WaveAbsorptionSpec {
  bool active = false;
  double gauge_x = 0;     ///< m: where the elevation is measured, in front of the paddle
  double gauge_y = 0;     ///< m: the middle of the water's width there
  double gain = 0;        ///< 1/s
  double delay = 0;       ///< s
  double drift_time = 0;  ///< s
  double mean_time = 0;   ///< s: the running mean taken from the measured elevation
};

struct WaveSpec {
  bool given = false;
  WaveKind kind = WaveKind::Regular;
  PaddleType paddle = PaddleType::Piston;
  std::string wavemaker;  ///< the name of the paddle: a [[wall]] (piston) or [[body]] (flap)
  std::size_t wall = 0;   ///< piston: its index in CaseSpec::walls
  std::size_t body = 0;   ///< flap: its index in CaseSpec::bodies
  double height = 0;      ///< regular: H, m
  double period = 0;      ///< regular: T, s
  WaveTheory theory = WaveTheory::Linear;
  /// regular, flume: the paddle's motion, first order or with the second harmonic that
  /// suppresses the free one (default: second order for a Stokes-2 wave, else first)
  PaddleGeneration generation = PaddleGeneration::FirstOrder;
  JonswapSpec jonswap;     ///< jonswap: hs, tp, gamma
  std::uint64_t seed = 1;  ///< jonswap: the random phases' seed
  int components = 0;      ///< jonswap: how many frequencies
  /// displacement: the record's Hm0 = 4 sqrt(m0) and the period of its tallest component, of
  /// the waves its harmonics make (waves/displacement_record.hpp), m and s
  double record_height = 0, record_period = 0;
  double record_length = 0;  ///< displacement: N dt, s (the paddle repeats the record after it)
  double depth = 0;          ///< still-water depth h, m (default: still level - lowest fill)
  double still_level = 0;    ///< z of the still-water level, m (default: the highest fill top)
  double ramp = 0;           ///< s (default: two periods)
  /// x of the paddle's face at rest (standalone: origin_x; relaxation: relaxation_end), m
  double paddle_x = 0;
  bool standalone = false;  ///< a standalone net case's waves: no paddle
  /// A relaxation wavemaker instead of a paddle: the fluid's velocity is relaxed towards the
  /// wave's (plus the current's) over x from relaxation_full (fully) to relaxation_end (not at
  /// all), where the waves leave it; relaxation_end is then paddle_x, the waves' origin.
  bool relaxation = false;
  double relaxation_full = 0, relaxation_end = 0;  ///< m
  double relaxation_rate = 0;                      ///< 1/s, at relaxation_full
  /// standalone, relaxation: the current along the waves' direction they ride on, m/s
  double current = 0;
  int direction = 1;              ///< +1: the waves travel in +x; -1: in -x
  WaveTrain train;                ///< the components, set up (derived)
  double max_excursion = 0;       ///< the paddle's largest excursion from rest over the run, m
  WaveAbsorptionSpec absorption;  ///< the paddle's active absorption (none by default)
  SourceLocation where;

  /// A paddle wall makes the waves (not a standalone case's theory, not a relaxation zone).
  bool has_paddle() const { return given && !standalone && !relaxation; }
  /// The paddle is a piston, a [[wall]] that translates (a flap is a [[body]] that rotates).
  bool paddle_is_wall() const { return has_paddle() && paddle == PaddleType::Piston; }
  /// The period that sets the time scales (ramp, gauge sampling): T or Tp, s.
  double reference_period() const {
    return kind == WaveKind::Regular   ? period
           : kind == WaveKind::Jonswap ? jonswap.tp
                                       : record_period;
  }
  /// The height that sets the crests and the resolution: H or Hs, m.
  double reference_height() const {
    return kind == WaveKind::Regular   ? height
           : kind == WaveKind::Jonswap ? jonswap.hs
                                       : record_height;
  }
  /// The keys that set reference_period() and reference_height(), for messages.
  std::string_view period_key() const {
    return kind == WaveKind::Regular ? "period" : kind == WaveKind::Jonswap ? "tp" : "displacement";
  }
  std::string_view height_key() const {
    return kind == WaveKind::Regular ? "height" : kind == WaveKind::Jonswap ? "hs" : "displacement";
  }
  /// The wavelength of the tallest component, m.
  double reference_wavelength() const;
  /// The target elevation above the still-water level at x (m), time t (s): train_elevation
  /// at the distance from the paddle's rest position along the waves' direction.
  double target_elevation(double x, double t) const {
    return train_elevation(train, direction * (x - paddle_x), t);
  }
};

/// [[damping]]: a zone where the fluid's velocity is relaxed towards `velocity` (zero, or a
/// current), graded smoothly along x from nothing at `from` to `rate` at `to` and beyond
/// (sph/damping_zone.hpp): a numerical beach that absorbs the waves arriving at it.
struct DampingSpec {
  std::string name;  ///< default "damping<N>"
  double from = 0;   ///< x where the damping starts, m
  double to = 0;     ///< x where it reaches `rate` (beyond: `rate` too), m
  double rate = 0;   ///< relaxation rate, 1/s
  Vec3d velocity{};  ///< m/s
  SourceLocation where;
};

/// [[gauge]]: a wave gauge, the free-surface elevation at (x, y) over time (run/wave_gauges.hpp).
struct GaugeSpec {
  std::string name;  ///< column name in gauges.csv; default "gauge<N>"
  double x = 0, y = 0;
  double z_min = 0, z_max = 0;  ///< the vertical line searched for the surface, m (derived)
  SourceLocation where;
};

/// [output]
struct OutputSpec {
  bool snapshots = true;        ///< write HDF5 + XDMF snapshots
  double snapshot_every = 0;    ///< s; 0: end_time / 50
  double series_every = 0;      ///< s; 0: snapshot_every / 10
  double checkpoint_every = 0;  ///< s of simulated time between checkpoints; 0: end_time / 10
  double gauge_every = 0;       ///< s between rows of gauges.csv; 0: run/wave_gauges.hpp's default
  /// Time window over which summary.json averages body forces and Cd, s; default: the second
  /// half of the run (force_window = [t0, t1]).
  std::optional<std::array<double, 2>> force_window;
  /// snapshot_region = { min, max }: snapshots hold only the particles inside this box (a
  /// slice through a large case instead of all of it). The nets' files are not affected.
  std::optional<BoxSpec> snapshot_region;
};

struct CaseSpec {
  std::string source;                  ///< file path, or "builtin:<name>"
  std::vector<std::string> overrides;  ///< the --set strings applied over the file, in order
  SimulationSpec simulation;
  FluidSpec fluid;
  DomainSpec domain;
  std::vector<FillSpec> fills;
  std::vector<WallSpec> walls;
  std::vector<OpenBoundarySpec> inlets;
  std::vector<OpenBoundarySpec> outlets;
  std::vector<BodySpec> bodies;
  std::vector<NetSpec> nets;
  std::vector<ProbeSpec> probes;
  WaveSpec waves;
  std::vector<DampingSpec> damping;
  std::vector<GaugeSpec> gauges;
  CurrentSpec current;
  OutputSpec output;
  /// The current's speed when the case has exactly one [[inlet]] with a uniform velocity
  /// (the reference for net Cd and probe velocity reductions), m/s.
  std::optional<double> uniform_inflow() const {
    if (inlets.size() != 1 || !inlets[0].velocity || !inlets[0].profile_z.empty()) return {};
    return inlets[0].velocity;
  }
  /// A standalone net run: nets, no fluid (no [[fill]]); dp is then not needed.
  bool net_only() const { return fills.empty() && !nets.empty(); }
};

}  // namespace netsph
