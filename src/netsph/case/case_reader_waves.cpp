// The [waves] table: the wave a piston paddle makes (the reader sets the paddle wall's motion
// from it); the zones that absorb waves and the gauges that measure them are
// case_reader_damping_gauges.cpp's. Same conventions as case_reader.cpp; docs/case-reference.md
// documents every key. The checks here need only the case; those that need the scene (the first
// time step, the particles per wave height) are setup/scene_waves.cpp's.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "netsph/case/case_reader_impl.hpp"
#include "netsph/core/error.hpp"
#include "netsph/waves/dispersion.hpp"
#include "netsph/waves/wave_kinematics.hpp"

namespace netsph::case_detail {
namespace {

/// The JONSWAP sea's frequencies span [kJonswapLow, kJonswapHigh] fp: below 0.5 fp the
/// spectrum holds no energy to speak of (exp(-5/4 * 16) = 2e-9), above 3 fp about 1% of it.
constexpr double kJonswapLow = 0.5, kJonswapHigh = 3.0;

/// Stokes second order's largest second-order surface, as a fraction of the first order's.
constexpr double kMaxStokesRatio = 0.25;

/// The paddle's velocity table: at most this many samples (32 B each), and this many
/// sample-components of work to fill it (a few seconds).
constexpr double kMaxPaddleSamples = 5e6, kMaxPaddleWork = 5e9;

}  // namespace

void CaseReader::read_waves() {
  const toml::table* table = find_table("waves");
  if (!table) return;
  TomlTableReader r(*table, "waves", "[waves]", keys_of("waves"), source_, home_hint);
  WaveSpec& w = spec_.waves;
  w.given = true;
  w.where = r.location();
  const Vec3d g = spec_.fluid.gravity;
  if (!(g.z < 0) || g.x != 0 || g.y != 0) {
    r.fail_table(
        fmt::format("waves are gravity waves: they need fluid.gravity = [0, 0, -g] with "
                    "g > 0, and this case has gravity = {}",
                    format_vec3(g)));
  }
  w.kind = r.choice("type", kWaveKindNames, w.kind);
  if (!r.has("relaxation_zone")) {
    if (const toml::node* node = r.find("relaxation_rate")) {
      r.fail_value("relaxation_rate", *node,
                   "applies to a relaxation wavemaker (relaxation_zone), and this [waves] has "
                   "none: remove the key");
    }
  }
  if (spec_.net_only()) return read_standalone_waves(r);
  if (spec_.fills.empty()) r.fail_table("waves need water: this case has no [[fill]]");
  for (const std::string_view key : {"depth", "still_water_level", "origin_x"}) {
    if (const toml::node* node = r.find(key)) {
      r.fail_value(key, *node,
                   "applies to standalone net cases only (no [[fill]]); here the water's depth "
                   "and level are the fill's in front of the paddle, and the paddle is the "
                   "waves' origin");
    }
  }
  if (r.has("relaxation_zone")) return read_relaxation_wavemaker(r);
  w.paddle = r.choice("paddle", kPaddleTypeNames, w.paddle);
  if (!spec_.inlets.empty() || !spec_.outlets.empty()) {
    const OpenBoundarySpec& ob = spec_.inlets.empty() ? spec_.outlets[0] : spec_.inlets[0];
    r.fail_table(fmt::format(
        "a paddle needs a closed tank with a damping zone before its far wall, and '{}' ({}) "
        "is an {}: for waves on a current from an inlet, make them with a relaxation zone "
        "(waves.relaxation_zone = [x_full, x_end]) instead of a paddle",
        ob.name, ob.where.str(), spec_.inlets.empty() ? "outlet" : "inlet"));
  }
  const toml::node& maker = r.require(
      "wavemaker", "the name of the paddle: a [[wall]] for a piston, a [[body]] for a flap");
  w.wavemaker = r.to_string("wavemaker", maker);
  if (w.paddle == PaddleType::Flap) {
    read_wave_flap_body(r, maker);
  } else {
    read_wave_paddle_wall(r, maker);
  }
  read_wave_levels(r, maker);
  read_wave_train(r);
  check_paddle_geometry(r, maker);
  set_paddle_motion(r);
  read_absorption(r);
  check_free_surface(r);
}

std::string CaseReader::wave_current_source() const {
  const WaveSpec& w = spec_.waves;
  const std::string along = fmt::format("{} m/s along the waves", format_number(w.current));
  if (w.relaxation && !spec_.inlets.empty()) {
    const OpenBoundarySpec& in = spec_.inlets.front();
    return fmt::format("inlet '{}' ({}) velocity = {} m/s on its {} face: {}", in.name,
                       in.where.str(), format_number(in.velocity.value_or(0.0)), name_of(in.face),
                       along);
  }
  return fmt::format("[current] velocity x = {} m/s: {}", format_number(w.direction * w.current),
                     along);
}

void CaseReader::read_standalone_waves(const TomlTableReader& r) {
  WaveSpec& w = spec_.waves;
  w.standalone = true;
  for (const std::string_view key : {"wavemaker", "paddle", "relaxation_zone", "absorption"}) {
    if (const toml::node* node = r.find(key)) {
      r.fail_value(key, *node,
                   "a standalone net case (nets, no [[fill]]) has no wavemaker: its waves are "
                   "given by their theory, travelling in +x from origin_x; remove the key");
    }
  }
  w.depth = r.required_number("depth", NumberRule::positive("m"),
                              "the water depth h, m (a standalone net case has no fill)");
  w.still_level = r.required_number("still_water_level", NumberRule::any("m"),
                                    "z of the still-water surface, m");
  w.paddle_x = r.number("origin_x", NumberRule::any("m"), 0.0);
  w.direction = 1;
  if (spec_.current.given) w.current = spec_.current.velocity.x;
  // Every net in the water column: none below the bed, none wholly above the still water.
  const double bed = w.still_level - w.depth;
  for (const NetSpec& net : spec_.nets) {
    const Vec3d n = net.normal / norm(net.normal);
    Vec3d up = net.up - n * dot(n, net.up);
    up = up / norm(up);
    const Vec3d across = cross(n, up);
    const double reach = 0.5 * (net.height * std::fabs(up.z) + net.width * std::fabs(across.z));
    const double low = net.center.z - reach;
    if (low < bed - 1e-9 * std::max(1.0, std::fabs(bed))) {
      r.fail_value("depth", *r.find("depth"),
                   fmt::format("puts the bed at z = {} m (still_water_level - depth), above the "
                               "lowest point of net '{}' ({}), z = {:.4g} m: the net must lie "
                               "in the water",
                               format_number(bed), net.name, net.where.str(), low));
    }
    if (low >= w.still_level) {
      r.fail_value("still_water_level", *r.find("still_water_level"),
                   fmt::format("lies at or below the lowest point of net '{}' ({}), z = {:.4g} m: "
                               "the whole net would be in air",
                               net.name, net.where.str(), low));
    }
  }
  read_wave_train(r);
}

void CaseReader::read_wave_paddle_wall(const TomlTableReader& r, const toml::node& maker) {
  WaveSpec& w = spec_.waves;
  std::vector<std::string_view> names;
  const WallSpec* wall = nullptr;
  for (std::size_t i = 0; i < spec_.walls.size(); ++i) {
    names.push_back(spec_.walls[i].name);
    if (spec_.walls[i].name == w.wavemaker) wall = &spec_.walls[i], w.wall = i;
  }
  if (!wall) {
    for (const NamedEntry& other : names_) {
      if (other.name != w.wavemaker) continue;
      r.fail_value("wavemaker", maker,
                   fmt::format("names {} ({}), not a [[wall]]: the paddle is a wall with one x "
                               "face; the walls are: {}",
                               other.label, other.where.str(), join(names)));
    }
    r.fail_value("wavemaker", maker,
                 names.empty() ? std::string("names no [[wall]]: this case has none; add a wall "
                                             "with faces = [\"xmin\"] as the paddle")
                               : fmt::format("names no [[wall]]{}; the walls are: {}",
                                             did_you_mean(w.wavemaker, names), join(names)));
  }
  int faces = 0;
  for (const bool f : wall->faces) faces += f ? 1 : 0;
  if (faces != 1 || !(wall->faces[kXMin] || wall->faces[kXMax])) {
    r.fail_value("wavemaker", maker,
                 fmt::format("the paddle wall '{}' ({}) must have one face, faces = [\"xmin\"] "
                             "(waves travel in +x) or [\"xmax\"] (in -x): the whole wall moves "
                             "with the paddle, so the tank's other faces belong to another wall",
                             wall->name, wall->where.str()));
  }
  if (wall->motion.moving()) {
    r.fail_value("wavemaker", maker,
                 fmt::format("the paddle wall '{}' ({}) has its own velocity or motion: [waves] "
                             "sets the paddle's motion, so remove them from the wall",
                             wall->name, wall->where.str()));
  }
  w.direction = wall->faces[kXMin] ? 1 : -1;
  w.paddle_x = w.direction > 0 ? wall->box.min.x : wall->box.max.x;
}

void CaseReader::read_wave_levels(const TomlTableReader& r, const toml::node& maker) {
  WaveSpec& w = spec_.waves;
  const double dp = spec_.simulation.dp;
  // The water the paddle pushes: the fill just in front of its face.
  const double front = w.paddle_x + w.direction * 0.5 * dp;
  const FillSpec* water = nullptr;
  for (const FillSpec& f : spec_.fills) {
    if (front >= f.box.min.x && front <= f.box.max.x) water = &f;
  }
  if (!water) {
    r.fail_value("wavemaker", maker,
                 fmt::format("the paddle's face is at x = {} m (its {} face), and no "
                             "[[fill]] lies in front of it: put the water against the paddle",
                             format_number(w.paddle_x), w.direction > 0 ? "xmin" : "xmax"));
  }
  w.still_level = water->surface_z.value_or(water->box.max.z);
  w.depth = w.still_level - water->box.min.z;
  if (!(w.depth > 0)) {
    r.fail_table(fmt::format(
        "the water in front of the paddle ({}) has no depth: its surface, "
        "z = {} m, is not above its bottom, z = {} m",
        water->where.str(), format_number(w.still_level), format_number(water->box.min.z)));
  }
  // Water behind the paddle would be pushed by its back, making waves of its own.
  for (const FillSpec& f : spec_.fills) {
    const bool behind =
        w.direction > 0 ? f.box.min.x < w.paddle_x - 0.5 * dp : f.box.max.x > w.paddle_x + 0.5 * dp;
    if (!behind) continue;
    r.fail_value(
        "wavemaker", maker,
        fmt::format("the fill at {} holds water behind the paddle (x {} {} m): a paddle "
                    "has water on one side only; end the fill at the paddle's face",
                    f.where.str(), w.direction > 0 ? "<" : ">", format_number(w.paddle_x)));
  }
}

void CaseReader::check_paddle_geometry(const TomlTableReader& r, const toml::node& maker) const {
  const WaveSpec& w = spec_.waves;
  const double dp = spec_.simulation.dp;
  const double bottom = w.still_level - w.depth;
  const double crest = w.still_level + w.reference_height();
  // The paddle's box and what to call it: a piston's wall, or a flap's body.
  BoxSpec box;
  std::string what;
  if (w.paddle == PaddleType::Flap) {
    const BodySpec& b = spec_.bodies[w.body];
    box = {b.center - b.lengths * 0.5, b.center + b.lengths * 0.5};
    what = fmt::format("the flap body '{}' ({})", b.name, b.where.str());
    // Hinged at the bed: a box reaching below it would turn its corner through the bed's
    // particles, one ending above it would let water under the hinge.
    if (std::fabs(box.min.z - bottom) > 0.5 * dp) {
      r.fail_value("wavemaker", maker,
                   fmt::format("{} starts at z = {:.4g} m, and a flap is hinged at the bed: its "
                               "box must start at the bottom of the water in front of it, z = "
                               "{} m (within dp / 2)",
                               what, box.min.z, format_number(bottom)));
    }
  } else {
    const WallSpec& wall = spec_.walls[w.wall];
    box = wall.box;
    what = fmt::format("the paddle wall '{}' ({})", wall.name, wall.where.str());
  }
  if (box.min.z > bottom + 0.5 * dp || box.max.z < crest) {
    r.fail_value("wavemaker", maker,
                 fmt::format("{} spans z from {:.4g} to {:.4g} m, and a paddle must reach from the "
                             "bottom, z = {} m, to above the crests, z = {:.4g} m (the still "
                             "water plus the wave height): water would pass under or over it",
                             what, box.min.z, box.max.z, format_number(bottom), crest));
  }
  if (is_2d()) return;
  for (const FillSpec& f : spec_.fills) {
    // A flap wider than the water would turn through the side walls' particles.
    if (w.paddle == PaddleType::Flap &&
        (box.min.y < f.box.min.y - 0.5 * dp || box.max.y > f.box.max.y + 0.5 * dp)) {
      r.fail_value("wavemaker", maker,
                   fmt::format("{} spans y from {:.4g} to {:.4g} m, wider than the water of the "
                               "fill at {} (y from {} to {} m): it would turn through the side "
                               "walls; make it as wide as the water",
                               what, box.min.y, box.max.y, f.where.str(),
                               format_number(f.box.min.y), format_number(f.box.max.y)));
    }
    if (box.min.y <= f.box.min.y + 0.5 * dp && box.max.y >= f.box.max.y - 0.5 * dp) continue;
    r.fail_value("wavemaker", maker,
                 fmt::format("{} spans y from {:.4g} to {:.4g} m, narrower than the water of the "
                             "fill at {} (y from {} to {} m): a paddle spans the tank's width",
                             what, box.min.y, box.max.y, f.where.str(), format_number(f.box.min.y),
                             format_number(f.box.max.y)));
  }
}

void CaseReader::read_wave_train(const TomlTableReader& r) {
  WaveSpec& w = spec_.waves;
  const double g = -spec_.fluid.gravity.z;
  const std::string_view kind = name_of(w.kind);
  const std::vector<std::string_view> regular_keys = {"height", "period", "theory", "generation"};
  const std::vector<std::string_view> jonswap_keys = {"hs", "tp", "gamma", "seed", "components"};
  const std::vector<std::string_view> record_keys = {"displacement"};
  for (const auto& [owner, keys] :
       {std::pair{WaveKind::Regular, regular_keys}, std::pair{WaveKind::Jonswap, jonswap_keys},
        std::pair{WaveKind::Displacement, record_keys}}) {
    if (owner == w.kind) continue;
    for (const std::string_view key : keys) {
      if (const toml::node* node = r.find(key)) {
        r.fail_value(key, *node,
                     fmt::format("applies to type = \"{}\" only, and this is type = \"{}\"{}",
                                 name_of(owner), kind, r.has("type") ? "" : " (the default)"));
      }
    }
  }
  double height = 0, period = 0;
  std::string_view height_key = "height";
  std::vector<WaveComponent> record;  // type = "displacement": the record's components
  if (w.kind == WaveKind::Displacement) {
    if (!w.has_paddle()) {
      r.fail_value("type", *r.find("type"),
                   fmt::format("a displacement record drives a flume's paddle, and {} has none: "
                               "give regular or jonswap waves",
                               w.standalone ? "a standalone net case" : "a relaxation wavemaker"));
    }
    height_key = "displacement";
    record = read_displacement_record(r);
    height = w.record_height;
    period = w.record_period;
  } else if (w.kind == WaveKind::Regular) {
    w.height = height = r.required_number("height", NumberRule::positive("m"),
                                          "the wave height H, crest to trough, m");
    w.period = period =
        r.required_number("period", NumberRule::positive("s"), "the wave period T, s");
    w.theory = r.choice("theory", kWaveTheoryNames, w.theory);
    read_generation(r);
    if (period > spec_.simulation.end_time) {
      r.fail_value("period", *r.find("period"),
                   fmt::format("is longer than the run (simulation.end_time = {} s): not one "
                               "wave would be made",
                               format_number(spec_.simulation.end_time)));
    }
  } else {
    height_key = "hs";
    w.jonswap.hs = height =
        r.required_number("hs", NumberRule::positive("m"), "the significant wave height Hm0, m");
    w.jonswap.tp = period =
        r.required_number("tp", NumberRule::positive("s"), "the peak period Tp, s");
    if (period > spec_.simulation.end_time) {
      r.fail_value("tp", *r.find("tp"),
                   fmt::format("is longer than the run (simulation.end_time = {} s): not one "
                               "wave would be made",
                               format_number(spec_.simulation.end_time)));
    }
    w.jonswap.gamma = r.number("gamma", NumberRule::closed(1, 20, ""), w.jonswap.gamma);
    w.seed = static_cast<std::uint64_t>(
        r.integer("seed", IntRule{0, std::numeric_limits<std::int64_t>::max()}, 1));
    // Enough frequencies that the signal does not repeat within the run: it repeats after
    // 1 / df = components / ((high - low) fp) seconds.
    const double span = (kJonswapHigh - kJonswapLow) / period;
    const auto fallback = static_cast<std::int64_t>(
        std::clamp(std::ceil(1.1 * spec_.simulation.end_time * span), 100.0, 5000.0));
    w.components = static_cast<int>(r.integer("components", IntRule{10, 20000}, fallback));
  }
  // A record carries its own start (no ramp unless asked); a theory's waves start over two
  // periods.
  w.ramp = r.number("ramp", NumberRule::non_negative("s"),
                    w.kind == WaveKind::Displacement ? 0.0 : 2 * period);
  // The breaking limit (Miche 1944) at the wave's (or the sea's peak) wavelength, on the
  // current it rides (standalone waves; a flume's water is still).
  double k = 0;
  try {
    k = w.current == 0 ? wave_number(2 * M_PI / period, w.depth, g)
                       : wave_number_on_current(2 * M_PI / period, w.depth, w.current, g);
  } catch (const Error& e) {
    r.fail_table(fmt::format("the waves cannot exist on this current ({}): {}",
                             wave_current_source(), e.message()));
  }
  const double wavelength = 2 * M_PI / k, limit = breaking_steepness(k * w.depth);
  if (height / wavelength > limit) {
    r.fail_value(
        height_key, *r.find(height_key),
        fmt::format("makes a wave steeper than the breaking limit: H / L = {:.4g} with "
                    "L = {:.4g} m (T = {} s, depth {} m{}), and a wave breaks above H / "
                    "L = 0.142 tanh(kh) = {:.4g} (Miche 1944); the highest that does "
                    "not break is {:.4g} m{}",
                    height / wavelength, wavelength, format_number(period), format_number(w.depth),
                    w.current == 0 ? std::string() : fmt::format(", on {}", wave_current_source()),
                    limit, limit * wavelength,
                    w.kind == WaveKind::Displacement
                        ? fmt::format(" (H is the record's waves' Hm0, T the period of its tallest "
                                      "component: scale the record by {:.3g} or less)",
                                      limit * wavelength / height)
                        : std::string()));
  }
  // Stokes' expansion holds while its second-order surface stays small beside the first
  // order. In shallow water the ratio is 3 H L^2 / (32 pi^2 h^3) = Ur / 105 (Ur = H L^2 / h^3,
  // the Ursell number), so a quarter is Ur = 26, the usual limit of Stokes theory, past which
  // cnoidal theory applies (Dean & Dalrymple 1991, sec. 11).
  if (w.kind == WaveKind::Regular && w.theory == WaveTheory::Stokes2) {
    RegularWave probe;
    probe.height = height, probe.k = k, probe.depth = w.depth, probe.order = 2;
    const double ratio = second_order_surface_amplitude(probe) / (0.5 * height);
    if (ratio > kMaxStokesRatio) {
      r.fail_value("theory", *r.find("theory"),
                   fmt::format("Stokes second order is outside its range here: its second-order "
                               "surface is {:.3g} of the first order's (at most {}), the Ursell "
                               "number H L^2 / h^3 = {:.3g}; use theory = \"linear\" (netsph has "
                               "no cnoidal theory for such long, high waves)",
                               ratio, kMaxStokesRatio,
                               height * wavelength * wavelength / std::pow(w.depth, 3)));
    }
  }
  try {
    if (w.kind == WaveKind::Displacement) {
      w.train = irregular_wave_train(record, w.depth, w.ramp, g);
    } else if (w.kind == WaveKind::Regular) {
      w.train = regular_wave_train(w.height, w.period, w.depth,
                                   w.theory == WaveTheory::Stokes2 ? 2 : 1, w.ramp, g, w.current);
    } else {
      const double fp = 1 / w.jonswap.tp;
      w.train = irregular_wave_train(
          jonswap_components(w.jonswap, kJonswapLow * fp, kJonswapHigh * fp, w.components, w.seed),
          w.depth, w.ramp, g, w.current);
    }
  } catch (const Error& e) {
    // An opposing current past the blocking speed.
    r.fail_table(fmt::format("the waves cannot exist on this current ({}): {}",
                             wave_current_source(), e.message()));
  }
}

// Second-order generation makes the Stokes second-order wave: its paddle adds the second
// harmonic that leaves only the Stokes wave's bound one (waves/wavemaker_theory.hpp). It follows
// the theory by default, so that the paddle makes the wave the gauges are compared with.
void CaseReader::read_generation(const TomlTableReader& r) {
  WaveSpec& w = spec_.waves;
  // Only a paddle has a generation: a standalone case's waves and a relaxation zone's are
  // given by their theory (the relaxation reader refuses the key itself).
  if (!w.has_paddle()) {
    if (const toml::node* node = r.find("generation")) {
      r.fail_value("generation", *node,
                   "applies to a flume's paddle; a standalone case's waves have no paddle (they "
                   "are given by their theory): remove the key");
    }
    return;
  }
  // A flap has first-order theory only (second-order flap generation is not built).
  const PaddleGeneration fallback =
      w.theory == WaveTheory::Stokes2 && w.paddle == PaddleType::Piston
          ? PaddleGeneration::SecondOrder
          : PaddleGeneration::FirstOrder;
  w.generation = r.choice("generation", kPaddleGenerationNames, fallback);
  const toml::node* node = r.find("generation");
  if (!node || w.generation != PaddleGeneration::SecondOrder) return;
  if (w.theory != WaveTheory::Stokes2) {
    r.fail_value(
        "generation", *node,
        "second-order generation makes the Stokes second-order wave, and theory = \"linear\" "
        "asks for a linear one: set theory = \"stokes2\" or generation = \"first_order\"");
  }
  if (w.paddle != PaddleType::Piston) {
    r.fail_value("generation", *node, "second-order generation is built for a piston paddle only");
  }
}

void CaseReader::set_paddle_motion(const TomlTableReader& r) {
  WaveSpec& w = spec_.waves;
  const PaddleMotion motion = train_paddle_motion(w.paddle, w.train, w.generation);
  const double interval = paddle_sample_interval(motion);
  const double samples = spec_.simulation.end_time / interval;
  const double work = samples * static_cast<double>(motion.harmonics.size());
  if (samples > kMaxPaddleSamples || work > kMaxPaddleWork) {
    r.fail_table(fmt::format(
        "the paddle's velocity table would take {:.3g} samples (simulation.end_time = {} s, one "
        "every {:.3g} s: a hundredth of the shortest component's period) of {} component{}: "
        "more than netsph tabulates ({:.0e} samples, {:.0e} sample-components); shorten the run{}",
        samples, format_number(spec_.simulation.end_time), interval, motion.harmonics.size(),
        motion.harmonics.size() == 1 ? "" : "s", kMaxPaddleSamples, kMaxPaddleWork,
        w.kind == WaveKind::Jonswap ? " or give fewer components" : ""));
  }
  SampledPaddle s = sample_paddle(motion, spec_.simulation.end_time, interval);
  if (!std::isfinite(s.max_excursion)) {
    r.fail_table("the paddle's motion is not finite: the wave is too long for the water depth");
  }
  w.max_excursion = s.max_excursion;
  if (w.paddle == PaddleType::Flap) return set_flap_motion(r, s);
  WallSpec& wall = spec_.walls[w.wall];
  wall.motion.times = std::move(s.times);
  wall.motion.velocities.clear();
  for (const double v : s.velocities) wall.motion.velocities.push_back({w.direction * v, 0, 0});

  // The tank must hold the paddle's travel: behind it, its particle layers stay in [domain]
  // and above a bottom; in front, the water it pushes is longer than its stroke.
  const double dp = spec_.simulation.dp, e = w.max_excursion;
  const double back = w.paddle_x - w.direction * (e + wall.layers * dp);
  const toml::node& maker = *r.find("wavemaker");
  const std::string what = fmt::format(
      "the paddle travels {:.4g} m either side of x = {} m over the run (its largest excursion "
      "from {} wavemaker theory, stroke {:.4g} m)",
      e, format_number(w.paddle_x),
      w.generation == PaddleGeneration::SecondOrder ? "second-order" : "first-order", 2 * e);
  const DomainSpec& d = spec_.domain;
  if (d.given && (back < d.min.x || back > d.max.x)) {
    r.fail_value(
        "wavemaker", maker,
        fmt::format("{}; its {} particle layers behind it then reach x = {:.4g} m, "
                    "outside [domain] (x from {} to {} m): widen the domain behind "
                    "the paddle",
                    what, wall.layers, back, format_number(d.min.x), format_number(d.max.x)));
  }
  double water = 0;
  for (const FillSpec& f : spec_.fills) water = std::max(water, f.box.max.x - f.box.min.x);
  if (2 * e > 0.5 * water) {
    r.fail_value("wavemaker", maker,
                 fmt::format("{}, more than half the length of the water ({:.4g} m): a tank "
                             "that short cannot take this wave; lower the height or lengthen "
                             "the tank",
                             what, water));
  }
  const double reach = w.paddle_x - w.direction * e;
  bool bottomed = false, any_bottom = false;
  for (const WallSpec& other : spec_.walls) {
    if (!other.faces[kZMin]) continue;
    any_bottom = true;
    bottomed = bottomed || (w.direction > 0 ? other.box.min.x <= reach + 1e-9 * std::fabs(reach)
                                            : other.box.max.x >= reach - 1e-9 * std::fabs(reach));
  }
  if (any_bottom && !bottomed) {
    r.fail_value("wavemaker", maker,
                 fmt::format("{}, but no wall's bottom (a zmin face) reaches x = {:.4g} m: the "
                             "water behind the retreating paddle would fall through; extend the "
                             "tank's bottom behind the paddle",
                             what, reach));
  }
}

void CaseReader::check_free_surface(const TomlTableReader& r) const {
  const WaveSpec& w = spec_.waves;
  const double crest = w.still_level + w.reference_height();
  for (const WallSpec& wall : spec_.walls) {
    if (!wall.faces[kZMax] || wall.box.max.z > crest) continue;
    for (const FillSpec& f : spec_.fills) {
      if (wall.box.max.x <= f.box.min.x || wall.box.min.x >= f.box.max.x) continue;
      r.fail_table(fmt::format(
          "waves need a free surface, and wall '{}' ({}) closes the water with a lid at z = {} "
          "m, below the wave crests (still level {} m plus the wave height): remove its zmax "
          "face or raise it",
          wall.name, wall.where.str(), format_number(wall.box.max.z),
          format_number(w.still_level)));
    }
  }
}

}  // namespace netsph::case_detail
