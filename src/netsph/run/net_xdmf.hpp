#pragma once
// A net's shapes over time as one XDMF 3 file for ParaView, <net>.xdmf next to the particles'
// particles.xdmf: a temporal collection with one grid per snapshot, the knots as the points
// and the twines as two-node polylines, with each twine's tension (cell data) and each knot's
// displacement, velocity and anchoring (point data). The data are inline XML: a net has tens to
// hundreds of knots, so one small file serves the whole run. The file is rewritten atomically
// after every snapshot. (The same shapes also go to <net>.vtk.series with one legacy VTK file
// per snapshot, for tools that read those.)
#include <filesystem>
#include <string>
#include <vector>

#include "netsph/net/net_model.hpp"

namespace netsph {

class NetXdmfSeries {
 public:
  explicit NetXdmfSeries(std::filesystem::path file)
      : file_(std::move(file)), name_(file_.stem().string()) {}
  /// Adds the net's present shape at `time` and rewrites the file.
  void add(const NetModel& net, const std::vector<Vec3d>& initial, double time);
  /// A restarted run: keeps the first `steps` grids of the file a previous run wrote.
  void resume(std::size_t steps);
  std::size_t size() const { return grids_.size(); }

 private:
  void rewrite() const;
  std::filesystem::path file_;
  std::string name_;
  std::vector<std::string> grids_;  ///< the XML of each time's grid
};

}  // namespace netsph
