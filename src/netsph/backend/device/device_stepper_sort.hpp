#pragma once
// The sort of a step: periodic wrap, cell keys, radix sort, the gather of every array, the cell
// table; the particles it drops for leaving the grid are named (note_lost).
// Members of DeviceStepper (device_stepper_class.hpp); device_stepper.hpp includes every part.
#include "netsph/backend/device/device_stepper_class.hpp"

namespace netsph {

template <class Exec>
void DeviceStepper<Exec>::sort(bool mid_step, std::size_t removed,
                               std::vector<LostParticle>& last_lost) {
  std::optional<PhaseTimer<Exec>> timer(std::in_place, profile(), DevicePhase::SortKeys);
  const GridIndex g = s_.grid;
  const DeviceState st = state();
  WorkCarver carve(work_.data(), n_);
  const SortArrays sa = sort_layout(carve);
  std::uint32_t* keys = keys_.data();
  std::uint32_t* order = sa.order;
  const bool periodic = g.periodic[0] || g.periodic[1] || g.periodic[2];
  // Mid-step, buffer particles are not wrapped (Simulation::sort_particles says why).
  Exec::for_each(n_, [=] NETSPH_LAMBDA(std::uint32_t i) {
    if (periodic && !(mid_step && st.kind[i] == ParticleKind::Buffer))
      st.pos[i] = g.wrapped(st.pos[i]);
    keys[i] = g.key_of(st.pos[i]);
    order[i] = i;
  });
  int bits = 1;
  while ((std::uint64_t{1} << bits) <= g.sentinel()) ++bits;
  const bool in_alt = Exec::sort_pairs(keys, sa.keys_alt, order, sa.order_alt, n_, bits);
  if (in_alt) {
    const std::uint32_t* sorted = sa.keys_alt;
    Exec::for_each(n_, [=] NETSPH_LAMBDA(std::uint32_t i) { keys[i] = sorted[i]; });
  }
  const std::uint32_t* sorted_order = in_alt ? sa.order_alt : sa.order;
  const std::size_t kept = Exec::count_below(keys_.data(), n_, g.sentinel());
  if (n_ - kept > removed) note_lost(sorted_order + kept, n_ - kept, last_lost);
  timer.emplace(profile(), DevicePhase::Gather);
  gather(pos_, sorted_order, sa.scratch, kept), gather(vel_, sorted_order, sa.scratch, kept);
  gather(rho_, sorted_order, sa.scratch, kept), gather(kind_, sorted_order, sa.scratch, kept);
  gather(id_, sorted_order, sa.scratch, kept), gather(group_, sorted_order, sa.scratch, kept);
  if (mid_step) {
    gather(svel_, sorted_order, sa.scratch, kept);
    gather(srho_, sorted_order, sa.scratch, kept);
  }
  n_ = kept;
  timer.emplace(profile(), DevicePhase::CellTable);
  // cell_begin[c] = first sorted index with key >= c, for c in [0, cells + 1]: each cell's
  // particle count (written by the first particle of the cell), then an exclusive scan in
  // place. (Filling the empty cells between two particles' keys from the particles instead
  // left one thread to write every cell of the air above a free surface, millions in a row.)
  std::uint32_t* begin = cell_begin_.data();
  const std::uint32_t* k = keys_.data();
  const std::uint32_t n = static_cast<std::uint32_t>(n_);
  const std::size_t entries = static_cast<std::size_t>(g.sentinel()) + 2;
  Exec::for_each(entries, [=] NETSPH_LAMBDA(std::uint32_t c) { begin[c] = 0; });
  Exec::for_each(n_, [=] NETSPH_LAMBDA(std::uint32_t i) {
    if (i > 0 && k[i - 1] == k[i]) return;
    std::uint32_t j = i + 1;
    while (j < n && k[j] == k[i]) ++j;
    begin[k[i]] = j - i;
  });
  Exec::exclusive_scan(begin, begin, entries);
}

template <class Exec>
void DeviceStepper<Exec>::note_lost(const std::uint32_t* dropped, std::size_t count,
                                    std::vector<LostParticle>& last_lost) {
  // Rare (a step that lost particles): the copies are made and freed here.
  Buffer<LostParticle> copies;
  Exec::resize_discarding(copies, count);
  LostParticle* out = copies.data();
  const DeviceState st = state();
  Exec::for_each(count, [=] NETSPH_LAMBDA(std::uint32_t i) {
    const std::uint32_t j = dropped[i];
    out[i].id = st.id[j], out[i].pos = st.pos[j], out[i].vel = st.vel[j];
  });
  std::vector<LostParticle> host(count);
  Exec::download(host.data(), copies, count);
  for (const LostParticle& l : host)
    if (std::isfinite(l.pos.x)) remember_lost(last_lost, l);
}

template <class Exec>
template <class T>
void DeviceStepper<Exec>::gather(Buffer<T>& v, const std::uint32_t* order, unsigned char* scratch,
                                 std::size_t kept) {
  T* tmp = reinterpret_cast<T*>(scratch);
  T* a = v.data();
  Exec::for_each(kept, [=] NETSPH_LAMBDA(std::uint32_t i) { tmp[i] = a[order[i]]; });
  Exec::for_each(kept, [=] NETSPH_LAMBDA(std::uint32_t i) { a[i] = tmp[i]; });
}

}  // namespace netsph
