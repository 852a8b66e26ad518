#include "netsph/backend/cpu/contact.hpp"

namespace netsph {

bool compute_contacts(const ContactModel& model, const CellGrid& grid, const InteractionView& v,
                      std::span<const ParticleKind> kind, std::vector<Vec3f>& contact) {
  contact.assign(v.x.size(), Vec3f{});
  const auto& cells = grid.occupied_cells();
  const auto ncells = static_cast<std::int64_t>(cells.size());
  // The dashpot acts on the solids' own velocities: a solid under a mirror slip condition
  // shows the fluid its mirrored velocity (vx), and its own in continuity.
  const Real* vx = v.continuity_vx();
  const Real* vy = v.continuity_vy();
  const Real* vz = v.continuity_vz();
  int any = 0;
#pragma omp parallel for schedule(dynamic, 64) reduction(max : any)
  for (std::int64_t k = 0; k < ncells; ++k) {
    const std::int64_t c = cells[k];
    const IndexRange own = grid.cell_range(c);
    bool has_body = false;
    for (std::uint32_t a = own.begin; a < own.end; ++a) has_body |= kind[a] == ParticleKind::Body;
    if (!has_body) continue;
    NeighbourRanges ranges;
    const int nr = grid.neighbour_ranges(c, ranges);
    for (std::uint32_t a = own.begin; a < own.end; ++a) {
      if (kind[a] != ParticleKind::Body) continue;
      const std::int32_t self = v.solid[a];
      Vec3f acc{};
      for (int r = 0; r < nr; ++r) {
        const Vec3f pa(v.x[a] - ranges[r].shift.x, v.y[a] - ranges[r].shift.y,
                       v.z[a] - ranges[r].shift.z);
        for (std::uint32_t b = ranges[r].begin; b < ranges[r].end; ++b) {
          const std::int32_t other = v.solid[b];
          if (other == InteractionView::kNotSolid || other == self) continue;
          acc += contact_acceleration(model, pa - Vec3f(v.x[b], v.y[b], v.z[b]),
                                      Vec3f(vx[a] - vx[b], vy[a] - vy[b], vz[a] - vz[b]));
        }
      }
      if (acc.x != 0 || acc.y != 0 || acc.z != 0) contact[a] = acc, any = 1;
    }
  }
  return any != 0;
}

}  // namespace netsph
