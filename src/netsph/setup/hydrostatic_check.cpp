#include "netsph/setup/hydrostatic_check.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace netsph {

std::vector<std::string> hydrostatic_warnings(const CaseSpec& spec, double water_top,
                                              double water_bottom) {
  std::vector<std::string> out;
  if (spec.fills.empty()) return out;
  // Heights within a kernel support of the water are lattice detail, not a mistake.
  const double margin = 2 * spec.simulation.h_over_dp * spec.simulation.dp;
  const double g = std::fabs(spec.fluid.gravity.z);
  const auto head = [&](const std::string& what, double surface) {
    const double above = surface - water_top;
    if (!(g > 0) || !(above > margin)) return;
    out.push_back(fmt::format(
        "{} = {:.4g} m lies {:.3g} m above the highest water ({:.4g} m): the water "
        "starts under that head ({:.3g} kPa) and, unless a lid holds it, springs up. Leave "
        "surface_z out for a free surface at the water's top",
        what, surface, above, water_top, spec.fluid.density * g * above / 1e3));
  };
  for (std::size_t i = 0; i < spec.fills.size(); ++i) {
    if (spec.fills[i].surface_z)
      head(fmt::format("fill[{}].surface_z", i + 1), *spec.fills[i].surface_z);
  }
  const auto open = [&](const OpenBoundarySpec& o, const char* kind) {
    const std::string what = fmt::format("{} '{}'", kind, o.name);
    // The head matters only where the buffer's density is hydrostatic; an inlet also creates
    // no particle above its surface, whatever its density.
    if (o.surface_z && o.density == BufferDensity::Hydrostatic)
      head(what + ": surface_z", *o.surface_z);
    if (o.surface_z && std::string(kind) == "inlet" && *o.surface_z < water_bottom) {
      out.push_back(fmt::format(
          "{}: surface_z = {:.4g} m lies below the water's bottom ({:.4g} m): the inlet creates "
          "no particle above its surface, so none at all",
          what, *o.surface_z, water_bottom));
    }
    if (!o.profile_z.empty()) {
      const auto [lo, hi] = std::minmax_element(o.profile_z.begin(), o.profile_z.end());
      if (*lo > water_top || *hi < water_bottom) {
        const double u = *lo > water_top ? o.profile_u.front() : o.profile_u.back();
        out.push_back(fmt::format(
            "{}: its profile covers z = {:.4g} to {:.4g} m, wholly outside the water ({:.4g} to "
            "{:.4g} m): the whole inflow takes its end value, {:.3g} m/s",
            what, *lo, *hi, water_bottom, water_top, u));
      }
    }
  };
  for (const OpenBoundarySpec& o : spec.inlets) open(o, "inlet");
  for (const OpenBoundarySpec& o : spec.outlets) open(o, "outlet");
  return out;
}

}  // namespace netsph
