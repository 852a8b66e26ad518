#include "netsph/net/net_generator.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "netsph/core/error.hpp"
#include "netsph/geometry/shapes.hpp"

namespace netsph {
namespace {

/// Meshes of the numerical twine length across an outline side; the side must hold a whole
/// number of them within 5% (the knots are then spread evenly over the side).
int mesh_count(const NetSpec& spec, double side, double twine, const char* key) {
  const double meshes = side / twine;
  // A bound before any count becomes an int or a knot is built: a side of 100 km at 2 cm
  // meshes asked for 1e13 knots and ran the machine out of memory. 10^4 meshes a side is a
  // 30 m cage wall at 3 mm twines, far beyond what the coupled model resolves.
  constexpr double kMostMeshes = 1e4;
  if (!(meshes <= kMostMeshes)) {
    throw Error(spec.where.str(),
                fmt::format("net '{}': {} = {} m holds {:.3g} numerical meshes of mesh_grouping x "
                            "twine_length = {:.4g} m, more than {:.0f} a side: raise "
                            "mesh_grouping or make the net smaller",
                            spec.name, key, side, meshes, twine, kMostMeshes));
  }
  const int n = std::max(1, static_cast<int>(std::lround(meshes)));
  if (std::abs(meshes - n) > 0.05 * n) {
    throw Error(spec.where.str(),
                fmt::format("net '{}': {} = {} m holds {:.3g} numerical meshes of mesh_grouping x "
                            "twine_length = {:.4g} m; it must be a whole number (within 5%): "
                            "choose {} or {} m, or another mesh_grouping",
                            spec.name, key, side, meshes, twine, std::floor(meshes) * twine,
                            std::ceil(meshes) * twine));
  }
  return n;
}

KnotGeometry scaled_knot(const CruciformElement& whole, KnotShape shape, double fraction) {
  return equivalent_knot({whole.area * fraction, whole.volume * fraction}, shape);
}

bool on_fixed_edge(const NetSpec& spec, int row, int column, int rows, int columns) {
  return spec.rigid || (spec.fixed_edges[0] && row == 0) ||
         (spec.fixed_edges[1] && row == rows - 1) || (spec.fixed_edges[2] && column == 0) ||
         (spec.fixed_edges[3] && column == columns - 1);
}

}  // namespace

double resolved_knot_volume(const KnotGeometry& g, double dp) {
  if (dp <= 0) return g.volume;
  Shape s;
  switch (g.shape) {
    case KnotShape::SquarePlate:
      s = Shape::box({g.thickness, g.size, g.size});
      break;
    case KnotShape::CircularPlate:
      s = Shape::cylinder(g.size, g.thickness);
      break;
    case KnotShape::Sphere:
      s = Shape::sphere(g.size);
      break;
  }
  return resolvable_shape(s, dp, 3).measure(3);
}

NetEnvironment net_environment(const CaseSpec& spec) {
  NetEnvironment env;
  env.water_density = spec.fluid.density;
  env.gravity = spec.fluid.gravity;
  if (spec.net_only()) {
    env.knot_buoyancy = true;
  } else if (norm2(spec.fluid.gravity) > 0 || !spec.fluid.structure_gravity) {
    env.knot_buoyancy = false;
    env.resolved_dp = spec.simulation.dp;
  } else {
    env.gravity = *spec.fluid.structure_gravity;
    env.knot_buoyancy = true;
  }
  return env;
}

NetModel generate_net(const NetSpec& spec, const NetEnvironment& env) {
  constexpr double pi = std::numbers::pi;
  NetModel net;
  net.name = spec.name;
  net.center = spec.center;
  net.normal = spec.normal / norm(spec.normal);
  const Vec3d up = spec.up - net.normal * dot(spec.up, net.normal);
  net.up = up / norm(up);
  net.across = cross(net.up, net.normal);
  net.width = spec.width;
  net.height = spec.height;
  net.mesh_grouping = spec.mesh_grouping;
  net.twine_length = spec.twine_length;
  net.twine_diameter = spec.twine_diameter;

  const double lambda = spec.mesh_grouping;
  const double twine = lambda * spec.twine_length;
  const double diameter = lambda * spec.twine_diameter;
  const int meshes_across = mesh_count(spec, spec.width, twine, "width");
  const int meshes_up = mesh_count(spec, spec.height, twine, "height");
  net.spacing_across = spec.width / meshes_across;
  net.spacing_up = spec.height / meshes_up;
  const bool crossings = spec.layout == KnotLayout::Crossings;
  net.columns = crossings ? meshes_across + 1 : meshes_across;
  net.rows = crossings ? meshes_up + 1 : meshes_up;
  const double offset = crossings ? 0.0 : 0.5;

  net.element = cruciform_element(twine, diameter, spec.equivalent_knot);
  net.knot = equivalent_knot(net.element, spec.knot_shape);
  net.real_solidity = netting_solidity(spec.twine_length, spec.twine_diameter);
  // The real netting a numerical element stands for: lambda^2 real elements.
  const double real_element_volume =
      cruciform_element(spec.twine_length, spec.twine_diameter, spec.equivalent_knot).volume;
  const double cell_area = net.spacing_across * net.spacing_up;

  // Sinker: weight less buoyancy, shared by the bottom knots in proportion to the outline
  // length each one carries (half a spacing at the ends of a crossings layout).
  const SinkerSpec& sinker = spec.sinker;
  const double sinker_volume = pi / 4 * sinker.diameter * sinker.diameter * sinker.length;
  net.sinker_mass = sinker.density * sinker_volume;
  net.sinker_diameter = sinker.diameter;
  net.sinker_drag_coefficient = sinker.drag_coefficient;
  net.sinker_offset = offset * net.spacing_up;
  net.crossings = crossings;

  double projected = 0;
  for (int row = 0; row < net.rows; ++row) {
    for (int column = 0; column < net.columns; ++column) {
      NetKnot k;
      k.row = row;
      k.column = column;
      const double a = (column + offset) * net.spacing_across - spec.width / 2;
      const double u = (row + offset) * net.spacing_up - spec.height / 2;
      k.position = net.center + net.across * a + net.up * u;
      const bool edge_column = crossings && (column == 0 || column == net.columns - 1);
      const bool edge_row = crossings && (row == 0 || row == net.rows - 1);
      // The outline area a knot carries: its cell, cut by the outline.
      const double outline_share = (edge_column ? 0.5 : 1.0) * (edge_row ? 0.5 : 1.0);
      k.screen_area = cell_area * outline_share;
      k.element_fraction = spec.edges == EdgeKnots::SolidityMatched ? outline_share : 1.0;
      k.geometry = scaled_knot(net.element, spec.knot_shape, k.element_fraction);
      projected += k.geometry.projected_area;
      const double netting_mass =
          spec.material_density * real_element_volume * lambda * lambda * k.element_fraction;
      net.netting_mass += netting_mass;
      k.mass = netting_mass;
      k.constant_force = env.gravity * netting_mass;
      const double netting_volume = netting_mass / spec.material_density;
      // Resolved knots: the fluid's pressure gives rho_w g V_resolved; the rest makes it the
      // netting's buoyancy (NetEnvironment::knot_buoyancy).
      const double buoyant_volume =
          env.knot_buoyancy ? netting_volume
                            : netting_volume - resolved_knot_volume(k.geometry, env.resolved_dp);
      k.constant_force -= env.gravity * (env.water_density * buoyant_volume);
      if (row == 0 && sinker.length > 0) {
        const double carried = (edge_column ? 0.5 : 1.0) * net.spacing_across;
        k.sinker_length = carried * sinker.length / spec.width;
        const double share = k.sinker_length / sinker.length;
        k.mass += net.sinker_mass * share;
        k.constant_force +=
            env.gravity * ((sinker.density - env.water_density) * sinker_volume * share);
      }
      k.fixed = on_fixed_edge(spec, row, column, net.rows, net.columns);
      net.knots.push_back(k);
    }
  }
  net.numerical_solidity = projected / (spec.width * spec.height);
  for (const NetPointLoad& load : spec.point_loads) {
    if (load.row < 0 || load.row >= net.rows || load.column < 0 || load.column >= net.columns) {
      throw Error(spec.where.str(),
                  fmt::format("net '{}': point load at row {}, column {} is outside the {} x {} "
                              "knots (rows 0..{}, columns 0..{})",
                              spec.name, load.row, load.column, net.rows, net.columns, net.rows - 1,
                              net.columns - 1));
    }
    net.knots[net.index(load.row, load.column)].constant_force += load.force;
  }

  // Twines. A numerical twine stands for lambda real twines in parallel, each strained as
  // much as it is, so its tension is lambda times the real twine's.
  TwineLaw law;
  if (spec.tension_law) {
    law = {(*spec.tension_law)[0], (*spec.tension_law)[1]};
  } else {
    const double ea = spec.axial_stiffness > 0 ? spec.axial_stiffness
                                               : spec.youngs_modulus * pi / 4 *
                                                     spec.twine_diameter * spec.twine_diameter;
    law = {ea, 0};
  }
  law.c1 *= lambda;
  law.c2 *= lambda;
  auto add_twine = [&](int a, int b, double rest) {
    NetTwine t;
    t.a = a;
    t.b = b;
    t.rest = rest;
    t.law = law;
    t.diameter = diameter;
    // Damping ratio zeta of the twine's axial mode with the two end masses (reduced mass;
    // an anchored end counts as infinitely heavy): c = 2 zeta sqrt(k m).
    const double m = twine_modal_mass(net.knots[a], net.knots[b]);
    t.damping = 2 * spec.damping_ratio * std::sqrt(law.c1 / rest * m);
    net.twines.push_back(t);
  };
  for (int row = 0; row < net.rows; ++row) {
    for (int column = 0; column < net.columns; ++column) {
      const int i = net.index(row, column);
      if (column + 1 < net.columns) add_twine(i, net.index(row, column + 1), net.spacing_across);
      if (row + 1 < net.rows) add_twine(i, net.index(row + 1, column), net.spacing_up);
    }
  }
  return net;
}

}  // namespace netsph
