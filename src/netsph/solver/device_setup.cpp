#include "netsph/solver/device_setup.hpp"

#include <string>

#include "netsph/core/error.hpp"
#include "netsph/neighbors/cell_grid.hpp"
#include "netsph/solver/step_settings.hpp"

namespace netsph {

namespace {

void refuse(const std::string& what) {
  throw Error("--backend cuda", "the CUDA backend does not support " + what +
                                    " yet (it runs fluid, fixed walls, periodic axes and "
                                    "shifting); use --backend cpu");
}

}  // namespace

DeviceSetup device_setup(const CaseSpec& spec, const Scene& scene) {
  if (!spec.inlets.empty() || !spec.outlets.empty())
    refuse("open boundaries ([[inlet]], [[outlet]])");
  if (!spec.bodies.empty()) refuse("bodies ([[body]])");
  if (!spec.nets.empty()) refuse("nets ([[net]])");
  if (!spec.probes.empty()) refuse("probes ([[probe]])");
  DeviceSetup s;
  s.model = scene.model;
  CellGrid grid;
  grid.configure(scene.domain_min, scene.domain_max, s.model.support, kGridSkin, s.model.dims,
                 spec.domain.periodic);
  s.max_displacement = grid.max_displacement();
  DeviceGrid& g = s.grid;
  g.origin = grid.origin();
  g.upper = scene.domain_max;
  g.period = grid.period();
  g.dims = s.model.dims;
  for (int a = 0; a < 3; ++a) {
    g.n[a] = grid.dims()[static_cast<std::size_t>(a)];
    g.periodic[a] = grid.periodic(a);
  }
  g.inv_cell = {1.0 / grid.cell_size().x, 1.0 / grid.cell_size().y, 1.0 / grid.cell_size().z};
  s.cfl = spec.simulation.cfl;
  s.dt_max = spec.simulation.dt_max;
  s.dt_min = spec.simulation.dt_min;
  s.shifting = spec.fluid.shifting == ShiftingModel::Fickian;
  s.shift_params = shifting_params(spec, s.model);
  for (const WallSpec& w : spec.walls) {
    if (w.motion.moving()) refuse("moving walls (wall '" + w.name + "')");
    DeviceWall d;
    d.mdbc = w.model == WallModel::Mdbc;
    d.slip = w.slip;
    d.shows_own_velocity = w.model == WallModel::Dbc || w.slip == WallSlip::WallVelocity;
    s.walls.push_back(d);
  }
  return s;
}

std::unique_ptr<DeviceRun> make_device_run(const CaseSpec& spec, DeviceExecutor exec) {
  const Scene scene = build_scene(spec);
  DeviceSetup setup = device_setup(spec, scene);
  if (exec == DeviceExecutor::Host) return make_host_device_run(std::move(setup), scene.particles);
#if defined(NETSPH_HAVE_CUDA)
  return make_cuda_device_run(std::move(setup), scene.particles);
#else
  throw Error("--backend cuda",
              "this netsph was built without CUDA (no nvcc found at configure "
              "time); use --backend cpu");
#endif
}

}  // namespace netsph
