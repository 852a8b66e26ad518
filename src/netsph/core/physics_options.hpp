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

namespace netsph {

/// The rigid shape that stands for one cruciform net element (Shi et al. 2024, Table 1).
enum class KnotShape : std::uint8_t { SquarePlate, CircularPlate, Sphere };
/// How the cruciform element's projected area A and volume V are counted (twine length l,
/// diameter d; net/equivalent_knot.hpp):
///   Exact       A = 2ld - d^2, V = (pi/4) d^2 (2l - d)  (the crossing counted once; Table 1)
///   FullVolume  A = 2ld - d^2, V = (pi/4) d^2 2l        (reproduces the paper's rigid net)
///   Full        A = 2ld,       V = (pi/4) d^2 2l        (reproduces the paper's Bi 2014 net)
enum class EquivalentKnotRule : std::uint8_t { Exact, FullVolume, Full };
/// Crossings: a knot at every twine crossing, (n+1) x (n+1) for n x n meshes, edges included
/// (the paper's 36 and 121 knots). Inset: n x n knots at the centres of the outline's n x n
/// cells, half a mesh inside the outline (the paper's 225 knots for Bi's 15 x 15 net).
enum class KnotLayout : std::uint8_t { Crossings, Inset };
/// Full: every knot a whole equivalent element (the paper). SolidityMatched: edge knots stand
/// for half an element and corner knots for a quarter, so that the numerical solidity equals
/// the real one (crossings layout only).
enum class EdgeKnots : std::uint8_t { Full, SolidityMatched };
/// How a standalone net (no SPH fluid) is loaded by a uniform current.
enum class NetLoadModel : std::uint8_t { None, Morison, Screen };
/// Screen-model coefficient sets (net/screen_model.hpp).
enum class ScreenCoefficients : std::uint8_t { S1Aarsnes, S2Loland, S3KristiansenFaltinsen };

}  // namespace netsph
