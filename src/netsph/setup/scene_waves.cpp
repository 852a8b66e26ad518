#include <cmath>
#include <string>

#include <fmt/format.h>

#include "netsph/core/error.hpp"
#include "netsph/setup/scene_builders.hpp"
#include "netsph/sph/time_step.hpp"
#include "netsph/waves/wavemaker_theory.hpp"

// The waves' part of a scene: the damping zones the step applies, and the checks on [waves]
// that need the scene's fluid model (its first time step) or its resolution.
namespace netsph::scene_build {

namespace {

/// A wave period needs this many time steps at least: the paddle's motion and the orbital
/// velocities then change by under a third of a radian per step.
constexpr double kMinStepsPerPeriod = 20;
/// A wave height resolved by fewer particles than this is a warning: below about six, the
/// surface's kernel smoothing (2h = 3 dp) is as large as the wave and damps it.
constexpr double kMinParticlesPerHeight = 6;

}  // namespace

void add_damping_zones(const CaseSpec& spec, Scene& scene) {
  // A relaxation wavemaker is a damping zone whose target moves with the wave: s = 0 at the
  // zone's end (x_end, where the waves leave), full at x_full.
  const WaveSpec& w = spec.waves;
  if (w.given && w.relaxation) {
    DampingZone z{w.relaxation_end, w.relaxation_full, w.relaxation_rate,
                  Vec3f(Vec3d{w.direction * w.current, 0, 0})};
    z.wave = {w.train.components.front(), w.paddle_x, w.still_level, w.ramp, w.direction};
    scene.damping.push_back(z);
  }
  for (const DampingSpec& d : spec.damping)
    scene.damping.push_back({d.from, d.to, d.rate, Vec3f(d.velocity)});
}

void check_waves(const CaseSpec& spec, Scene& scene) {
  const WaveSpec& w = spec.waves;
  if (!w.given) return;
  const double dp = spec.simulation.dp;
  const bool regular = w.kind == WaveKind::Regular;
  const std::string_view period_key = w.period_key(), height_key = w.height_key();
  const bool record = w.kind == WaveKind::Displacement;
  const double height = w.reference_height();
  const double period = w.reference_period();
  // The first step: the fluid at rest under gravity (force limit) or the acoustic limit.
  TimeStepInputs at_rest;
  at_rest.max_acc = norm(spec.fluid.gravity);
  TimeStepLimits limits = compute_time_step(scene.model, spec.simulation.cfl, at_rest);
  double dt = limits.dt;
  if (spec.simulation.dt_max > 0) dt = std::min(dt, spec.simulation.dt_max);
  // An irregular sea's shortest component matters: its period is Tp / 3.
  double shortest = period;
  for (const RegularWave& c : w.train.components) shortest = std::min(shortest, 2 * M_PI / c.omega);
  if (shortest / dt < kMinStepsPerPeriod) {
    throw Error(w.where.str(),
                fmt::format("waves.{}{} gives {:.3g} time steps per {}period{} at the first time "
                            "step, {:.3g} s; the paddle and the waves need at least {:.0f}: lower "
                            "simulation.dt_max or simulation.cfl, or lengthen the period",
                            period_key, record ? std::string() : fmt::format(" = {:g} s", period),
                            shortest / dt, regular ? "" : "shortest component's ",
                            regular ? std::string() : fmt::format(" ({:.3g} s)", shortest), dt,
                            kMinStepsPerPeriod));
  }
  const double per_height = height / dp;
  if (per_height < kMinParticlesPerHeight) {
    scene.warnings.push_back(fmt::format(
        "[waves] ({}): waves.{} {} {:g} m, the wave height, is {:.3g} particle spacings (dp = "
        "{:g} m); below {:.0f} the kernel (2h = {:.3g} dp) smooths the surface over the whole "
        "wave and damps it: use dp <= {:.3g} m",
        w.where.str(), height_key, record ? "(its waves' Hm0)" : "=", height, per_height, dp,
        kMinParticlesPerHeight, 2 * spec.simulation.h_over_dp, height / kMinParticlesPerHeight));
  }
  if (w.paddle == PaddleType::Flap && w.theory == WaveTheory::Stokes2 && w.has_paddle()) {
    scene.warnings.push_back(fmt::format(
        "[waves] ({}): a flap moves by first-order theory only: the Stokes second-order wave "
        "asked for comes with the free second harmonic first-order generation makes "
        "(second-order generation is built for a piston)",
        w.where.str()));
  }
  if (record && spec.simulation.end_time > w.record_length * (1 + 1e-9)) {
    scene.warnings.push_back(fmt::format(
        "[waves] ({}): the displacement record is {:g} s long and the run {:g} s: the paddle "
        "repeats the record every {:g} s",
        w.where.str(), w.record_length, spec.simulation.end_time, w.record_length));
  }
  if (w.ramp >= spec.simulation.end_time) {
    scene.warnings.push_back(fmt::format(
        "[waves] ({}): the ramp, {:g} s, lasts the whole run (simulation.end_time = {:g} s): "
        "the waves never reach their full height",
        w.where.str(), w.ramp, spec.simulation.end_time));
  }
  const double wavelength = w.reference_wavelength();
  if (w.generation == PaddleGeneration::SecondOrder) {
    // Madsen's correction is a long-wave result: past kh of about 1.16 its second harmonic
    // changes sign, where the full theory with evanescent modes (Schaffer 1996) departs from it.
    const double kh = 2 * M_PI / wavelength * w.depth;
    if (piston_second_order_amplitude(height, kh, w.depth) < 0) {
      scene.warnings.push_back(fmt::format(
          "[waves] ({}): generation = \"second_order\" at kh = {:.3g}: Madsen's (1971) "
          "correction, a shallow-water theory, is outside its range past kh = 1.16 (it changes "
          "sign there); the free second harmonic it is meant to cancel is small in this deeper "
          "water: consider generation = \"first_order\"",
          w.where.str(), kh));
    }
  }
  if (w.relaxation && std::fabs(w.relaxation_end - w.relaxation_full) < 0.5 * wavelength) {
    scene.warnings.push_back(fmt::format(
        "[waves] ({}): the relaxation zone is {:.3g} m long, under half the wavelength ({:.3g} "
        "m): a zone that short makes a lower wave than asked for; make it one to two "
        "wavelengths long",
        w.where.str(), std::fabs(w.relaxation_end - w.relaxation_full), wavelength));
  }
  for (const DampingSpec& d : spec.damping) {
    const double length = std::fabs(d.to - d.from);
    if (length >= 0.5 * wavelength) continue;
    scene.warnings.push_back(fmt::format(
        "damping zone '{}' ({}) is {:.3g} m long, under half the wavelength ({:.3g} m): a zone "
        "that short reflects much of the wave; make it one to two wavelengths long",
        d.name, d.where.str(), length, wavelength));
  }
}

}  // namespace netsph::scene_build
