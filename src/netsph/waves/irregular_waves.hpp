#pragma once
// Irregular waves from a JONSWAP spectrum (Hasselmann et al. 1973): the spectrum, scaled to a
// given significant wave height, and its discretisation into wave components with seeded
// random phases (the random-phase method). The components' phases come from a generator whose
// output the C++ standard fixes (std::mt19937_64), turned into a phase by our own arithmetic,
// so that a seed gives the same wave train on every machine and compiler.
#include <cstdint>
#include <vector>

namespace netsph {

/// A JONSWAP sea state.
struct JonswapSpec {
  double hs = 0;          ///< significant wave height Hm0 = 4 sqrt(m0), m
  double tp = 0;          ///< peak period, s
  double gamma = 3.3;     ///< peak enhancement factor (3.3: the JONSWAP mean; 1: Pierson-Moskowitz)
  double sigma_a = 0.07;  ///< peak width below the peak frequency
  double sigma_b = 0.09;  ///< peak width above it
};

/// The spectrum's shape at frequency f (Hz), before scaling: f^-5 exp(-5/4 (fp/f)^4)
/// gamma^exp(-(f - fp)^2 / (2 sigma^2 fp^2)), the JONSWAP form (Hasselmann et al. 1973) with
/// the Phillips constant and g left out; jonswap_density scales it.
double jonswap_shape(const JonswapSpec& s, double f);

/// One wave component: elevation a cos(k x - 2 pi f t + phase), the convention of
/// RegularWave (wave_kinematics.hpp).
struct WaveComponent {
  double frequency = 0;  ///< Hz
  double amplitude = 0;  ///< m
  double phase = 0;      ///< rad, in [0, 2 pi)
};

/// The discretised sea state: `count` components at equally spaced frequencies f_i = (i + 1/2)
/// df over [f_min, f_max] (df = (f_max - f_min) / count), amplitudes sqrt(2 S(f_i) df) with S
/// scaled so that the components' variance sum_i a_i^2 / 2 is exactly Hs^2 / 16, and phases
/// from `seed`. The signal repeats after 1 / df seconds: choose df below 1 / (the run's
/// duration). Throws netsph::Error for a spec or range that makes no sea state.
std::vector<WaveComponent> jonswap_components(const JonswapSpec& s, double f_min, double f_max,
                                              int count, std::uint64_t seed);

/// The components' surface elevation at the reference point x = 0 at time t, m.
double irregular_elevation(const std::vector<WaveComponent>& components, double t);

}  // namespace netsph
