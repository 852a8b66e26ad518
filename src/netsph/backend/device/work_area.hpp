#pragma once
// Typed per-particle arrays carved out of one untyped allocation. The phases of a device step
// need different short-lived arrays, never at the same time: the interaction view and the
// rates; the sort's second key buffer, its order and its gather scratch; the open boundaries'
// flags. Sharing one allocation among them is what brings the device step under 150 B a
// particle (docs/PERFORMANCE.md, "Memory"); DualSPHysics' GPU code pools its arrays for the
// same reason.
#include <cstddef>

namespace netsph {

/// Consecutive arrays of n elements each from `base` (null: only counts the bytes), each
/// starting on a 256 B boundary: coalesced loads on the GPU, and aligned for every element
/// type (the allocation itself is at least 16 B aligned: cudaMalloc gives 256, operator new
/// 16).
class WorkCarver {
 public:
  WorkCarver(unsigned char* base, std::size_t n) : base_(base), n_(n) {}

  /// The next array: n * per_particle elements of T.
  template <class T>
  T* take(std::size_t per_particle = 1) {
    offset_ = (offset_ + kAlign - 1) / kAlign * kAlign;
    T* p = base_ ? reinterpret_cast<T*>(base_ + offset_) : nullptr;
    offset_ += n_ * per_particle * sizeof(T);
    return p;
  }
  /// Bytes carved so far.
  std::size_t bytes() const { return offset_; }

 private:
  static constexpr std::size_t kAlign = 256;
  unsigned char* base_;
  std::size_t n_;
  std::size_t offset_ = 0;
};

}  // namespace netsph
