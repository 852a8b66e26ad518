#pragma once
// The model choices a case can make. They live in core because both the case reader (which
// parses them) and the physics modules (which act on them) need them.
//
// Below each enum, its one table of names (core/enum_names.hpp): the words of the case file,
// which the case reader parses and lists in its messages (in the table's order), and which the
// logs and summary.json print (name_of).
#include <array>
#include <cstdint>
#include <string_view>

#include "netsph/core/enum_names.hpp"

namespace netsph {

enum class KernelType : std::uint8_t { Wendland, CubicSpline };
inline constexpr std::array kKernelTypeNames = {
    EnumName<KernelType>{"wendland", KernelType::Wendland},
    EnumName<KernelType>{"cubic_spline", KernelType::CubicSpline}};
/// The kernel as the scene summary in the log names it: a second spelling, in words.
inline constexpr std::array kKernelTypeLabels = {
    EnumName<KernelType>{"Wendland", KernelType::Wendland},
    EnumName<KernelType>{"cubic spline", KernelType::CubicSpline}};
constexpr std::string_view name_of(KernelType v) {
  return name_of(kKernelTypeNames, v);
}

enum class ViscosityModel : std::uint8_t { Artificial, Laminar };
inline constexpr std::array kViscosityModelNames = {
    EnumName<ViscosityModel>{"artificial", ViscosityModel::Artificial},
    EnumName<ViscosityModel>{"laminar", ViscosityModel::Laminar}};
constexpr std::string_view name_of(ViscosityModel v) {
  return name_of(kViscosityModelNames, v);
}

enum class DensityDiffusion : std::uint8_t { None, Molteni, Fourtakas };
inline constexpr std::array kDensityDiffusionNames = {
    EnumName<DensityDiffusion>{"none", DensityDiffusion::None},
    EnumName<DensityDiffusion>{"molteni", DensityDiffusion::Molteni},
    EnumName<DensityDiffusion>{"fourtakas", DensityDiffusion::Fourtakas}};
constexpr std::string_view name_of(DensityDiffusion v) {
  return name_of(kDensityDiffusionNames, v);
}

/// Dynamic boundary particles (Crespo et al. 2007) or modified DBC (English et al. 2022).
enum class WallModel : std::uint8_t { Dbc, Mdbc };
inline constexpr std::array kWallModelNames = {EnumName<WallModel>{"dbc", WallModel::Dbc},
                                               EnumName<WallModel>{"mdbc", WallModel::Mdbc}};
constexpr std::string_view name_of(WallModel v) {
  return name_of(kWallModelNames, v);
}

/// Velocity boundary particles show the fluid under mDBC: the wall's own velocity (DBC-like,
/// DualSPHysics' SlipMode 1), the no-slip mirror 2 v_wall - v_ghost, or the free-slip mirror
/// of the normal component only.
enum class WallSlip : std::uint8_t { WallVelocity, NoSlip, FreeSlip };
/// In the order of [[body]] slip (its default first); [[wall]] lists them no_slip first.
inline constexpr std::array kWallSlipNames = {
    EnumName<WallSlip>{"wall_velocity", WallSlip::WallVelocity},
    EnumName<WallSlip>{"no_slip", WallSlip::NoSlip},
    EnumName<WallSlip>{"free_slip", WallSlip::FreeSlip}};
constexpr std::string_view name_of(WallSlip v) {
  return name_of(kWallSlipNames, v);
}

/// Particle shifting: none, or the Fickian form of Lind et al. (2012) with Skillen et al.'s
/// (2013) coefficient, as DualSPHysics applies it.
enum class ShiftingModel : std::uint8_t { None, Fickian };
inline constexpr std::array kShiftingModelNames = {
    EnumName<ShiftingModel>{"none", ShiftingModel::None},
    EnumName<ShiftingModel>{"fickian", ShiftingModel::Fickian}};
constexpr std::string_view name_of(ShiftingModel v) {
  return name_of(kShiftingModelNames, v);
}

/// How an open boundary's buffer particles get their density: extrapolated from the fluid,
/// hydrostatic below a free surface, or the reference density rho0 (zero pressure: the
/// pressure reference of a closed duct's outlet).
enum class BufferDensity : std::uint8_t { Extrapolated, Hydrostatic, Reference };
inline constexpr std::array kBufferDensityNames = {
    EnumName<BufferDensity>{"extrapolated", BufferDensity::Extrapolated},
    EnumName<BufferDensity>{"hydrostatic", BufferDensity::Hydrostatic},
    EnumName<BufferDensity>{"reference", BufferDensity::Reference}};
constexpr std::string_view name_of(BufferDensity v) {
  return name_of(kBufferDensityNames, v);
}

/// The solid of a [[body]], in its own frame (geometry/shapes.hpp has the conventions). No
/// names: the case file names the shape in its own words (box, plate, square_plate, ...,
/// case_reader_bodies.cpp), several of which map to one BodyShape.
enum class BodyShape : std::uint8_t { Box, Cylinder, Sphere, Cruciform };

/// Fixed bodies only measure forces; floating ones move under them; prescribed ones follow a
/// given velocity.
enum class BodyMotion : std::uint8_t { Fixed, Floating, Prescribed };
inline constexpr std::array kBodyMotionNames = {
    EnumName<BodyMotion>{"fixed", BodyMotion::Fixed},
    EnumName<BodyMotion>{"floating", BodyMotion::Floating},
    EnumName<BodyMotion>{"prescribed", BodyMotion::Prescribed}};
constexpr std::string_view name_of(BodyMotion v) {
  return name_of(kBodyMotionNames, v);
}

}  // namespace netsph

namespace netsph {

/// The rigid shape that stands for one cruciform net element (Shi et al. 2024, Table 1).
enum class KnotShape : std::uint8_t { SquarePlate, CircularPlate, Sphere };
inline constexpr std::array kKnotShapeNames = {
    EnumName<KnotShape>{"square_plate", KnotShape::SquarePlate},
    EnumName<KnotShape>{"circular_plate", KnotShape::CircularPlate},
    EnumName<KnotShape>{"sphere", KnotShape::Sphere}};
constexpr std::string_view name_of(KnotShape v) {
  return name_of(kKnotShapeNames, v);
}

/// How the cruciform element's projected area A and volume V are counted (twine length l,
/// diameter d; net/equivalent_knot.hpp):
///   Exact       A = 2ld - d^2, V = (pi/4) d^2 (2l - d)  (the crossing counted once; Table 1)
///   FullVolume  A = 2ld - d^2, V = (pi/4) d^2 2l        (reproduces the paper's rigid net)
///   Full        A = 2ld,       V = (pi/4) d^2 2l        (reproduces the paper's Bi 2014 net)
enum class EquivalentKnotRule : std::uint8_t { Exact, FullVolume, Full };
inline constexpr std::array kEquivalentKnotRuleNames = {
    EnumName<EquivalentKnotRule>{"exact", EquivalentKnotRule::Exact},
    EnumName<EquivalentKnotRule>{"full_volume", EquivalentKnotRule::FullVolume},
    EnumName<EquivalentKnotRule>{"full", EquivalentKnotRule::Full}};
constexpr std::string_view name_of(EquivalentKnotRule v) {
  return name_of(kEquivalentKnotRuleNames, v);
}

/// Crossings: a knot at every twine crossing, (n+1) x (n+1) for n x n meshes, edges included
/// (the paper's 36 and 121 knots). Inset: n x n knots at the centres of the outline's n x n
/// cells, half a mesh inside the outline (the paper's 225 knots for Bi's 15 x 15 net).
enum class KnotLayout : std::uint8_t { Crossings, Inset };
inline constexpr std::array kKnotLayoutNames = {
    EnumName<KnotLayout>{"crossings", KnotLayout::Crossings},
    EnumName<KnotLayout>{"inset", KnotLayout::Inset}};
constexpr std::string_view name_of(KnotLayout v) {
  return name_of(kKnotLayoutNames, v);
}

/// Full: every knot a whole equivalent element (the paper). SolidityMatched: edge knots stand
/// for half an element and corner knots for a quarter, so that the numerical solidity equals
/// the real one (crossings layout only).
enum class EdgeKnots : std::uint8_t { Full, SolidityMatched };
inline constexpr std::array kEdgeKnotsNames = {
    EnumName<EdgeKnots>{"full", EdgeKnots::Full},
    EnumName<EdgeKnots>{"solidity-matched", EdgeKnots::SolidityMatched}};
constexpr std::string_view name_of(EdgeKnots v) {
  return name_of(kEdgeKnotsNames, v);
}

/// How a standalone net (no SPH fluid) is loaded by a uniform current.
enum class NetLoadModel : std::uint8_t { None, Morison, Screen };
/// The default, screen, first.
inline constexpr std::array kNetLoadModelNames = {
    EnumName<NetLoadModel>{"screen", NetLoadModel::Screen},
    EnumName<NetLoadModel>{"morison", NetLoadModel::Morison},
    EnumName<NetLoadModel>{"none", NetLoadModel::None}};
constexpr std::string_view name_of(NetLoadModel v) {
  return name_of(kNetLoadModelNames, v);
}

/// Screen-model coefficient sets (net/screen_model.hpp).
enum class ScreenCoefficients : std::uint8_t { S1Aarsnes, S2Loland, S3KristiansenFaltinsen };
/// The default, S3, first.
inline constexpr std::array kScreenCoefficientsNames = {
    EnumName<ScreenCoefficients>{"S3", ScreenCoefficients::S3KristiansenFaltinsen},
    EnumName<ScreenCoefficients>{"S1", ScreenCoefficients::S1Aarsnes},
    EnumName<ScreenCoefficients>{"S2", ScreenCoefficients::S2Loland}};
constexpr std::string_view name_of(ScreenCoefficients v) {
  return name_of(kScreenCoefficientsNames, v);
}

// Each table above names each value once.
static_assert(one_to_one(kKernelTypeNames) && one_to_one(kKernelTypeLabels) &&
              one_to_one(kViscosityModelNames) && one_to_one(kDensityDiffusionNames) &&
              one_to_one(kWallModelNames) && one_to_one(kWallSlipNames) &&
              one_to_one(kShiftingModelNames) && one_to_one(kBufferDensityNames) &&
              one_to_one(kBodyMotionNames) && one_to_one(kKnotShapeNames) &&
              one_to_one(kEquivalentKnotRuleNames) && one_to_one(kKnotLayoutNames) &&
              one_to_one(kEdgeKnotsNames) && one_to_one(kNetLoadModelNames) &&
              one_to_one(kScreenCoefficientsNames));

}  // namespace netsph
