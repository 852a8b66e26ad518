#pragma once
// The model choices a case can make. They live in core because both the case reader (which
// parses them) and the physics modules (which act on them) need them.
#include <cstdint>

namespace netsph {

enum class KernelType : std::uint8_t { Wendland, CubicSpline };
enum class ViscosityModel : std::uint8_t { Artificial, Laminar };
enum class DensityDiffusion : std::uint8_t { None, Molteni, Fourtakas };
/// Dynamic boundary particles (Crespo et al. 2007) or modified DBC (English et al. 2022).
enum class WallModel : std::uint8_t { Dbc, Mdbc };
/// Velocity boundary particles show the fluid under mDBC: the wall's own velocity (DBC-like,
/// DualSPHysics' SlipMode 1), the no-slip mirror 2 v_wall - v_ghost, or the free-slip mirror
/// of the normal component only.
enum class WallSlip : std::uint8_t { WallVelocity, NoSlip, FreeSlip };
/// Particle shifting: none, or the Fickian form of Lind et al. (2012) with Skillen et al.'s
/// (2013) coefficient, as DualSPHysics applies it.
enum class ShiftingModel : std::uint8_t { None, Fickian };
/// How an open boundary's buffer particles get their density: extrapolated from the fluid,
/// hydrostatic below a free surface, or the reference density rho0 (zero pressure: the
/// pressure reference of a closed duct's outlet).
enum class BufferDensity : std::uint8_t { Extrapolated, Hydrostatic, Reference };

/// The solid of a [[body]], in its own frame (geometry/shapes.hpp has the conventions).
enum class BodyShape : std::uint8_t { Box, Cylinder, Sphere, Cruciform };
/// Fixed bodies only measure forces; floating ones move under them; prescribed ones follow a
/// given velocity.
enum class BodyMotion : std::uint8_t { Fixed, Floating, Prescribed };

}  // namespace netsph
