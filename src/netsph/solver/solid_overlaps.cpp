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
  // Only walls near a body can overlap one: the bodies' box, a cell wider on each side.
  const double inf = std::numeric_limits<double>::infinity();
  Vec3d lo{inf, inf, inf}, hi{-inf, -inf, -inf};
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != ParticleKind::Body) continue;
    for (int a = 0; a < 3; ++a)
      lo[a] = std::min(lo[a], p.pos[i][a]), hi[a] = std::max(hi[a], p.pos[i][a]);
  }
  if (!(lo.x <= hi.x)) return out;  // no body
  const auto near_bodies = [&](const Vec3d& x) {
    for (int a = 0; a < 3; ++a)
      if (x[a] < lo[a] - dp || x[a] > hi[a] + dp) return false;
    return true;
  };
  const auto key_of = [&](const Vec3d& x) {
    return CellKey{static_cast<std::int64_t>(std::floor(x.x / dp)),
                   dims == 2 ? 0 : static_cast<std::int64_t>(std::floor(x.y / dp)),
                   static_cast<std::int64_t>(std::floor(x.z / dp))};
  };
  std::vector<std::pair<CellKey, std::uint32_t>> cells;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const bool solid = p.kind[i] == ParticleKind::Body ||
                       (p.kind[i] == ParticleKind::Wall && near_bodies(p.pos[i]));
    if (solid) cells.emplace_back(key_of(p.pos[i]), static_cast<std::uint32_t>(i));
  }
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
      out.push_back(fmt::format("... and {} more bodies overlap a wall or another body",
                                hits.size() - listed));
      break;
    }
    const auto worst =
        std::max_element(by_other.begin(), by_other.end(),
                         [](const auto& a, const auto& b) { return a.second < b.second; });
    std::size_t total = 0;
    for (const auto& [o, n] : by_other) total += n;
    const std::string what =
        worst->first < 0
            ? fmt::format("wall '{}'", wall_names.at(static_cast<std::size_t>(-1 - worst->first)))
            : fmt::format("body '{}'", body_names.at(static_cast<std::size_t>(worst->first)));
    out.push_back(fmt::format(
        "body '{}' starts inside {} ({} of its {} particles within dp/2 of its): set-up keeps "
        "a body where it is placed, so it will be held there or thrown out; move it clear",
        body_names.at(body), what, total, sizes[body]));
    ++listed;
  }
  return out;
}

}  // namespace netsph
