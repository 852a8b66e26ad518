#pragma once
// Net outputs that open in ParaView and in a spreadsheet:
//  - net_NNNN.vtk (legacy VTK polydata: knots as points, twines as lines with their tension)
//    and net.vtk.series (ParaView's JSON file series, one entry per snapshot with its time);
//  - knots.csv: every knot's row, column, position, displacement, mass and whether anchored;
//  - profile.csv: the deflection of the mid-width column (the paper's Figure 16 view).
#include <filesystem>
#include <string>
#include <vector>

#include "netsph/net/net_model.hpp"

namespace netsph {

/// Writes one VTK snapshot of `net`; `initial` holds the undeformed knot positions.
void write_net_vtk(const std::filesystem::path& file, const NetModel& net,
                   const std::vector<Vec3d>& initial);

/// A growing list of (file, time) for ParaView, rewritten after every snapshot.
class NetVtkSeries {
 public:
  explicit NetVtkSeries(std::filesystem::path series_file) : file_(std::move(series_file)) {}
  void add(const std::string& name, double time);
  /// A restarted run: the entries up to its checkpoint, written out again.
  void reset(std::vector<std::pair<std::string, double>> entries);

 private:
  std::filesystem::path file_;
  void rewrite() const;
  std::vector<std::pair<std::string, double>> entries_;
};

void write_knots_csv(const std::filesystem::path& file, const NetModel& net,
                     const std::vector<Vec3d>& initial);
/// Mid-width column (the middle column, or the two middle columns averaged), bottom to top:
/// height above the outline's bottom, displacement along the normal and along up.
void write_profile_csv(const std::filesystem::path& file, const NetModel& net,
                       const std::vector<Vec3d>& initial);

/// Largest displacement of any knot along the net's normal, m.
double max_normal_deflection(const NetModel& net, const std::vector<Vec3d>& initial);

}  // namespace netsph
