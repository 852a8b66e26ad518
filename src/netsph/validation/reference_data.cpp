#include "netsph/validation/reference_data.hpp"

#include <string>

#include "netsph/core/error.hpp"

namespace netsph {

const std::vector<ElementDragReference>& table2_element_drag() {
  // Shi et al. 2024, Table 2 (SPH, dp = 0.005 m, domain 4 x 2 x 2 m, open inlet and outlet);
  // Cd = F / (0.5 rho U^2 A_projected), Re on each shape's characteristic size.
  static const std::vector<ElementDragReference> rows = {
      {"cruciform", 0.41, 2.05e4, 1.03, 3.34},       {"cruciform", 0.60, 3.0e4, 0.98, 7.56},
      {"cruciform", 0.80, 4.0e4, 0.97, 12.48},       {"cruciform", 1.01, 5.05e4, 0.94, 19.32},
      {"sphere", 0.41, 5.79e4, 0.58, 0.76},          {"sphere", 0.60, 8.47e4, 0.55, 1.55},
      {"sphere", 0.80, 1.12e5, 0.52, 2.60},          {"sphere", 1.01, 1.43e5, 0.51, 4.07},
      {"circular_plate", 0.41, 8.96e4, 1.21, 3.81},  {"circular_plate", 0.60, 1.31e5, 1.15, 7.76},
      {"circular_plate", 0.80, 1.75e5, 1.13, 13.56}, {"circular_plate", 1.01, 2.21e5, 1.10, 21.04},
      {"square_plate", 0.41, 7.94e4, 1.19, 3.75},    {"square_plate", 0.60, 1.16e5, 1.17, 7.90},
      {"square_plate", 0.80, 1.55e5, 1.11, 13.32},   {"square_plate", 1.01, 1.96e5, 1.08, 20.85}};
  return rows;
}

const std::vector<NetDragReference>& table3_bi2014_drag() {
  // Shi et al. 2024, Table 3: the 0.3 x 0.3 m knotless PE net of Bi et al. (2014), 15 x 15
  // meshes, top on a fixed bar, 0.3 m x 6 mm steel sinker bar (8610 kg/m^3).
  static const std::vector<NetDragReference> rows = {{0.17, 0.567, 0.596, 0.624},
                                                     {0.226, 0.918, 0.912, 0.985}};
  return rows;
}

const std::vector<StatedFigure>& stated_figures() {
  static const std::vector<StatedFigure> figures = {
      // 3.1.2: the 5 x 5-twine panel (0.1 x 0.1 m, l0 = 2 cm, d0 = 0.35 cm) at 0.5 m/s.
      {"panel5_twine_drag", 0.6, "N", "Shi et al. 2024, 3.1.2 (Figure 9)",
       "drag on the panel of cruciform twines, about"},
      {"panel5_twine_cd", 0.48, "", "Shi et al. 2024, 3.1.2",
       "Cd of the twine panel on its outline area"},
      {"panel5_plate_ratio", 1.45, "", "Shi et al. 2024, 3.1.2",
       "drag of the plate-knot panels over the twine panel, about"},
      {"panel5_numerical_solidity", 0.46, "", "Shi et al. 2024, 3.1.2",
       "36 square knots of 11.3 mm over the 0.1 x 0.1 m outline"},
      // 3.2: the rigid net of Patursson et al. (2010), mesh grouping 3.45.
      {"rigid_cd_over_experiment_low", 1.2, "", "Shi et al. 2024, 3.2.2",
       "computed Cd over the experiment's, lower end (121 knots, Sn 1.21 x real)"},
      {"rigid_cd_over_experiment_high", 1.3, "", "Shi et al. 2024, 3.2.2",
       "computed Cd over the experiment's, upper end"},
      {"rigid_centreline_reduction", 0.20, "", "Shi et al. 2024, 3.2.2 (Figure 13)",
       "velocity reduction behind the rigid net at 90 deg, 0.25 m/s, about"},
      {"rigid_numerical_solidity", 0.223, "", "Shi et al. 2024, 3.2.1",
       "121 knots of 42.89 mm over the 1 x 1 m outline"},
      // 3.3: the flexible net of Bi et al. (2014).
      {"bi_reduction_low", 0.10, "", "Shi et al. 2024, 3.3.2 (Figure 19)",
       "velocity reduction behind the net on the centreline, lower end"},
      {"bi_reduction_high", 0.15, "", "Shi et al. 2024, 3.3.2 (Figure 19)",
       "velocity reduction behind the net on the centreline, upper end"},
      {"bi_numerical_solidity", 0.258, "", "Shi et al. 2024, 3.3.1",
       "225 knots of 10.19 mm over the 0.3 x 0.3 m outline"},
      // 3.4: two flexible nets 0.3 m apart.
      {"two_nets_reduction_per_net", 0.13, "", "Shi et al. 2024, 3.4.2",
       "velocity reduction across each net, about"},
      {"two_nets_max_reduction_0226", 0.263, "", "Shi et al. 2024, 3.4.2",
       "largest velocity reduction downstream at 0.226 m/s"},
      {"two_nets_max_reduction_017", 0.275, "", "Shi et al. 2024, 3.4.2",
       "largest velocity reduction downstream at 0.17 m/s"},
  };
  return figures;
}

const StatedFigure& stated_figure(std::string_view key) {
  for (const StatedFigure& f : stated_figures())
    if (f.key == key) return f;
  throw Error("validation", "no stated figure named '" + std::string(key) + "'");
}

}  // namespace netsph
