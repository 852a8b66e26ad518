#pragma once
// The motion of a wavemaker paddle that makes a given wave, from first-order wavemaker
// theory (wavemaker_theory.hpp): its stroke from the wave's height, and its displacement and
// velocity in time, ramped up from rest. The wave at the paddle (x = 0 of the wave) is
// eta = (H/2) cos(k x - omega t + phase); the progressive wave's velocity at the paddle is in
// phase with the paddle's velocity (the evanescent modes take the rest of the paddle's flow,
// in quadrature: Dean & Dalrymple 1991, sec. 6.3), so the paddle moves as
// X(t) = (S/2) sin(omega t - phase). For a flap, X is the excursion at the still-water level.
// An irregular sea moves it as the sum of its components' motions (wave_train.hpp:
// train_paddle_motion). Host functions: a moving wall's velocity is evaluated once per step
// per wall.
#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "netsph/core/enum_names.hpp"
#include "netsph/waves/wave_kinematics.hpp"
#include "netsph/waves/wavemaker_theory.hpp"

namespace netsph {

enum class PaddleType : std::uint8_t { Piston, Flap };
inline constexpr std::array kPaddleTypeNames = {EnumName<PaddleType>{"piston", PaddleType::Piston},
                                                EnumName<PaddleType>{"flap", PaddleType::Flap}};
static_assert(one_to_one(kPaddleTypeNames));
constexpr std::string_view name_of(PaddleType v) {
  return name_of(kPaddleTypeNames, v);
}

/// How the paddle's motion is made: first-order wavemaker theory only, or with the second-order
/// correction that suppresses the free second harmonic (piston_second_order_amplitude).
enum class PaddleGeneration : std::uint8_t { FirstOrder, SecondOrder };
inline constexpr std::array kPaddleGenerationNames = {
    EnumName<PaddleGeneration>{"first_order", PaddleGeneration::FirstOrder},
    EnumName<PaddleGeneration>{"second_order", PaddleGeneration::SecondOrder}};
static_assert(one_to_one(kPaddleGenerationNames));
constexpr std::string_view name_of(PaddleGeneration v) {
  return name_of(kPaddleGenerationNames, v);
}

/// One harmonic of a paddle's motion: X = ramp(t) (stroke / 2) sin(omega t - phase).
struct PaddleHarmonic {
  double stroke = 0;  ///< S, m (full excursion; a second-order correction's may be negative)
  double omega = 0;   ///< rad/s
  double phase = 0;   ///< rad: the phase of the wave it makes at the paddle
};

/// The paddle's motion: its harmonics and the ramp that starts them from rest.
struct PaddleMotion {
  std::vector<PaddleHarmonic> harmonics;
  double ramp = 0;  ///< s (0: none)
};

/// H / S of a paddle of `type` at kh.
inline double paddle_height_to_stroke(PaddleType type, double kh) {
  return type == PaddleType::Piston ? piston_height_to_stroke(kh) : flap_height_to_stroke(kh);
}

/// The paddle motion that makes regular wave `w` (w.k the wave number in still water at the
/// paddle): its first-order harmonic and, for second-order generation (a piston only: netsph::
/// Error for a flap), the second harmonic A2 sin(2 (omega t - phase)) that cancels the free
/// second harmonic (wavemaker_theory.hpp). The ramp multiplies both.
PaddleMotion regular_paddle_motion(PaddleType type, const RegularWave& w, double ramp,
                                   PaddleGeneration generation = PaddleGeneration::FirstOrder);

/// The paddle's displacement X(t), m, and velocity dX/dt, m/s (the ramp's own rate included,
/// so that the velocity is the displacement's derivative).
void paddle_state(const PaddleMotion& m, double t, double& displacement, double& velocity);

}  // namespace netsph
