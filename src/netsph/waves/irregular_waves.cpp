#include "netsph/waves/irregular_waves.hpp"

#include <cmath>
#include <random>

#include <fmt/format.h>

#include "netsph/core/error.hpp"

namespace netsph {

double jonswap_shape(const JonswapSpec& s, double f) {
  if (!(f > 0)) return 0;
  const double fp = 1 / s.tp;
  const double sigma = f <= fp ? s.sigma_a : s.sigma_b;
  const double r = (f - fp) / (sigma * fp);
  const double x = fp / f;
  return std::pow(f, -5.0) * std::exp(-1.25 * x * x * x * x) *
         std::pow(s.gamma, std::exp(-0.5 * r * r));
}

std::vector<WaveComponent> jonswap_components(const JonswapSpec& s, double f_min, double f_max,
                                              int count, std::uint64_t seed) {
  if (!(s.hs > 0) || !(s.tp > 0) || !(s.gamma >= 1) || !(s.sigma_a > 0) || !(s.sigma_b > 0)) {
    throw Error("waves", fmt::format("a JONSWAP sea state needs Hs > 0, Tp > 0, gamma >= 1 and "
                                     "positive peak widths (got Hs = {}, Tp = {}, gamma = {})",
                                     s.hs, s.tp, s.gamma));
  }
  if (!(f_min >= 0) || !(f_max > f_min) || count < 1) {
    throw Error("waves", fmt::format("the wave components need 0 <= f_min < f_max and at least "
                                     "one component (got [{}, {}] Hz, {})",
                                     f_min, f_max, count));
  }
  const double df = (f_max - f_min) / count;
  std::vector<WaveComponent> c(static_cast<std::size_t>(count));
  double variance = 0;
  std::mt19937_64 rng(seed);
  for (int i = 0; i < count; ++i) {
    WaveComponent& w = c[static_cast<std::size_t>(i)];
    w.frequency = f_min + (i + 0.5) * df;
    w.amplitude = std::sqrt(2 * jonswap_shape(s, w.frequency) * df);
    variance += 0.5 * w.amplitude * w.amplitude;
    // 53 random bits to a phase in [0, 2 pi): std::uniform_real_distribution's algorithm is
    // the library's choice, this is ours.
    w.phase = 2 * M_PI * static_cast<double>(rng() >> 11) * 0x1.0p-53;
  }
  if (!(variance > 0)) {
    throw Error("waves", fmt::format("the JONSWAP spectrum with Tp = {} s has no energy in "
                                     "[{}, {}] Hz",
                                     s.tp, f_min, f_max));
  }
  // Scaled so that m0 of the discrete sea state is Hs^2 / 16 (Hm0 = 4 sqrt(m0)) exactly.
  const double scale = std::sqrt(s.hs * s.hs / 16 / variance);
  for (WaveComponent& w : c) w.amplitude *= scale;
  return c;
}

double irregular_elevation(const std::vector<WaveComponent>& components, double t) {
  double eta = 0;
  for (const WaveComponent& w : components)
    eta += w.amplitude * std::cos(w.phase - 2 * M_PI * w.frequency * t);
  return eta;
}

}  // namespace netsph
