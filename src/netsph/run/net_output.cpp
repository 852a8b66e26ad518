#include "netsph/run/net_output.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "netsph/io/atomic_file.hpp"

namespace netsph {

void write_net_vtk(const std::filesystem::path& file, const NetModel& net,
                   const std::vector<Vec3d>& initial) {
  std::string s =
      fmt::format("# vtk DataFile Version 3.0\nnetsph net {}\nASCII\nDATASET POLYDATA\n", net.name);
  s += fmt::format("POINTS {} double\n", net.knots.size());
  for (const NetKnot& k : net.knots) {
    s += fmt::format("{:.9g} {:.9g} {:.9g}\n", k.position.x, k.position.y, k.position.z);
  }
  s += fmt::format("LINES {} {}\n", net.twines.size(), 3 * net.twines.size());
  for (const NetTwine& t : net.twines) s += fmt::format("2 {} {}\n", t.a, t.b);
  s += fmt::format("POINT_DATA {}\n", net.knots.size());
  s += "VECTORS displacement double\n";
  for (std::size_t i = 0; i < net.knots.size(); ++i) {
    const Vec3d d = net.knots[i].position - initial[i];
    s += fmt::format("{:.9g} {:.9g} {:.9g}\n", d.x, d.y, d.z);
  }
  s += "VECTORS velocity double\n";
  for (const NetKnot& k : net.knots) {
    s += fmt::format("{:.9g} {:.9g} {:.9g}\n", k.velocity.x, k.velocity.y, k.velocity.z);
  }
  s += "SCALARS mass double 1\nLOOKUP_TABLE default\n";
  for (const NetKnot& k : net.knots) s += fmt::format("{:.9g}\n", k.mass);
  s += "SCALARS anchored int 1\nLOOKUP_TABLE default\n";
  for (const NetKnot& k : net.knots) s += k.fixed ? "1\n" : "0\n";
  s += fmt::format("CELL_DATA {}\nSCALARS tension double 1\nLOOKUP_TABLE default\n",
                   net.twines.size());
  for (const NetTwine& t : net.twines) {
    s += fmt::format("{:.9g}\n", twine_tension(t.law, twine_strain(net, t)));
  }
  write_file_atomic(file, s);
}

void NetVtkSeries::add(const std::string& name, double time) {
  entries_.emplace_back(name, time);
  rewrite();
}

void NetVtkSeries::reset(std::vector<std::pair<std::string, double>> entries) {
  entries_ = std::move(entries);
  rewrite();
}

void NetVtkSeries::rewrite() const {
  nlohmann::json j;
  j["file-series-version"] = "1.0";
  j["files"] = nlohmann::json::array();
  for (const auto& [n, t] : entries_) j["files"].push_back({{"name", n}, {"time", t}});
  write_file_atomic(file_, j.dump(1) + "\n");
}

void write_knots_csv(const std::filesystem::path& file, const NetModel& net,
                     const std::vector<Vec3d>& initial) {
  std::string s =
      "row,column,x [m],y [m],z [m],dx [m],dy [m],dz [m],vx [m/s],vy [m/s],vz [m/s],mass [kg],"
      "anchored\n";
  for (std::size_t i = 0; i < net.knots.size(); ++i) {
    const NetKnot& k = net.knots[i];
    const Vec3d d = k.position - initial[i];
    s += fmt::format(
        "{},{},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{}\n", k.row,
        k.column, k.position.x, k.position.y, k.position.z, d.x, d.y, d.z, k.velocity.x,
        k.velocity.y, k.velocity.z, k.mass, k.fixed ? 1 : 0);
  }
  write_file_atomic(file, s);
}

void write_profile_csv(const std::filesystem::path& file, const NetModel& net,
                       const std::vector<Vec3d>& initial) {
  const int left = (net.columns - 1) / 2;
  const int right = net.columns / 2;
  std::string s = "row,height [m],normal_displacement [m],up_displacement [m],x [m],y [m],z [m]\n";
  for (int row = 0; row < net.rows; ++row) {
    const int a = net.index(row, left), b = net.index(row, right);
    const Vec3d p = (net.knots[a].position + net.knots[b].position) * 0.5;
    const Vec3d p0 = (initial[a] + initial[b]) * 0.5;
    const Vec3d d = p - p0;
    const double height = dot(p0 - net.center, net.up) + net.height / 2;
    s += fmt::format("{},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}\n", row, height,
                     dot(d, net.normal), dot(d, net.up), p.x, p.y, p.z);
  }
  write_file_atomic(file, s);
}

double max_normal_deflection(const NetModel& net, const std::vector<Vec3d>& initial) {
  double m = 0;
  for (std::size_t i = 0; i < net.knots.size(); ++i) {
    m = std::max(m, std::abs(dot(net.knots[i].position - initial[i], net.normal)));
  }
  return m;
}

}  // namespace netsph
