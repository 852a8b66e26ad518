#include "netsph/app/run_results.hpp"

#include <spdlog/spdlog.h>

namespace netsph::app {
namespace {

std::string window_text(const nlohmann::json& j) {
  if (!j.contains("window_s")) return "";
  return fmt::format("{:.3g}-{:.3g} s", j["window_s"][0].get<double>(),
                     j["window_s"][1].get<double>());
}

}  // namespace

void log_run_results(const nlohmann::json& summary) {
  for (const auto& g : summary.value("bodies", nlohmann::json::array())) {
    if (!g.contains("force_N")) continue;
    const auto& f = g["force_N"];
    // 2D: per metre of depth, and the reference area is a length.
    const std::string unit = g.value("force_unit", "N");
    const bool per_metre = unit == "N/m";
    std::string cd;
    if (g.contains("cd")) {
      cd = fmt::format(", Cd {:.4f} (U = {:.4g} m/s, A = {:.4g} {})", g["cd"].get<double>(),
                       g["reference_velocity_m_s"].get<double>(), g["reference_area"].get<double>(),
                       per_metre ? "m" : "m^2");
    }
    spdlog::info("{} over {}: drag {:.4g} {} (force [{:.4g}, {:.4g}, {:.4g}] {}){}",
                 g["group"].get<std::string>(), window_text(g), f[0].get<double>(), unit,
                 f[0].get<double>(), f[1].get<double>(), f[2].get<double>(), unit, cd);
  }
  for (const auto& n : summary.value("nets", nlohmann::json::array())) {
    if (n.contains("mean_sinker_drag_N")) {
      const auto& f = n["mean_sinker_drag_N"];
      spdlog::info(
          "net {}: its sinker bar's drag over {} (modelled at the sampled flow, included in the "
          "net's force) [{:.4g}, {:.4g}, {:.4g}] N",
          n["name"].get<std::string>(), window_text(n), f[0].get<double>(), f[1].get<double>(),
          f[2].get<double>());
    }
    const auto& b = n["final_bottom_displacement_m"];
    // No means when no step fell in the window (a warning says so): no zeros in their place.
    const bool means = n.contains("mean_max_deflection_m");
    spdlog::info(
        "net {}: largest deflection along its normal {}{:.4g} m at the end; bottom edge moved "
        "[{:.3g}, {:.3g}, {:.3g}] m{}",
        n["name"].get<std::string>(),
        means ? fmt::format("{:.4g} m (mean over {}), ", n["mean_max_deflection_m"].get<double>(),
                            window_text(n))
              : std::string(),
        n["final_max_deflection_m"].get<double>(), b[0].get<double>(), b[1].get<double>(),
        b[2].get<double>(),
        means
            ? fmt::format("; largest twine tension {:.4g} N", n["mean_max_tension_N"].get<double>())
            : std::string());
  }
  for (const auto& p : summary.value("probes", nlohmann::json::array())) {
    const std::string name = p["name"].get<std::string>();
    if (p.contains("mean_velocity_m_s")) {
      const auto& u = p["mean_velocity_m_s"];
      std::string reduction;
      if (p.contains("velocity_reduction"))
        reduction =
            fmt::format(", {:.1f}% below the inflow", 100 * p["velocity_reduction"].get<double>());
      spdlog::info("probe {} over {}: mean velocity [{:.4g}, {:.4g}, {:.4g}] m/s{}", name,
                   window_text(p), u[0].get<double>(), u[1].get<double>(), u[2].get<double>(),
                   reduction);
    } else if (p.contains("mean_velocity_reduction")) {
      spdlog::info(
          "probe {} over {}: mean streamwise velocity over the plane {:.4g} m/s, {:.1f}% "
          "below the inflow",
          name, window_text(p), p["mean_ux_m_s"].get<double>(),
          100 * p["mean_velocity_reduction"].get<double>());
    } else if (p.contains("largest_velocity_reduction")) {
      const auto& x = p["largest_reduction_at_m"];
      spdlog::info(
          "probe {} over {}: flow slowed by up to {:.1f}% (at [{:.3g}, {:.3g}, {:.3g}] m); "
          "profile in {}",
          name, window_text(p), 100 * p["largest_velocity_reduction"].get<double>(),
          x[0].get<double>(), x[1].get<double>(), x[2].get<double>(),
          p["mean_file"].get<std::string>());
    }
  }
  for (const auto& g : summary.value("gauges", nlohmann::json::array())) {
    const nlohmann::json& m = g["measured"];
    const auto& window = g["window_s"];
    if (m["waves"].get<int>() == 0) {
      spdlog::info("gauge {} over {:.4g}-{:.4g} s: {}", g["name"].get<std::string>(),
                   window[0].get<double>(), window[1].get<double>(),
                   g.value("note", std::string("no complete wave")));
      continue;
    }
    std::string target;
    if (g.contains("height_ratio")) {
      target = fmt::format(" ({:.3f} and {:.4f} of the target)", g["height_ratio"].get<double>(),
                           g["period_ratio"].get<double>());
    }
    spdlog::info(
        "gauge {} over {:.4g}-{:.4g} s: {} waves, mean height {:.4g} m, mean period "
        "{:.4g} s{}",
        g["name"].get<std::string>(), window[0].get<double>(), window[1].get<double>(),
        m["waves"].get<int>(), m["mean_height_m"].get<double>(), m["mean_period_s"].get<double>(),
        target);
  }
}

}  // namespace netsph::app
