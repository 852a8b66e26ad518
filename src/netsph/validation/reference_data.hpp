#pragma once
// The numbers netsph is validated against, with their sources: Shi et al. (2024, Front. Mar.
// Sci. 11:1365857), its Tables 1-3 and the figures it states in sections 3.1-3.4, and the
// experiments it compares with (Bi et al. 2014; Patursson et al. 2010). Copied into the
// project (from the planning notes' reference/data folder) so that netsph never reads
// anything outside itself at run time. Every entry names where it comes from.
#include <optional>
#include <string_view>
#include <vector>

namespace netsph {

/// Table 2: drag of a single element in a uniform current (paper SPH, dp = 5 mm).
struct ElementDragReference {
  std::string_view shape;  ///< "cruciform", "sphere", "circular_plate", "square_plate"
  double velocity;         ///< m/s
  double reynolds;
  double cd;
  double drag;  ///< N
};
const std::vector<ElementDragReference>& table2_element_drag();

/// Table 3: drag on the single flexible net of Bi et al. (2014).
struct NetDragReference {
  double velocity;     ///< m/s
  double experiment;   ///< N, Bi et al. (2014)
  double bi_model;     ///< N, Bi et al.'s lumped-mass simulation
  double shi_sph;      ///< N, Shi et al. (2024)
};
const std::vector<NetDragReference>& table3_bi2014_drag();

/// A single figure the paper states in its text, with the sentence's place.
struct StatedFigure {
  std::string_view key;      ///< how the validation refers to it
  double value;
  std::string_view unit;     ///< "" for ratios
  std::string_view source;   ///< "Shi et al. 2024, 3.2.2"
  std::string_view meaning;  ///< what the number is
};
const std::vector<StatedFigure>& stated_figures();
/// The stated figure with this key (throws netsph::Error when there is none).
const StatedFigure& stated_figure(std::string_view key);

}  // namespace netsph
