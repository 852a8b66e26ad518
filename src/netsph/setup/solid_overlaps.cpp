#include "netsph/setup/solid_overlaps.hpp"

#include <algorithm>
#include <cstring>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

namespace netsph {

namespace {

// pack(): rows of (body, solid, count); a body's size is the row with this solid.
constexpr std::int64_t kSizeRow = std::numeric_limits<std::int64_t>::min();

}  // namespace

void SolidOverlaps::add(const SolidOverlaps& other) {
  for (const auto& [body, by_solid] : other.hits)
    for (const auto& [solid, count] : by_solid) hits[body][solid] += count;
  for (const auto& [body, count] : other.sizes) sizes[body] += count;
}

std::vector<std::byte> SolidOverlaps::pack() const {
  std::vector<std::int64_t> rows;
  const auto row = [&](std::uint32_t body, std::int64_t solid, std::size_t count) {
    rows.insert(rows.end(),
                {static_cast<std::int64_t>(body), solid, static_cast<std::int64_t>(count)});
  };
  for (const auto& [body, by_solid] : hits)
    for (const auto& [solid, count] : by_solid) row(body, solid, count);
  for (const auto& [body, count] : sizes) row(body, kSizeRow, count);
  std::vector<std::byte> bytes(rows.size() * sizeof(std::int64_t));
  if (!rows.empty()) std::memcpy(bytes.data(), rows.data(), bytes.size());
  return bytes;
}

SolidOverlaps SolidOverlaps::unpack(const std::vector<std::byte>& bytes) {
  constexpr std::size_t kRow = 3 * sizeof(std::int64_t);
  if (bytes.size() % kRow != 0)
    throw std::logic_error("SolidOverlaps::unpack: not a whole number of rows");
  SolidOverlaps o;
  for (std::size_t at = 0; at < bytes.size(); at += kRow) {
    std::int64_t r[3];
    std::memcpy(r, bytes.data() + at, kRow);
    const auto body = static_cast<std::uint32_t>(r[0]);
    const auto count = static_cast<std::size_t>(r[2]);
    if (r[1] == kSizeRow)
      o.sizes[body] += count;
    else
      o.hits[body][r[1]] += count;
  }
  return o;
}

SolidOverlaps find_solid_overlaps(const ParticleSet& p, const HalfSpacingSearch& search,
                                  const std::vector<RigidBody>& bodies,
                                  const std::function<bool(const Vec3d&)>& counted) {
  SolidOverlaps o;
  for (std::uint32_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != ParticleKind::Body) continue;
    const std::uint32_t body = p.group[i];
    if (bodies.at(body).motion != BodyMotion::Floating || !counted(p.pos[i])) continue;
    ++o.sizes[body];
    const std::int64_t j = search.find(i, [&](std::uint32_t b) {
      return p.kind[b] == ParticleKind::Wall ||
             (p.kind[b] == ParticleKind::Body && p.group[b] != body);
    });
    if (j < 0) continue;
    const auto g = static_cast<std::int64_t>(p.group[static_cast<std::size_t>(j)]);
    ++o.hits[body][p.kind[static_cast<std::size_t>(j)] == ParticleKind::Wall ? -1 - g : g];
  }
  return o;
}

std::vector<std::string> solid_overlap_warnings(const SolidOverlaps& overlaps, const CaseSpec& spec,
                                                const std::vector<RigidBody>& bodies) {
  std::vector<std::string> out;
  std::size_t listed = 0;
  for (const auto& [body, by_other] : overlaps.hits) {
    if (listed == kMaxListedOverlaps) {
      const std::size_t more = overlaps.hits.size() - listed;
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
        bodies.at(body).name, what, total, overlaps.sizes.at(body), wall ? "wall" : "body"));
    ++listed;
  }
  return out;
}

}  // namespace netsph
