#pragma once
// The linear dispersion relation of surface gravity waves and its Doppler-shifted form on a
// uniform current, solved for the wave number (Dean & Dalrymple 1991, "Water Wave Mechanics
// for Engineers and Scientists", ch. 3-4; Jonsson 1990 for waves on a current), and the limits
// a regular wave must respect: the breaking steepness (Miche 1944) and the blocking current.
// Host functions: wave set-up, not per-particle work.

namespace netsph {

/// Standard gravity, m/s^2, for callers without a case (tests, tools).
inline constexpr double kStandardGravity = 9.81;

/// The wave number k, rad/m, of a wave of angular frequency omega (rad/s) in water of depth h
/// (m) under gravity g (m/s^2): the root of omega^2 = g k tanh(k h) (Newton from the explicit
/// approximation of Fenton & McKee 1990; converged to 1e-14 relative). Throws netsph::Error
/// for omega, h or g not positive and finite.
double wave_number(double omega, double depth, double g = kStandardGravity);

/// The wave number of a wave of absolute (earth-frame) angular frequency omega travelling in
/// +x on a current U along +x (U > 0 following, U < 0 opposing): the root of
/// (omega - k U)^2 = g k tanh(k h) with intrinsic frequency omega - k U > 0, the branch that
/// tends to wave_number(omega, h, g) as U -> 0. An opposing current at or beyond the blocking
/// speed (where the wave's group velocity relative to the water equals -U; in deep water
/// U = -g / (4 omega)) stops the wave: throws netsph::Error saying so.
double wave_number_on_current(double omega, double depth, double current,
                              double g = kStandardGravity);

/// The intrinsic frequency sigma = sqrt(g k tanh(k h)), rad/s: the frequency seen moving
/// with the current.
double intrinsic_frequency(double k, double depth, double g = kStandardGravity);

/// The group velocity relative to the water, dsigma/dk, m/s.
double relative_group_velocity(double k, double depth, double g = kStandardGravity);

/// The steepest regular wave before it breaks, H / L = 0.142 tanh(k h) (Miche 1944, as in
/// Dean & Dalrymple 1991 sec. 4.8; 0.142 = 1/7 in deep water).
double breaking_steepness(double kh);

}  // namespace netsph
