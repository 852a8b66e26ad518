#include "netsph/geometry/box_bins.hpp"

#include <algorithm>
#include <cmath>

namespace netsph {

BoxBins::BoxBins(std::span<const Aabb> boxes) {
  if (boxes.empty()) return;
  all_ = boxes[0];
  double volume = 0;
  for (const Aabb& b : boxes) {
    for (int a = 0; a < 3; ++a) {
      all_.lo[a] = std::min(all_.lo[a], b.lo[a]);
      all_.hi[a] = std::max(all_.hi[a], b.hi[a]);
    }
    const Vec3d e = b.hi - b.lo;
    volume += std::max(e.x, 1e-12) * std::max(e.y, 1e-12) * std::max(e.z, 1e-12);
  }
  const Vec3d span = all_.hi - all_.lo;
  const double largest = std::max({span.x, span.y, span.z, 1e-12});
  // A bin about half a mean box across; no more than about 2e6 bins; at least 1/128 of the
  // largest extent.
  bin_ = std::max(0.5 * std::cbrt(volume / static_cast<double>(boxes.size())), largest / 128);
  for (;;) {
    for (int a = 0; a < 3; ++a)
      n_[a] = std::max<std::int64_t>(1, static_cast<std::int64_t>(std::ceil(span[a] / bin_)));
    if (n_[0] * n_[1] * n_[2] <= (std::int64_t{1} << 21)) break;
    bin_ *= 1.25;
  }
  const auto index_range = [&](const Aabb& b, int a) {
    const auto lo = static_cast<std::int64_t>(std::floor((b.lo[a] - all_.lo[a]) / bin_));
    const auto hi = static_cast<std::int64_t>(std::floor((b.hi[a] - all_.lo[a]) / bin_));
    return std::pair{std::clamp<std::int64_t>(lo, 0, n_[a] - 1),
                     std::clamp<std::int64_t>(hi, 0, n_[a] - 1)};
  };
  // Counting sort of (bin, box) pairs: count, prefix sum, fill.
  const std::int64_t bins = n_[0] * n_[1] * n_[2];
  std::vector<std::uint32_t> count(static_cast<std::size_t>(bins) + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    for (std::uint32_t k = 0; k < boxes.size(); ++k) {
      const auto [x0, x1] = index_range(boxes[k], 0);
      const auto [y0, y1] = index_range(boxes[k], 1);
      const auto [z0, z1] = index_range(boxes[k], 2);
      for (std::int64_t z = z0; z <= z1; ++z)
        for (std::int64_t y = y0; y <= y1; ++y)
          for (std::int64_t x = x0; x <= x1; ++x) {
            const auto c = static_cast<std::size_t>((z * n_[1] + y) * n_[0] + x);
            if (pass == 0)
              ++count[c + 1];
            else
              items_[start_[c] + count[c]++] = k;
          }
    }
    if (pass == 0) {
      for (std::size_t c = 1; c < count.size(); ++c) count[c] += count[c - 1];
      start_ = count;
      items_.resize(start_.back());
      std::fill(count.begin(), count.end(), 0);
    }
  }
}

std::span<const std::uint32_t> BoxBins::candidates(const Vec3d& x) const {
  if (start_.empty() || !all_.contains(x)) return {};
  std::int64_t i[3];
  for (int a = 0; a < 3; ++a)
    i[a] = std::min(n_[a] - 1, static_cast<std::int64_t>((x[a] - all_.lo[a]) / bin_));
  const auto c = static_cast<std::size_t>((i[2] * n_[1] + i[1]) * n_[0] + i[0]);
  return {items_.data() + start_[c], items_.data() + start_[c + 1]};
}

}  // namespace netsph
