// The CPU fluid pass's candidate scan (backend/cpu/neighbour_batch.hpp): every candidate within
// the support and no other, in index order, with the r^2 the pair loop needs and the fields it
// was asked to carry, and batches summed exactly at the capacity; the AVX-512 and AVX2 scans
// (when the build has them) must give the same batches bit for bit as the scalar one, so that
// the rates do not depend on the build.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "netsph/backend/cpu/neighbour_batch.hpp"

namespace netsph {
namespace {

struct Entry {
  Real dx, dy, dz, r2;
  std::int32_t j;
  std::vector<Real> carried;  ///< the carried fields, in CandidateScan::carry's order
  bool operator==(const Entry& o) const {
    return dx == o.dx && dy == o.dy && dz == o.dz && r2 == o.r2 && j == o.j && carried == o.carried;
  }
};

/// What a scan delivered: the batches summed at the capacity, then the final partial one.
struct Delivered {
  std::vector<std::vector<Entry>> full;
  std::vector<Entry> rest;
};

std::vector<Entry> entries(const NeighbourBatch& b, int n, int ncarried) {
  std::vector<Entry> e;
  for (int k = 0; k < n; ++k) {
    e.push_back({b.dx[k], b.dy[k], b.dz[k], b.r2[k], b.j[k], {}});
    for (int c = 0; c < ncarried; ++c) e.back().carried.push_back(b.carried[c][k]);
  }
  return e;
}

/// `count` fields of n random values each, and the scan's carry set to them.
std::vector<std::vector<Real>> carry_random_fields(CandidateScan& s, int count, std::size_t n,
                                                   unsigned seed) {
  std::mt19937 gen(seed + 100);
  std::uniform_real_distribution<Real> u(-1, 1);
  std::vector<std::vector<Real>> fields(static_cast<std::size_t>(count));
  for (int c = 0; c < count; ++c) {
    for (std::size_t i = 0; i < n; ++i) fields[c].push_back(u(gen));
    s.carry[c] = fields[c].data();
  }
  s.ncarry = count;
  return fields;
}

struct Cloud {
  std::vector<Real> x, y, z;
};

/// n candidates in a cube of side `side` around the origin.
Cloud cloud(std::size_t n, Real side, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<Real> u(-side / 2, side / 2);
  Cloud c;
  for (std::size_t i = 0; i < n; ++i)
    c.x.push_back(u(gen)), c.y.push_back(u(gen)), c.z.push_back(u(gen));
  return c;
}

template <class Scan>
Delivered run(const CandidateScan& s, const std::vector<std::uint32_t>& cuts, Scan scan) {
  Delivered d;
  NeighbourBatch batch;
  const auto sum = [&](const NeighbourBatch& b) {
    d.full.push_back(entries(b, NeighbourBatch::kCapacity, s.ncarry));
  };
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) scan(s, cuts[k], cuts[k + 1], batch, sum);
  d.rest = entries(batch, batch.n, s.ncarry);
  return d;
}

const auto scalar = [](const CandidateScan& s, std::uint32_t b0, std::uint32_t b1,
                       NeighbourBatch& batch,
                       auto&& sum) { scan_range_scalar(s, b0, b1, batch, sum); };

TEST(NeighbourBatch, ScalarScanKeepsExactlyTheCandidatesWithinTheSupportInOrder) {
  Cloud c = cloud(2000, 3.0f, 1);
  const std::uint32_t self = 417;  // at the centre: the ball lies inside the cloud
  c.x[self] = c.y[self] = c.z[self] = 0;
  CandidateScan s{c.x[self], c.y[self], c.z[self], c.x.data(), c.y.data(), c.z.data(), self, 1.0f};
  const auto fields = carry_random_fields(s, 3, 2000, 1);
  const std::vector<std::uint32_t> cuts{0, 13, 13, 250, 417, 418, 1999, 2000};
  const Delivered d = run(s, cuts, scalar);
  std::vector<Entry> all;
  for (const auto& f : d.full) all.insert(all.end(), f.begin(), f.end());
  all.insert(all.end(), d.rest.begin(), d.rest.end());
  std::vector<Entry> expected;
  for (std::uint32_t b = 0; b < 2000; ++b) {
    const Real dx = s.xs - c.x[b], dy = s.ys - c.y[b], dz = s.zs - c.z[b];
    const Real r2 = offset_r2(dx, dy, dz);
    if (b != self && r2 < s.support2)
      expected.push_back({dx,
                          dy,
                          dz,
                          r2,
                          static_cast<std::int32_t>(b),
                          {fields[0][b], fields[1][b], fields[2][b]}});
  }
  // A ball of radius 1 in a cube of side 3 holds about 15% of 2000 candidates: full batches
  // and a partial one.
  ASSERT_GT(expected.size(), static_cast<std::size_t>(NeighbourBatch::kCapacity));
  EXPECT_EQ(all, expected);
  ASSERT_EQ(d.full.size(), expected.size() / NeighbourBatch::kCapacity);
  EXPECT_EQ(d.rest.size(), expected.size() % NeighbourBatch::kCapacity);
  // r^2 is the squared distance to float round-off.
  for (const Entry& e : expected) {
    const double r2 = double(e.dx) * e.dx + double(e.dy) * e.dy + double(e.dz) * e.dz;
    EXPECT_NEAR(e.r2, r2, 4e-7 * r2);
  }
}

TEST(NeighbourBatch, EveryCandidateANeighbourFillsBatchesAtTheCapacityExactly) {
  // 300 candidates all within the support, the particle among them: 299 neighbours = two full
  // batches and 43, whatever the range lengths (1, 15, 16, 17, 128, ...).
  const Cloud c = cloud(300, 0.1f, 2);
  const CandidateScan s{0, 0, 0, c.x.data(), c.y.data(), c.z.data(), 16, 1.0f};
  const std::vector<std::uint32_t> cuts{0, 1, 16, 32, 49, 177, 300};
  const Delivered d = run(s, cuts, scalar);
  ASSERT_EQ(d.full.size(), 2u);
  EXPECT_EQ(d.rest.size(), 43u);
  EXPECT_EQ(d.full[1].front().j, 129);  // 0..15, 17..128 in the first batch (128 entries)
}

TEST(NeighbourBatch, ARequiredFlagLeavesOutTheCandidatesWithoutIt) {
  // Walls and bodies take fluid neighbours only: every other candidate flagged 0.
  const Cloud c = cloud(400, 0.1f, 3);
  std::vector<Real> fluid(400);
  for (std::size_t b = 0; b < fluid.size(); ++b) fluid[b] = b % 2 ? Real(1) : Real(0);
  const CandidateScan s{0, 0, 0, c.x.data(), c.y.data(), c.z.data(), 1000, 1.0f, fluid.data()};
  const Delivered d = run(s, {0, 7, 200, 400}, scalar);
  ASSERT_EQ(d.full.size(), 1u);
  ASSERT_EQ(d.rest.size(), 72u);
  for (const Entry& e : d.full[0]) EXPECT_EQ(e.j % 2, 1);
  for (const Entry& e : d.rest) EXPECT_EQ(e.j % 2, 1);
}

/// A vector scan against the scalar one: the same batches, bit for bit, over random clouds cut
/// into ranges of 0 to 40 candidates (shorter and longer than the vector, ending anywhere in
/// it), with and without a required flag and with 0 to 9 carried fields.
template <class Scan>
void expect_the_scalar_scans_batches(Scan vector) {
  for (unsigned seed = 0; seed < 20; ++seed) {
    const Cloud c = cloud(700, seed % 2 ? 3.0f : 1.2f, seed);
    std::mt19937 gen(seed);
    std::vector<std::uint32_t> cuts{0};
    while (cuts.back() < 700) {
      const auto len = static_cast<std::uint32_t>(std::uniform_int_distribution<int>(0, 40)(gen));
      cuts.push_back(std::min<std::uint32_t>(700, cuts.back() + len));
    }
    const std::uint32_t self = seed * 31 % 700;
    CandidateScan s{c.x[self] + 0.01f,
                    c.y[self],
                    c.z[self] - 0.02f,
                    c.x.data(),
                    c.y.data(),
                    c.z.data(),
                    self,
                    1.0f};
    // Every third seed scans for flagged neighbours only, as walls and bodies do.
    std::vector<Real> flag(700);
    for (std::size_t k = 0; k < flag.size(); ++k) flag[k] = (k * 7 + seed) % 3 ? Real(1) : Real(0);
    if (seed % 3 == 0) s.require = flag.data();
    // Carried fields: none, a few, or as many as a batch holds.
    const auto fields =
        carry_random_fields(s, static_cast<int>(seed % 4 * 3), 700, seed);  // 0, 3, 6, 9
    const Delivered a = run(s, cuts, scalar);
    const Delivered b = run(s, cuts, vector);
    ASSERT_EQ(a.full.size(), b.full.size()) << "seed " << seed;
    for (std::size_t k = 0; k < a.full.size(); ++k)
      EXPECT_EQ(a.full[k], b.full[k]) << "seed " << seed;
    EXPECT_EQ(a.rest, b.rest) << "seed " << seed;
  }
}

#if defined(__AVX512F__)
TEST(NeighbourBatch, Avx512ScanDeliversTheScalarScansBatchesBitForBit) {
  expect_the_scalar_scans_batches([](const CandidateScan& s, std::uint32_t b0, std::uint32_t b1,
                                     NeighbourBatch& batch,
                                     auto&& sum) { scan_range_avx512(s, b0, b1, batch, sum); });
}
#else
TEST(NeighbourBatch, Avx512ScanDeliversTheScalarScansBatchesBitForBit) {
  GTEST_SKIP() << "this build has no AVX-512";
}
#endif

// Built with AVX-512 too (which then scans with AVX-512), so an AVX-512 machine checks the
// scan that AVX2 machines run.
#if defined(NETSPH_SCAN_AVX2)
TEST(NeighbourBatch, Avx2ScanDeliversTheScalarScansBatchesBitForBit) {
  expect_the_scalar_scans_batches([](const CandidateScan& s, std::uint32_t b0, std::uint32_t b1,
                                     NeighbourBatch& batch,
                                     auto&& sum) { scan_range_avx2(s, b0, b1, batch, sum); });
}
#else
TEST(NeighbourBatch, Avx2ScanDeliversTheScalarScansBatchesBitForBit) {
  GTEST_SKIP() << "this build has no AVX2 with FMA";
}
#endif

}  // namespace
}  // namespace netsph
