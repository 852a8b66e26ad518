// `netsph net CASE`: the net generator's report for every [[net]] of a case (knots, twines,
// knot size and mass, numerical and real solidity) and the undeformed nets as VTK files for
// ParaView.
#include <filesystem>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "netsph/app/commands.hpp"
#include "netsph/core/error.hpp"
#include "netsph/io/output_folder.hpp"
#include "netsph/net/knot_spring_solver.hpp"
#include "netsph/net/net_generator.hpp"
#include "netsph/run/net_output.hpp"

namespace netsph::app {

int net_command(const NetArgs& args) {
  const CaseSpec spec = load_case(args.case_choice);
  if (spec.nets.empty()) {
    throw Error(spec.source, "the case has no [[net]] table; `netsph net` reports on nets");
  }
  const std::filesystem::path out = args.out_dir.empty()
                                        ? std::filesystem::path("out") / spec.simulation.name
                                        : std::filesystem::path(args.out_dir);
  create_output_folder(out, "-o");
  const NetEnvironment env = net_environment(spec);
  for (const NetSpec& ns : spec.nets) {
    NetModel net = generate_net(ns, env);
    const double l = ns.mesh_grouping * ns.twine_length;
    const double d = ns.mesh_grouping * ns.twine_diameter;
    int anchored = 0;
    double smallest = 1e300;
    for (const NetKnot& k : net.knots) {
      anchored += k.fixed ? 1 : 0;
      smallest = std::min(smallest, k.geometry.size);
    }
    fmt::print("net '{}' ({})\n", ns.name, ns.where.str());
    fmt::print("  outline            {} x {} m, centre {}, normal [{:.4g}, {:.4g}, {:.4g}]\n",
               ns.width, ns.height,
               fmt::format("[{:.4g}, {:.4g}, {:.4g}]", ns.center.x, ns.center.y, ns.center.z),
               net.normal.x, net.normal.y, net.normal.z);
    fmt::print("  real twine         l0 = {:.4g} mm, d0 = {:.4g} mm, {}, {} kg/m^3\n",
               ns.twine_length * 1e3, ns.twine_diameter * 1e3, ns.material, ns.material_density);
    fmt::print("  mesh grouping      lambda = {:.4g}: numerical twine {:.4g} mm x {:.4g} mm\n",
               ns.mesh_grouping, l * 1e3, d * 1e3);
    fmt::print("  knots              {} ({} x {}, {} layout), {} anchored\n", net.knots.size(),
               net.columns, net.rows, name_of(ns.layout), anchored);
    fmt::print("  twines             {}, rest length {:.4g} x {:.4g} mm\n", net.twines.size(),
               net.spacing_across * 1e3, net.spacing_up * 1e3);
    fmt::print("  equivalent knot    {} (rule \"{}\"): element A = {:.4g} mm^2, V = {:.4g} mm^3\n",
               name_of(ns.knot_shape), name_of(ns.equivalent_knot), net.element.area * 1e6,
               net.element.volume * 1e9);
    if (ns.knot_shape == KnotShape::Sphere) {
      fmt::print("                     diameter {:.4g} mm\n", net.knot.size * 1e3);
    } else {
      fmt::print("                     {} {:.4g} mm, thickness {:.4g} mm\n",
                 ns.knot_shape == KnotShape::SquarePlate ? "side" : "diameter", net.knot.size * 1e3,
                 net.knot.thickness * 1e3);
    }
    if (ns.edges == EdgeKnots::SolidityMatched) {
      fmt::print(
          "  edges              solidity-matched: edge knots 1/2, corner knots 1/4 of an "
          "element (smallest knot {:.4g} mm)\n",
          smallest * 1e3);
    } else {
      fmt::print("  edges              full: every knot a whole element\n");
    }
    fmt::print(
        "  solidity           numerical {:.4f}, real 2d/l - (d/l)^2 = {:.4f} (ratio {:.3f})\n",
        net.numerical_solidity, net.real_solidity, net.numerical_solidity / net.real_solidity);
    const double interior_mass = net.knots[net.index(net.rows / 2, net.columns / 2)].mass;
    fmt::print(
        "  mass               netting {:.4g} kg (interior knot {:.4g} g), sinker {:.4g} kg\n",
        net.netting_mass, interior_mass * 1e3, net.sinker_mass);
    // A net whose outline holds one numerical mesh has one knot and no twine to report.
    if (net.twines.empty()) {
      fmt::print("  twine law          no twines: the outline holds a single knot\n");
    } else {
      const NetTwine& t = net.twines.front();
      fmt::print(
          "  twine law          T = {:.4g} eps + {:.4g} eps^2 N per numerical twine; "
          "damping ratio {}\n",
          t.law.c1, t.law.c2, ns.damping_ratio);
      KnotSpringSolver solver(net);
      fmt::print("  stable sub-step    {:.3g} s (velocity Verlet, sub-cycled)\n",
                 solver.stable_step());
    }
    std::vector<Vec3d> initial;
    for (const NetKnot& k : net.knots) initial.push_back(k.position);
    const auto file = out / fmt::format("net_{}.vtk", ns.name);
    write_net_vtk(file, net, initial);
    write_knots_csv(out / fmt::format("knots_{}.csv", ns.name), net, initial);
    fmt::print("  written            {}\n", file.string());
  }
  return 0;
}

}  // namespace netsph::app
