#pragma once
// The candidate scan of the CPU interaction passes (rates.cpp): the neighbours of particle a
// within the support among one range of sorted candidates (for wall and body particles, the
// fluid ones only), appended in index order to a batch of offsets, squared distances, indices
// and the fields the pass asked to carry. The pair loop then runs over the batch in full vector
// lanes with contiguous loads (docs/PERFORMANCE.md, "Where the time goes").
//
// With AVX-512 the scan tests 16 candidates at a time and compacts the hits with vcompressps
// into registers, stored whole (the batch has 16 entries of slack for the lanes past the hits);
// with AVX2 and FMA (x86-64-v3), 8 at a time, compacted by a lane permutation looked up from
// the hit mask; without either, one candidate at a time with a branch (docs/PERFORMANCE.md,
// "Instruction sets", has what each costs). Within a build all give the same neighbours in the
// same order with the same float arithmetic, so the rates do not depend on which one ran
// (tests/unit/neighbour_batch_test.cpp).
#include <cstdint>
#include <cstring>

#include "netsph/core/real.hpp"

// The AVX2 scan needs FMA too: its r^2 must round as offset_r2's does.
#if defined(__AVX2__) && defined(__FMA__)
#define NETSPH_SCAN_AVX2 1
#endif

#if defined(__AVX512F__) || defined(NETSPH_SCAN_AVX2)
#include <immintrin.h>
#endif

namespace netsph {

struct NeighbourBatch {
  static constexpr int kCapacity = 128;  ///< neighbours summed at a time
  static constexpr int kSlack = 16;      ///< room for a whole vector store past the last hit
  static constexpr int kMaxCarried = 9;  ///< fields a scan can copy along (CandidateScan::carry)
  alignas(64) Real dx[kCapacity + kSlack];
  alignas(64) Real dy[kCapacity + kSlack];
  alignas(64) Real dz[kCapacity + kSlack];
  alignas(64) Real r2[kCapacity + kSlack];
  alignas(64) std::int32_t j[kCapacity + kSlack];
  /// The neighbours' fields the scan was asked to carry, in the order of CandidateScan::carry.
  alignas(64) Real carried[kMaxCarried][kCapacity + kSlack];
  int n = 0;

  /// After sum(batch) has taken the first kCapacity entries: moves the rest to the front
  /// (with the first `ncarried` carried fields).
  void drop_full_batch(int ncarried) {
    const int rest = n - kCapacity;
    const auto bytes = static_cast<std::size_t>(rest) * sizeof(Real);
    std::memmove(dx, dx + kCapacity, bytes), std::memmove(dy, dy + kCapacity, bytes);
    std::memmove(dz, dz + kCapacity, bytes), std::memmove(r2, r2 + kCapacity, bytes);
    std::memmove(j, j + kCapacity, static_cast<std::size_t>(rest) * sizeof(std::int32_t));
    for (int c = 0; c < ncarried; ++c) std::memmove(carried[c], carried[c] + kCapacity, bytes);
    n = rest;
  }

  /// After a vector scan stored `hits` more entries whole: counts them, and when the batch
  /// then holds kCapacity or more, sum(batch) takes the first kCapacity and they are dropped.
  template <class Sum>
  void add_vector_hits(int hits, int ncarried, Sum&& sum) {
    n += hits;
    if (n >= kCapacity) {
      sum(*this);
      drop_full_batch(ncarried);
    }
  }
};

/// Where a candidate range is scanned: particle a's position less the range's periodic shift
/// (so the loop reads the candidates' positions as they are), and the view's positions.
struct CandidateScan {
  Real xs, ys, zs;
  const Real* x;
  const Real* y;
  const Real* z;
  std::uint32_t a;  ///< the particle itself, never its own neighbour
  Real support2;
  /// When set, only candidates b with require[b] > 0 are neighbours (walls and bodies take
  /// fluid neighbours only: the view's fluid flag).
  const Real* require = nullptr;
  /// Fields of the candidates copied into the batch with each neighbour (carried[c][k] =
  /// carry[c][j[k]]): the AVX-512 scan loads them whole for 16 candidates and compresses them
  /// as it does the offsets, so the sums read them contiguously instead of gathering each
  /// neighbour's (a gather per field per 16 neighbours was the pair loop's largest cost).
  const Real* carry[NeighbourBatch::kMaxCarried] = {};
  int ncarry = 0;
};

/// r^2 of an offset, contracted as GCC 12 contracts the expression dx*dx + dy*dy + dz*dz with
/// FMA (-ffp-contract=fast: fma(dz, dz, fma(dx, dx, dy*dy))), written out so that the scalar and
/// vector scans round alike, and as the scan did before it was vectorised.
inline Real offset_r2(Real dx, Real dy, Real dz) {
#if defined(__FMA__)
  return __builtin_fmaf(dz, dz, __builtin_fmaf(dx, dx, dy * dy));
#else
  return dx * dx + dy * dy + dz * dz;
#endif
}

/// Appends the neighbours among candidates [b0, b1) one at a time; whenever the batch holds
/// kCapacity entries calls sum(batch), which sums those first kCapacity, and drops them.
template <class Sum>
inline void scan_range_scalar(const CandidateScan& s, std::uint32_t b0, std::uint32_t b1,
                              NeighbourBatch& batch, Sum&& sum) {
  for (std::uint32_t b = b0; b < b1; ++b) {
    const Real dx = s.xs - s.x[b], dy = s.ys - s.y[b], dz = s.zs - s.z[b];
    const Real r2 = offset_r2(dx, dy, dz);
    if (r2 < s.support2 && b != s.a && (!s.require || s.require[b] > Real(0))) {
      const int q = batch.n++;
      batch.dx[q] = dx, batch.dy[q] = dy, batch.dz[q] = dz, batch.r2[q] = r2;
      batch.j[q] = static_cast<std::int32_t>(b);
      for (int c = 0; c < s.ncarry; ++c) batch.carried[c][q] = s.carry[c][b];
      if (batch.n == NeighbourBatch::kCapacity) {
        sum(batch);
        batch.drop_full_batch(s.ncarry);
      }
    }
  }
}

#if defined(__AVX512F__)
/// The same, 16 candidates at a time.
template <class Sum>
inline void scan_range_avx512(const CandidateScan& s, std::uint32_t b0, std::uint32_t b1,
                              NeighbourBatch& batch, Sum&& sum) {
  const __m512 xs = _mm512_set1_ps(s.xs), ys = _mm512_set1_ps(s.ys), zs = _mm512_set1_ps(s.zs);
  const __m512 support2 = _mm512_set1_ps(s.support2);
  const __m512i lane = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
  for (std::uint32_t b = b0; b < b1; b += 16) {
    const std::uint32_t left = b1 - b;
    // Lanes past the range are masked: their loads do not touch memory.
    const __mmask16 live =
        left >= 16 ? static_cast<__mmask16>(0xFFFF) : static_cast<__mmask16>((1u << left) - 1);
    const __m512 dx = _mm512_sub_ps(xs, _mm512_maskz_loadu_ps(live, s.x + b));
    const __m512 dy = _mm512_sub_ps(ys, _mm512_maskz_loadu_ps(live, s.y + b));
    const __m512 dz = _mm512_sub_ps(zs, _mm512_maskz_loadu_ps(live, s.z + b));
    const __m512 r2 = _mm512_fmadd_ps(dz, dz, _mm512_fmadd_ps(dx, dx, _mm512_mul_ps(dy, dy)));
    __mmask16 hit = _mm512_mask_cmp_ps_mask(live, r2, support2, _CMP_LT_OQ);
    if (s.a - b < 16) hit &= static_cast<__mmask16>(~(1u << (s.a - b)));
    if (s.require && hit != 0) {
      const __m512 flag = _mm512_maskz_loadu_ps(hit, s.require + b);
      hit = _mm512_mask_cmp_ps_mask(hit, flag, _mm512_setzero_ps(), _CMP_GT_OQ);
    }
    if (hit == 0) continue;
    const int q = batch.n;
    _mm512_storeu_ps(batch.dx + q, _mm512_maskz_compress_ps(hit, dx));
    _mm512_storeu_ps(batch.dy + q, _mm512_maskz_compress_ps(hit, dy));
    _mm512_storeu_ps(batch.dz + q, _mm512_maskz_compress_ps(hit, dz));
    _mm512_storeu_ps(batch.r2 + q, _mm512_maskz_compress_ps(hit, r2));
    const __m512i idx = _mm512_add_epi32(_mm512_set1_epi32(static_cast<int>(b)), lane);
    _mm512_storeu_si512(batch.j + q, _mm512_maskz_compress_epi32(hit, idx));
    for (int c = 0; c < s.ncarry; ++c) {
      const __m512 field = _mm512_maskz_loadu_ps(hit, s.carry[c] + b);
      _mm512_storeu_ps(batch.carried[c] + q, _mm512_maskz_compress_ps(hit, field));
    }
    batch.add_vector_hits(__builtin_popcount(hit), s.ncarry, sum);
  }
}
#endif

#if defined(NETSPH_SCAN_AVX2)
namespace detail {
/// For each mask of 8 lanes, the lanes it selects in increasing order, one byte each from the
/// lowest: the permutation that packs a vector's hits to its front, as vcompressps does.
struct LeftPackTable {
  std::uint64_t lanes[256];
  constexpr LeftPackTable() : lanes{} {
    for (unsigned m = 0; m < 256; ++m) {
      int q = 0;
      for (unsigned l = 0; l < 8; ++l)
        if (m >> l & 1u) lanes[m] |= static_cast<std::uint64_t>(l) << (8 * q++);
    }
  }
};
inline constexpr LeftPackTable kLeftPack{};
}  // namespace detail

/// The same, 8 candidates at a time with AVX2.
template <class Sum>
inline void scan_range_avx2(const CandidateScan& s, std::uint32_t b0, std::uint32_t b1,
                            NeighbourBatch& batch, Sum&& sum) {
  const __m256 xs = _mm256_set1_ps(s.xs), ys = _mm256_set1_ps(s.ys), zs = _mm256_set1_ps(s.zs);
  const __m256 support2 = _mm256_set1_ps(s.support2);
  const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  for (std::uint32_t b = b0; b < b1; b += 8) {
    const std::uint32_t left = b1 - b;
    // Lanes past the range are masked: their loads do not touch memory (and read 0).
    const __m256i live =
        _mm256_cmpgt_epi32(_mm256_set1_epi32(static_cast<int>(left < 8 ? left : 8)), lane);
    const __m256 dx = _mm256_sub_ps(xs, _mm256_maskload_ps(s.x + b, live));
    const __m256 dy = _mm256_sub_ps(ys, _mm256_maskload_ps(s.y + b, live));
    const __m256 dz = _mm256_sub_ps(zs, _mm256_maskload_ps(s.z + b, live));
    const __m256 r2 = _mm256_fmadd_ps(dz, dz, _mm256_fmadd_ps(dx, dx, _mm256_mul_ps(dy, dy)));
    const __m256 within = _mm256_cmp_ps(r2, support2, _CMP_LT_OQ);
    auto hit =
        static_cast<unsigned>(_mm256_movemask_ps(_mm256_and_ps(within, _mm256_castsi256_ps(live))));
    if (s.a - b < 8) hit &= ~(1u << (s.a - b));
    if (s.require && hit != 0) {
      const __m256 flag = _mm256_maskload_ps(s.require + b, live);
      hit &= static_cast<unsigned>(
          _mm256_movemask_ps(_mm256_cmp_ps(flag, _mm256_setzero_ps(), _CMP_GT_OQ)));
    }
    if (hit == 0) continue;
    const __m256i pack = _mm256_cvtepu8_epi32(
        _mm_cvtsi64_si128(static_cast<long long>(detail::kLeftPack.lanes[hit])));
    const int q = batch.n;
    _mm256_storeu_ps(batch.dx + q, _mm256_permutevar8x32_ps(dx, pack));
    _mm256_storeu_ps(batch.dy + q, _mm256_permutevar8x32_ps(dy, pack));
    _mm256_storeu_ps(batch.dz + q, _mm256_permutevar8x32_ps(dz, pack));
    _mm256_storeu_ps(batch.r2 + q, _mm256_permutevar8x32_ps(r2, pack));
    const __m256i idx = _mm256_add_epi32(_mm256_set1_epi32(static_cast<int>(b)), lane);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(batch.j + q),
                        _mm256_permutevar8x32_epi32(idx, pack));
    for (int c = 0; c < s.ncarry; ++c) {
      const __m256 field = _mm256_maskload_ps(s.carry[c] + b, live);
      _mm256_storeu_ps(batch.carried[c] + q, _mm256_permutevar8x32_ps(field, pack));
    }
    batch.add_vector_hits(__builtin_popcount(hit), s.ncarry, sum);
  }
}
#endif

/// The scan this build runs.
template <class Sum>
inline void scan_range(const CandidateScan& s, std::uint32_t b0, std::uint32_t b1,
                       NeighbourBatch& batch, Sum&& sum) {
#if defined(__AVX512F__)
  scan_range_avx512(s, b0, b1, batch, sum);
#elif defined(NETSPH_SCAN_AVX2)
  scan_range_avx2(s, b0, b1, batch, sum);
#else
  scan_range_scalar(s, b0, b1, batch, sum);
#endif
}

/// Runs the scan over every candidate range of a particle and hands the neighbours to
/// sum(batch, n) in batches: the first n entries, n = kCapacity while more may follow, then the
/// rest. `scan` holds the particle's own position: each range's periodic shift is taken off.
template <class Ranges, class Sum>
inline void scan_ranges(CandidateScan scan, const Ranges& ranges, int nranges, Sum&& sum) {
  NeighbourBatch batch;
  const Real xa = scan.xs, ya = scan.ys, za = scan.zs;
  const auto full = [&](const NeighbourBatch& b) { sum(b, NeighbourBatch::kCapacity); };
  for (int k = 0; k < nranges; ++k) {
    // The neighbour's position is x[b] + shift: shifting a instead keeps the loop body plain.
    scan.xs = xa - ranges[k].shift.x, scan.ys = ya - ranges[k].shift.y;
    scan.zs = za - ranges[k].shift.z;
    scan_range(scan, ranges[k].begin, ranges[k].end, batch, full);
  }
  if (batch.n > 0) sum(batch, batch.n);
}

}  // namespace netsph
