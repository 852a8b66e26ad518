#include "netsph/solver/solid_overlaps.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <tuple>
#include <utility>

#include <fmt/format.h>

namespace netsph {

namespace {

/// A solid particle's cell of size dp (x fastest), for the sorted search below.
struct CellKey {
  std::int64_t x, y, z;
  friend bool operator<(const CellKey& a, const CellKey& b) {
    return std::tie(a.z, a.y, a.x) < std::tie(b.z, b.y, b.x);
  }
  friend bool operator==(const CellKey& a, const CellKey& b) {
    return a.x == b.x && a.y == b.y && a.z == b.z;
  }
};

}  // namespace

std::vector<std::string> solid_overlap_warnings(const ParticleSet& p, double dp, int dims,
                                                const std::vector<std::string>& wall_names,
                                                const std::vector<std::string>& body_names,
                                                const std::vector<bool>& body_moves) {
  std::vector<std::string> out;
  const auto key_of = [&](const Vec3d& x) {
    return CellKey{static_cast<std::int64_t>(std::floor(x.x / dp)),
                   dims == 2 ? 0 : static_cast<std::int64_t>(std::floor(x.y / dp)),
                   static_cast<std::int64_t>(std::floor(x.z / dp))};
  };
  // Only walls in a cell next to a moving body's can overlap one: those cells, sorted (a few
  // times the bodies' particles; a set of boxes would take in every wall between two bodies
  // far apart, or across a period for a body cut by a periodic face).
  std::vector<CellKey> near;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != ParticleKind::Body || !body_moves.at(p.group[i])) continue;
    const CellKey k = key_of(p.pos[i]);
    for (std::int64_t dz = -1; dz <= 1; ++dz)
      for (std::int64_t dy = dims == 2 ? 0 : -1; dy <= (dims == 2 ? 0 : 1); ++dy)
        for (std::int64_t dx = -1; dx <= 1; ++dx) near.push_back({k.x + dx, k.y + dy, k.z + dz});
  }
  if (near.empty()) return out;
  std::sort(near.begin(), near.end());
  near.erase(std::unique(near.begin(), near.end()), near.end());
  const auto n = static_cast<std::int64_t>(p.size());
  std::vector<char> take(p.size(), 0);
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    const auto k = p.kind[static_cast<std::size_t>(i)];
    if (k == ParticleKind::Body || k == ParticleKind::Wall)
      take[static_cast<std::size_t>(i)] =
          std::binary_search(near.begin(), near.end(), key_of(p.pos[static_cast<std::size_t>(i)]));
  }
  std::vector<std::pair<CellKey, std::uint32_t>> cells;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (take[i]) cells.emplace_back(key_of(p.pos[i]), static_cast<std::uint32_t>(i));
  std::sort(cells.begin(), cells.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  // For each body: its particles that overlap, by the solid they overlap (walls as ~g).
  std::map<std::uint32_t, std::map<std::int64_t, std::size_t>> hits;
  std::map<std::uint32_t, std::size_t> sizes;
  const double tol2 = 0.25 * dp * dp;
  for (const auto& [key, i] : cells) {
    if (p.kind[i] != ParticleKind::Body || !body_moves.at(p.group[i])) continue;
    const std::uint32_t body = p.group[i];
    ++sizes[body];
    std::int64_t other = std::numeric_limits<std::int64_t>::min();
    for (std::int64_t dz = -1; dz <= 1 && other == std::numeric_limits<std::int64_t>::min(); ++dz)
      for (std::int64_t dy = dims == 2 ? 0 : -1; dy <= (dims == 2 ? 0 : 1); ++dy)
        for (std::int64_t dx = -1; dx <= 1; ++dx) {
          const CellKey k{key.x + dx, key.y + dy, key.z + dz};
          auto it = std::lower_bound(cells.begin(), cells.end(), k,
                                     [](const auto& e, const CellKey& c) { return e.first < c; });
          for (; it != cells.end() && it->first == k; ++it) {
            const std::uint32_t j = it->second;
            const bool same = p.kind[j] == ParticleKind::Body && p.group[j] == body;
            if (same || !(norm2(p.pos[i] - p.pos[j]) < tol2)) continue;
            other = p.kind[j] == ParticleKind::Wall ? -1 - static_cast<std::int64_t>(p.group[j])
                                                    : static_cast<std::int64_t>(p.group[j]);
          }
        }
    if (other != std::numeric_limits<std::int64_t>::min()) ++hits[body][other];
  }
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
    const std::string what =
        worst->first < 0
            ? fmt::format("wall '{}'", wall_names.at(static_cast<std::size_t>(-1 - worst->first)))
            : fmt::format("body '{}'", body_names.at(static_cast<std::size_t>(worst->first)));
    out.push_back(fmt::format(
        "body '{}' starts inside {}: {} of its {} particles lie within dp/2 of that {}'s. Set-up "
        "keeps a body where it is placed, so it will be held there or thrown out: move it clear "
        "(a body thinner than 2 dp is resolved 2 dp thick about its centre)",
        body_names.at(body), what, total, sizes[body], worst->first < 0 ? "wall" : "body"));
    ++listed;
  }
  return out;
}

}  // namespace netsph
