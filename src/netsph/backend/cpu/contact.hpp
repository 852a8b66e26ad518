#pragma once
// Contact accelerations of body particles (sph/contact.hpp) on the CPU.
#include <vector>

#include "netsph/backend/cpu/interaction_view.hpp"
#include "netsph/neighbours/cell_grid.hpp"
#include "netsph/sph/contact.hpp"
#include "netsph/sph/particle_set.hpp"

namespace netsph {

/// contact[i] = contact acceleration of body particle i from particles of walls and other
/// bodies; zero for other particles. Returns whether any contact was found.
bool compute_contacts(const ContactModel& model, const CellGrid& grid, const InteractionView& v,
                      std::span<const ParticleKind> kind, std::vector<Vec3f>& contact);

}  // namespace netsph
