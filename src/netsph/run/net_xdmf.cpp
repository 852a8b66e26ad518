#include "netsph/run/net_xdmf.hpp"

#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "netsph/io/atomic_file.hpp"

namespace netsph {
namespace {

// Each grid starts with this line, so that a restart can split the file it wrote.
constexpr const char* kGridMark = "   <!-- netsph net grid -->\n";

template <class Each>
std::string data_item(const std::string& dims, const char* type, int precision, Each&& each) {
  std::string s = fmt::format(
      "     <DataItem Dimensions=\"{}\" NumberType=\"{}\" Precision=\"{}\" Format=\"XML\">", dims,
      type, precision);
  each(s);
  return s + "</DataItem>\n";
}

}  // namespace

void NetXdmfSeries::add(const NetModel& net, const std::vector<Vec3d>& initial, double time) {
  name_ = net.name;
  const std::size_t nk = net.knots.size(), nt = net.twines.size();
  std::string g = kGridMark;
  g += fmt::format(
      "   <Grid Name=\"{}_{:06d}\" GridType=\"Uniform\">\n    <Time Value=\"{:.17g}\"/>\n",
      net.name, grids_.size(), time);
  g += fmt::format(
      "    <Topology TopologyType=\"Polyline\" NumberOfElements=\"{}\" "
      "NodesPerElement=\"2\">\n",
      nt);
  g += data_item(fmt::format("{} 2", nt), "Int", 4, [&](std::string& s) {
    for (const NetTwine& t : net.twines) s += fmt::format(" {} {}", t.a, t.b);
  });
  g += "    </Topology>\n    <Geometry GeometryType=\"XYZ\">\n";
  g += data_item(fmt::format("{} 3", nk), "Float", 8, [&](std::string& s) {
    for (const NetKnot& k : net.knots)
      s += fmt::format(" {:.9g} {:.9g} {:.9g}", k.position.x, k.position.y, k.position.z);
  });
  g += "    </Geometry>\n";
  g += "    <Attribute Name=\"tension\" AttributeType=\"Scalar\" Center=\"Cell\">\n";
  g += data_item(std::to_string(nt), "Float", 8, [&](std::string& s) {
    for (const NetTwine& t : net.twines)
      s += fmt::format(" {:.9g}", twine_tension(t.law, twine_strain(net, t)));
  });
  g += "    </Attribute>\n";
  g += "    <Attribute Name=\"displacement\" AttributeType=\"Vector\" Center=\"Node\">\n";
  g += data_item(fmt::format("{} 3", nk), "Float", 8, [&](std::string& s) {
    for (std::size_t i = 0; i < nk; ++i) {
      const Vec3d d = net.knots[i].position - initial[i];
      s += fmt::format(" {:.9g} {:.9g} {:.9g}", d.x, d.y, d.z);
    }
  });
  g += "    </Attribute>\n";
  g += "    <Attribute Name=\"velocity\" AttributeType=\"Vector\" Center=\"Node\">\n";
  g += data_item(fmt::format("{} 3", nk), "Float", 8, [&](std::string& s) {
    for (const NetKnot& k : net.knots)
      s += fmt::format(" {:.9g} {:.9g} {:.9g}", k.velocity.x, k.velocity.y, k.velocity.z);
  });
  g += "    </Attribute>\n";
  g += "    <Attribute Name=\"anchored\" AttributeType=\"Scalar\" Center=\"Node\">\n";
  g += data_item(std::to_string(nk), "Int", 4, [&](std::string& s) {
    for (const NetKnot& k : net.knots) s += k.fixed ? " 1" : " 0";
  });
  g += "    </Attribute>\n   </Grid>\n";
  grids_.push_back(std::move(g));
  rewrite();
}

void NetXdmfSeries::resume(std::size_t steps) {
  std::ifstream in(file_);
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  grids_.clear();
  const std::string mark = kGridMark;
  std::size_t at = s.find(mark);
  while (at != std::string::npos && grids_.size() < steps) {
    const std::size_t next = s.find(mark, at + mark.size());
    const std::size_t end = next != std::string::npos ? next : s.find("  </Grid>\n </Domain>", at);
    grids_.push_back(s.substr(at, end - at));
    at = next;
  }
  rewrite();
}

void NetXdmfSeries::rewrite() const {
  std::string s = "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n";
  s += fmt::format("  <Grid Name=\"{}\" GridType=\"Collection\" CollectionType=\"Temporal\">\n",
                   name_.empty() ? "net" : name_);
  for (const std::string& g : grids_) s += g;
  s += "  </Grid>\n </Domain>\n</Xdmf>\n";
  write_file_atomic(file_, s);
}

}  // namespace netsph
