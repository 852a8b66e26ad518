#include "netsph/solver/solid_overlaps.hpp"

#include <algorithm>
#include <cstdint>
#include <map>

#include <fmt/format.h>

namespace netsph {

std::vector<std::string> solid_overlap_warnings(const ParticleSet& p,
                                                const HalfSpacingSearch& search,
                                                const CaseSpec& spec,
                                                const std::vector<RigidBody>& bodies) {
  // For each floating body: its particles that overlap, by the solid they overlap (walls as
  // -1 - wall index); and its particles.
  std::map<std::uint32_t, std::map<std::int64_t, std::size_t>> hits;
  std::map<std::uint32_t, std::size_t> sizes;
  for (std::uint32_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != ParticleKind::Body) continue;
    const std::uint32_t body = p.group[i];
    if (bodies.at(body).motion != BodyMotion::Floating) continue;
    ++sizes[body];
    const std::int64_t j = search.find(i, [&](std::uint32_t b) {
      return p.kind[b] == ParticleKind::Wall ||
             (p.kind[b] == ParticleKind::Body && p.group[b] != body);
    });
    if (j < 0) continue;
    const auto g = static_cast<std::int64_t>(p.group[static_cast<std::size_t>(j)]);
    ++hits[body][p.kind[static_cast<std::size_t>(j)] == ParticleKind::Wall ? -1 - g : g];
  }
  std::vector<std::string> out;
  std::size_t listed = 0;
  for (const auto& [body, by_other] : hits) {
    if (listed == kMaxListedOverlaps) {
      const std::size_t more = hits.size() - listed;
      out.push_back(fmt::format("... and {} more {} a wall or another body", more,
                                more == 1 ? "body overlaps" : "bodies overlap"));
      break;
    }
    const auto worst =
        std::max_element(by_other.begin(), by_other.end(),
                         [](const auto& a, const auto& b) { return a.second < b.second; });
    std::size_t total = 0;
    for (const auto& [o, count] : by_other) total += count;
    const bool wall = worst->first < 0;
    const std::string what =
        wall ? fmt::format("wall '{}'",
                           spec.walls.at(static_cast<std::size_t>(-1 - worst->first)).name)
             : fmt::format("body '{}'", bodies.at(static_cast<std::size_t>(worst->first)).name);
    out.push_back(fmt::format(
        "body '{}' starts inside {}: {} of its {} particles lie within dp/2 of that {}'s. Set-up "
        "keeps a body where it is placed, so it will be held there or thrown out: move it clear "
        "(a body thinner than 2 dp is resolved 2 dp thick about its centre)",
        bodies.at(body).name, what, total, sizes[body], wall ? "wall" : "body"));
    ++listed;
  }
  return out;
}

}  // namespace netsph
