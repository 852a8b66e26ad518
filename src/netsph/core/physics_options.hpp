#pragma once
// The model choices a case can make. They live in core because both the case reader (which
// parses them) and the physics modules (which act on them) need them.
#include <cstdint>

namespace netsph {

enum class KernelType : std::uint8_t { Wendland, CubicSpline };
enum class ViscosityModel : std::uint8_t { Artificial, Laminar };
enum class DensityDiffusion : std::uint8_t { None, Molteni, Fourtakas };
enum class WallModel : std::uint8_t { Dbc };

}  // namespace netsph
