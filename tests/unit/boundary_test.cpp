// Boundary conditions: the mDBC wall state (boundary/mdbc.hpp), the ghost offsets of walls built
// on a box (boundary/wall_ghosts.hpp), open boundaries (boundary/open_boundary.hpp) and the
// wall velocity history (case/case_spec.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

#include "netsph/boundary/mdbc.hpp"
#include "netsph/boundary/open_boundary.hpp"
#include "netsph/boundary/wall_ghosts.hpp"
#include "netsph/case/case_spec.hpp"
#include "netsph/core/periodic_image.hpp"
#include "netsph/sph/ghost_interpolation.hpp"
#include "netsph/sph/kernels.hpp"

namespace netsph {
namespace {

void expect_vec_near(const Vec3f& got, const Vec3d& want, double tol, const char* what = "") {
  EXPECT_NEAR(got.x, want.x, tol) << what;
  EXPECT_NEAR(got.y, want.y, tol) << what;
  EXPECT_NEAR(got.z, want.z, tol) << what;
}

void expect_vec_near(const Vec3d& got, const Vec3d& want, double tol, const char* what = "") {
  EXPECT_NEAR(got.x, want.x, tol) << what;
  EXPECT_NEAR(got.y, want.y, tol) << what;
  EXPECT_NEAR(got.z, want.z, tol) << what;
}

// ---------------------------------------------------------------------------------------------
// mDBC wall state

GhostValue first_order_ghost() {
  GhostValue g;
  g.any = true;
  g.first_order = true;
  g.rho = 1002;
  g.grad_rho = {10, 4, -50};  // density rising downwards (hydrostatic) and along x
  g.vel = {0.4, -0.1, 0.25};
  return g;
}

TEST(Mdbc, FirstOrderExtrapolatesTheDensityToTheWallParticle) {
  // Wall below the fluid: the ghost is 2 cm above the wall particle. rho_b = rho_g - grad . off.
  const GhostValue g = first_order_ghost();
  const Vec3f off{0, 0, 0.02f};
  const WallState w = mdbc_wall_state(g, off, 1000, WallSlip::WallVelocity, {});
  EXPECT_NEAR(w.rho, 1002 + 50 * 0.02, 1e-4);  // denser below, as the hydrostatic profile
  // Corner offset: all components count.
  const Vec3f diag{0.01f, -0.02f, 0.03f};
  const WallState w2 = mdbc_wall_state(g, diag, 1000, WallSlip::WallVelocity, {});
  EXPECT_NEAR(w2.rho, 1002 - (10 * 0.01 - 4 * 0.02 - 50 * 0.03), 1e-4);
}

TEST(Mdbc, ShepardFallbackUsesTheGhostDensity) {
  GhostValue g = first_order_ghost();
  g.first_order = false;  // gradient not valid (it is still filled in here: must be ignored)
  const WallState w = mdbc_wall_state(g, {0, 0, 0.02f}, 1000, WallSlip::WallVelocity, {});
  EXPECT_NEAR(w.rho, 1002, 1e-4);
}

TEST(Mdbc, NoFluidGivesRho0AndTheWallVelocity) {
  GhostValue g = first_order_ghost();
  g.any = false;
  g.first_order = false;
  const Vec3f v_wall{0.5f, 0, -0.2f};
  for (WallSlip slip : {WallSlip::WallVelocity, WallSlip::NoSlip, WallSlip::FreeSlip}) {
    const WallState w = mdbc_wall_state(g, {0, 0, 0.02f}, 998, slip, v_wall);
    EXPECT_EQ(w.rho, 998.0f);
    expect_vec_near(w.vel, Vec3d(v_wall), 0);
  }
}

TEST(Mdbc, WallVelocityModeShowsTheWallVelocity) {
  const Vec3f v_wall{0.3f, 0.1f, 0};
  const WallState w =
      mdbc_wall_state(first_order_ghost(), {0, 0, 0.02f}, 1000, WallSlip::WallVelocity, v_wall);
  expect_vec_near(w.vel, Vec3d(v_wall), 0);
}

TEST(Mdbc, NoSlipMirrorsTheGhostVelocity) {
  // 2 v_wall - v_g: the average of fluid and wall image is the wall velocity.
  const Vec3f v_wall{0.3f, 0.1f, 0};
  const GhostValue g = first_order_ghost();
  const WallState w = mdbc_wall_state(g, {0, 0, 0.02f}, 1000, WallSlip::NoSlip, v_wall);
  expect_vec_near(w.vel, {2 * 0.3 - 0.4, 2 * 0.1 + 0.1, -0.25}, 1e-6);
  expect_vec_near((Vec3d(w.vel) + g.vel) * 0.5, Vec3d(v_wall), 1e-6);
  // Resting wall: plain reversal.
  const WallState r = mdbc_wall_state(g, {0, 0, 0.02f}, 1000, WallSlip::NoSlip, {});
  expect_vec_near(r.vel, g.vel * -1.0, 1e-6);
}

TEST(Mdbc, FreeSlipMirrorsTheNormalComponentOnly) {
  const GhostValue g = first_order_ghost();
  const Vec3f v_wall{0.05f, 0, 0.1f};
  // Bottom wall: normal z. Tangential (x, y) kept, normal mirrored about v_wall.z.
  const WallState w = mdbc_wall_state(g, {0, 0, 0.02f}, 1000, WallSlip::FreeSlip, v_wall);
  expect_vec_near(w.vel, {0.4, -0.1, 2 * 0.1 - 0.25}, 1e-6);
  // Oblique (corner) normal: check the decomposition.
  const Vec3f off{0.02f, -0.01f, 0.02f};
  const WallState c = mdbc_wall_state(g, off, 1000, WallSlip::FreeSlip, v_wall);
  const Vec3d n = Vec3d(off) / norm(Vec3d(off));
  const Vec3d vg = g.vel, vb = Vec3d(c.vel), vw(v_wall);
  const Vec3d tg = vg - n * dot(vg, n), tb = vb - n * dot(vb, n);
  expect_vec_near(tb, tg, 1e-6, "tangential part kept");
  EXPECT_NEAR(dot(vb - vw, n), -dot(vg - vw, n), 1e-6) << "normal part mirrored";
  // The offset's length does not matter, only its direction.
  const WallState c2 = mdbc_wall_state(g, off * 3.0f, 1000, WallSlip::FreeSlip, v_wall);
  expect_vec_near(c2.vel, Vec3d(c.vel), 1e-6);
}

TEST(Mdbc, HydrostaticWallDensityFromALattice) {
  // End to end: a 2D fluid lattice above a wall at z = 0 with a linear (hydrostatic) density;
  // a wall particle at z = -dp/2 takes its ghost's density extrapolated to its own depth.
  const double dp = 0.01, h = 1.5 * dp, rho0 = 1000, slope = -9.81 * rho0 / (20.0 * 20.0);
  const KernelScale ks = make_kernel_scale<WendlandC2>(2, h);
  const Real mass = static_cast<Real>(rho0 * dp * dp);
  auto rho_at = [&](double z) { return rho0 + slope * (z - 0.2); };
  const Vec3d wall{0.1, 0, -0.5 * dp};
  const auto off =
      box_wall_ghost_offsets(std::span<const Vec3d>(&wall, 1), {0, 0, 0}, {0.2, 0, 0.2}, 2);
  ASSERT_EQ(off.size(), 1u);
  const Vec3d rg = wall + Vec3d(off[0]);
  EXPECT_NEAR(rg.z, 0.5 * dp, 1e-7);
  GhostSums s;
  for (int k = 0; k < 20; ++k)
    for (int i = 0; i < 20; ++i) {
      const Vec3d r{(i + 0.5) * dp, 0, (k + 0.5) * dp};
      const Vec3d d = r - rg;
      const double q = norm(d);
      if (q >= 2 * h) continue;
      ghost_accumulate(s, Vec3f(d), kernel_value<WendlandC2>(ks, static_cast<Real>(q)),
                       kernel_grad_factor<WendlandC2>(ks, static_cast<Real>(q)), mass,
                       static_cast<Real>(rho_at(r.z)), {});
    }
  const GhostValue g = ghost_solve(s, 2);
  ASSERT_TRUE(g.first_order);
  const WallState w = mdbc_wall_state(g, off[0], static_cast<Real>(rho0), WallSlip::NoSlip, {});
  EXPECT_NEAR(w.rho, rho_at(wall.z), 2e-3);
  EXPECT_GT(w.rho, rho_at(rg.z));  // deeper than its ghost: denser
}

// ---------------------------------------------------------------------------------------------
// Wall ghost offsets

TEST(WallGhosts, BehindAFaceTheGhostIsTheMirror) {
  const Vec3d lo{0, 0, 0}, hi{1, 0.5, 0.8};
  const std::vector<Vec3d> pos = {
      {0.5, 0.2, -0.015},  // below zmin
      {1.02, 0.3, 0.4},    // beyond xmax
      {0.3, -0.005, 0.4},  // below ymin
      {0.3, 0.53, 0.4},    // beyond ymax
      {0.3, 0.2, 0.81},    // above zmax
      {-0.025, 0.2, 0.4},  // below xmin
      {0.5, 0.2, 0.4},     // inside: no ghost
  };
  const auto off = box_wall_ghost_offsets(pos, lo, hi, 3);
  ASSERT_EQ(off.size(), pos.size());
  const Vec3d expect[] = {{0, 0, 0.03},  {-0.04, 0, 0}, {0, 0.01, 0}, {0, -0.06, 0},
                          {0, 0, -0.02}, {0.05, 0, 0},  {0, 0, 0}};
  for (std::size_t i = 0; i < pos.size(); ++i) {
    expect_vec_near(off[i], expect[i], 1e-7);
    // The ghost is the mirror image: as far inside the face as the particle is outside.
    const Vec3d g = pos[i] + Vec3d(off[i]);
    for (int a = 0; a < 3; ++a) {
      const double face = pos[i][a] < lo[a] ? lo[a] : (pos[i][a] > hi[a] ? hi[a] : pos[i][a]);
      EXPECT_NEAR(g[a] - face, face - pos[i][a], 1e-7) << i << " axis " << a;
    }
  }
}

TEST(WallGhosts, EdgesAndCornersPointToTheEdgeOrCorner) {
  const Vec3d lo{0, 0, 0}, hi{1, 0.5, 0.8};
  const std::vector<Vec3d> pos = {
      {-0.01, 0.2, -0.02},     // xmin-zmin edge
      {1.03, 0.2, 0.82},       // xmax-zmax edge
      {0.4, 0.51, -0.01},      // ymax-zmin edge
      {-0.01, -0.02, 0.83},    // corner xmin, ymin, zmax
      {1.015, 0.525, -0.005},  // corner xmax, ymax, zmin
  };
  const auto off = box_wall_ghost_offsets(pos, lo, hi, 3);
  const Vec3d expect[] = {{0.02, 0, 0.04},
                          {-0.06, 0, -0.04},
                          {0, -0.02, 0.02},
                          {0.02, 0.04, -0.06},
                          {-0.03, -0.05, 0.01}};
  const Vec3d edge_point[] = {{0, 0.2, 0}, {1, 0.2, 0.8}, {0.4, 0.5, 0}, {0, 0, 0.8}, {1, 0.5, 0}};
  for (std::size_t i = 0; i < pos.size(); ++i) {
    expect_vec_near(off[i], expect[i], 1e-7);
    // r + off/2 is the edge or corner point.
    expect_vec_near(pos[i] + Vec3d(off[i]) * 0.5, edge_point[i], 1e-7);
  }
}

TEST(WallGhosts, TwoDimensionsIgnoreY) {
  // In 2D the box has no y extent; y must not produce an offset.
  const Vec3d lo{0, 0, 0}, hi{1, 0, 0.8};
  const std::vector<Vec3d> pos = {{-0.01, 0.0, 0.4}, {0.5, 3.0, -0.02}, {1.01, -2.0, 0.81}};
  const auto off = box_wall_ghost_offsets(pos, lo, hi, 2);
  expect_vec_near(off[0], {0.02, 0, 0}, 1e-7);
  expect_vec_near(off[1], {0, 0, 0.04}, 1e-7);
  expect_vec_near(off[2], {-0.02, 0, -0.02}, 1e-7);
  EXPECT_TRUE(box_wall_ghost_offsets({}, lo, hi, 2).empty());
}

// ---------------------------------------------------------------------------------------------
// Open boundaries

/// Inlet on the xmin face of a domain [0, 1] in x: buffer [0, 0.03].
OpenBoundaryZone inlet_xmin() {
  OpenBoundaryZone z;
  z.name = "in";
  z.inlet = true;
  z.axis = 0;
  z.inward = 1;
  z.plane = 0.03;
  z.width = 0.03;
  z.face = 0;
  z.speed = 0.5;
  z.surface_z = 0.2;
  return z;
}

/// Outlet on the xmax face: buffer [0.97, 1].
OpenBoundaryZone outlet_xmax() {
  OpenBoundaryZone z;
  z.name = "out";
  z.inlet = false;
  z.axis = 0;
  z.inward = -1;
  z.plane = 0.97;
  z.width = 0.03;
  z.face = 1;
  z.speed = 0.4;
  return z;
}

TEST(OpenBoundary, DepthIsZeroAtTheInterfaceAndWidthAtTheFace) {
  const OpenBoundaryZone in = inlet_xmin(), out = outlet_xmax();
  EXPECT_NEAR(in.depth({0.03, 0, 0.1}), 0, 1e-15);
  EXPECT_NEAR(in.depth({0.0, 0, 0.1}), 0.03, 1e-15);
  EXPECT_NEAR(in.depth({0.01, 5, -3}), 0.02, 1e-15);
  EXPECT_LT(in.depth({0.05, 0, 0.1}), 0);  // in the fluid
  EXPECT_NEAR(out.depth({0.97, 0, 0.1}), 0, 1e-15);
  EXPECT_NEAR(out.depth({1.0, 0, 0.1}), 0.03, 1e-15);
  EXPECT_NEAR(out.depth({0.9, 0, 0.1}), -0.07, 1e-15);
  OpenBoundaryZone bottom = inlet_xmin();  // an inlet through the zmin face
  bottom.axis = 2;
  bottom.plane = 0.04;
  bottom.width = 0.04;
  EXPECT_NEAR(bottom.depth({0.5, 0.5, 0.01}), 0.03, 1e-15);
  expect_vec_near(bottom.inward_normal(), {0, 0, 1}, 0);
  expect_vec_near(out.inward_normal(), {-1, 0, 0}, 0);
}

TEST(OpenBoundary, GhostIsTheMirrorAcrossTheInterface) {
  const OpenBoundaryZone in = inlet_xmin(), out = outlet_xmax();
  expect_vec_near(in.ghost_of({0.01, 0.2, 0.1}), {0.05, 0.2, 0.1}, 1e-15);
  expect_vec_near(out.ghost_of({0.99, 0.2, 0.1}), {0.95, 0.2, 0.1}, 1e-14);
  for (const auto& z : {in, out}) {
    for (double x : {0.0, 0.01, 0.02, 0.975, 0.99, 1.0}) {
      const Vec3d p{x, 0.3, 0.15};
      if (z.depth(p) < 0 || z.depth(p) > z.width) continue;
      const Vec3d g = z.ghost_of(p);
      EXPECT_NEAR(z.depth(g), -z.depth(p), 1e-14) << x;  // as deep into the fluid
      EXPECT_EQ(g.y, p.y);
      EXPECT_EQ(g.z, p.z);
    }
  }
}

TEST(OpenBoundary, UniformImposedVelocityDirection) {
  OpenBoundaryZone in = inlet_xmin(), out = outlet_xmax();
  expect_vec_near(in.imposed_velocity({0.01, 0, 0.1}), {0.5, 0, 0}, 1e-7);   // into +x
  expect_vec_near(out.imposed_velocity({0.99, 0, 0.1}), {0.4, 0, 0}, 1e-7);  // out at xmax
  // The other faces: an inlet at xmax pushes towards -x, an outlet at xmin draws towards -x.
  in.inward = -1, in.plane = 0.97;
  out.inward = 1, out.plane = 0.03;
  expect_vec_near(in.imposed_velocity({0.99, 0, 0.1}), {-0.5, 0, 0}, 1e-7);
  expect_vec_near(out.imposed_velocity({0.01, 0, 0.1}), {-0.4, 0, 0}, 1e-7);
  // An inlet through the bottom pushes up.
  OpenBoundaryZone bottom = inlet_xmin();
  bottom.axis = 2;
  expect_vec_near(bottom.imposed_velocity({0.5, 0.5, 0.01}), {0, 0, 0.5}, 1e-7);
}

TEST(OpenBoundary, ProfileIsPiecewiseLinearInZAndClamped) {
  OpenBoundaryZone in = inlet_xmin();
  in.speed = 9;  // ignored when a profile is given
  in.profile_z = {0.0, 0.1, 0.3};
  in.profile_u = {0.0, 1.0, 0.5};
  auto u = [&](double z) { return in.imposed_velocity({0.01, 0, z}).x; };
  EXPECT_NEAR(u(0.0), 0.0, 1e-7);
  EXPECT_NEAR(u(0.05), 0.5, 1e-6);
  EXPECT_NEAR(u(0.1), 1.0, 1e-6);
  EXPECT_NEAR(u(0.2), 0.75, 1e-6);
  EXPECT_NEAR(u(0.27), 0.575, 1e-6);
  EXPECT_NEAR(u(0.3), 0.5, 1e-6);
  EXPECT_NEAR(u(-1.0), 0.0, 1e-7);  // below the first point: its value
  EXPECT_NEAR(u(5.0), 0.5, 1e-6);   // above the last point: its value
  EXPECT_EQ(in.imposed_velocity({0.01, 0, 0.2}).y, 0.0f);
  EXPECT_EQ(in.imposed_velocity({0.01, 0, 0.2}).z, 0.0f);
  // At the xmax face the same profile points towards -x.
  in.inward = -1, in.plane = 0.97;
  EXPECT_NEAR(in.imposed_velocity({0.99, 0, 0.2}).x, -0.75, 1e-6);
}

TEST(OpenBoundary, ZoneContaining) {
  const std::vector<OpenBoundaryZone> zones = {outlet_xmax(), inlet_xmin()};
  EXPECT_EQ(zone_containing(zones, {0.01, 0, 0.1}), 1);
  EXPECT_EQ(zone_containing(zones, {0.03, 0, 0.1}), 1);  // on the interface: inside
  EXPECT_EQ(zone_containing(zones, {0.0, 0, 0.1}), 1);   // on the face: inside
  EXPECT_EQ(zone_containing(zones, {0.985, 0, 0.1}), 0);
  EXPECT_EQ(zone_containing(zones, {0.5, 0, 0.1}), -1);
  EXPECT_EQ(zone_containing(zones, {0.031, 0, 0.1}), -1);
  EXPECT_EQ(zone_containing(zones, {-0.001, 0, 0.1}), -1);  // beyond the face
  EXPECT_EQ(zone_containing(zones, {1.001, 0, 0.1}), -1);
  EXPECT_EQ(zone_containing({}, {0.01, 0, 0.1}), -1);
}

TEST(OpenBoundary, UpdateConvertsCreatesAndRemoves) {
  // Zone 0: outlet at xmax, zone 1: inlet at xmin (surface at z = 0.2).
  const std::vector<OpenBoundaryZone> zones = {outlet_xmax(), inlet_xmin()};
  ParticleSet p;
  const Vec3f v_in{0.5f, 0, 0.01f};
  p.add({0.035, 0, 0.1}, v_in, 1001, ParticleKind::Buffer, 1);         // 0 crossed in
  p.add({0.04, 0, 0.25}, v_in, 1001, ParticleKind::Buffer, 1);         // 1 crossed, dry
  p.add({0.02, 0, 0.1}, v_in, 1001, ParticleKind::Buffer, 1);          // 2 stays
  p.add({1.005, 0, 0.1}, {0.4f, 0, 0}, 999, ParticleKind::Buffer, 0);  // 3 left domain
  p.add({0.98, 0, 0.1}, {0.4f, 0, 0}, 999, ParticleKind::Fluid);       // 4 absorbed
  p.add({0.5, 0, 0.1}, {0.4f, 0, 0}, 999, ParticleKind::Fluid);        // 5 stays fluid
  p.add({0.96, 0, 0.1}, {-0.1f, 0, 0}, 999, ParticleKind::Buffer, 0);  // 6 back to fluid
  p.add({0.01, 0, 0.1}, {}, 1000, ParticleKind::Wall, 3);              // 7 wall: untouched
  p.add({0.01, 0, 0.12}, {-0.2f, 0, 0}, 1000, ParticleKind::Fluid);    // 8 backflow
  p.add({-0.005, 0, 0.1}, v_in, 1001, ParticleKind::Buffer, 1);        // 9 left at inlet
  const std::size_t n0 = p.size();
  const std::uint32_t next0 = p.next_id;
  const std::size_t fluid0 = p.count(ParticleKind::Fluid), buffer0 = p.count(ParticleKind::Buffer);

  const OpenBoundaryCounts c = update_open_boundary_particles(p, zones);
  EXPECT_EQ(c.entered_fluid, 3u);  // 0, 1, 6
  EXPECT_EQ(c.created, 1u);        // behind 0 only (1 is above the surface, 6 is at an outlet)
  EXPECT_EQ(c.removed, 2u);        // 3, 9
  EXPECT_EQ(c.absorbed, 2u);       // 4, 8
  ASSERT_EQ(p.size(), n0 + c.created);

  using K = ParticleKind;
  const K kinds[] = {K::Fluid, K::Fluid, K::Buffer, K::Buffer, K::Buffer,
                     K::Fluid, K::Fluid, K::Wall,   K::Buffer, K::Buffer};
  const std::uint32_t groups[] = {0, 0, 1, 0, 0, 0, 0, 3, 1, 1};
  for (std::size_t i = 0; i < n0; ++i) {
    EXPECT_EQ(p.kind[i], kinds[i]) << i;
    EXPECT_EQ(p.group[i], groups[i]) << i;
  }
  // Removed particles get NaN positions; the others do not move.
  EXPECT_TRUE(std::isnan(p.pos[3].x) && std::isnan(p.pos[3].y) && std::isnan(p.pos[3].z));
  EXPECT_TRUE(std::isnan(p.pos[9].x));
  EXPECT_EQ(p.pos[0].x, 0.035);
  EXPECT_EQ(p.pos[4].x, 0.98);

  // The new buffer particle: one buffer width behind particle 0, in the inlet zone (group 1),
  // with a fresh id.
  const std::size_t nw = n0;
  EXPECT_EQ(p.kind[nw], ParticleKind::Buffer);
  EXPECT_EQ(p.group[nw], 1u);
  EXPECT_NEAR(p.pos[nw].x, 0.035 - 0.03, 1e-15);
  EXPECT_EQ(p.pos[nw].y, 0.0);
  EXPECT_EQ(p.pos[nw].z, 0.1);
  EXPECT_EQ(zone_containing(zones, p.pos[nw]), 1);
  EXPECT_EQ(p.id[nw], next0);
  EXPECT_EQ(p.next_id, next0 + 1);
  const std::set<std::uint32_t> ids(p.id.begin(), p.id.end());
  EXPECT_EQ(ids.size(), p.size()) << "ids must be unique";

  // Counts: fluid gains entered - absorbed; buffers gain absorbed + created - entered (the
  // removed ones are still buffer particles until the sort drops them).
  EXPECT_EQ(p.count(K::Fluid), fluid0 + c.entered_fluid - c.absorbed);
  EXPECT_EQ(p.count(K::Buffer), buffer0 + c.absorbed + c.created - c.entered_fluid);
  EXPECT_EQ(p.count(K::Wall), 1u);

  // A second pass changes nothing: all particles are where their kind says.
  const OpenBoundaryCounts again = update_open_boundary_particles(p, zones);
  EXPECT_EQ(again.entered_fluid, 0u);
  EXPECT_EQ(again.created, 0u);
  EXPECT_EQ(again.absorbed, 0u);
}

TEST(OpenBoundary, NoZonesNoChange) {
  ParticleSet p;
  p.add({0.01, 0, 0.1}, {}, 1000, ParticleKind::Fluid);
  const OpenBoundaryCounts c = update_open_boundary_particles(p, {});
  EXPECT_EQ(c.entered_fluid + c.created + c.removed + c.absorbed, 0u);
  EXPECT_EQ(p.size(), 1u);
  EXPECT_EQ(p.kind[0], ParticleKind::Fluid);
}

TEST(OpenBoundary, InletKeepsItsBufferFilledOverManySteps) {
  // A column of buffer particles moved at the inlet speed: every particle that crosses the
  // interface is replaced, so the buffer always holds the same number of particles.
  const double dp = 0.01;
  OpenBoundaryZone in = inlet_xmin();
  in.surface_z = 1e9;
  const std::vector<OpenBoundaryZone> zones = {in};
  ParticleSet p;
  for (int k = 0; k < 5; ++k)
    for (int i = 0; i < 3; ++i)
      p.add({(i + 0.5) * dp, 0, (k + 0.5) * dp}, {0.5f, 0, 0}, 1000, ParticleKind::Buffer, 0);
  const double dt = 0.004;  // 0.2 dp per step
  std::size_t created = 0;
  for (int step = 0; step < 50; ++step) {
    for (std::size_t i = 0; i < p.size(); ++i) p.pos[i].x += 0.5 * dt;
    created += update_open_boundary_particles(p, zones).created;
    EXPECT_EQ(p.count(ParticleKind::Buffer), 15u) << step;
  }
  // 50 steps * 0.2 dp = 10 dp advanced over 5 rows: 50 particles entered the fluid.
  EXPECT_EQ(created, 50u);
  EXPECT_EQ(p.count(ParticleKind::Fluid), 50u);
}

TEST(OpenBoundary, BufferParticlesStayInTheHalfOpenRangeThePeriodicWrapKeeps) {
  // Domain [0, 0.5] in x, periodic: the wrap keeps x in [0, 0.5) and carries x = 0.5 to 0.
  // A buffer 0.04 wide at xmax: its interface 0.5 - 0.04 rounds so that a particle exactly on
  // the face is 0.04 - 2e-17 deep, inside the buffer by depth.
  OpenBoundaryZone out = outlet_xmax();
  out.face = 0.5;
  out.width = 0.04;
  out.plane = out.face + out.inward * out.width;
  const Vec3d on_face{0.5, 0, 0.1};
  ASSERT_LT(out.depth(on_face), out.width);
  ASSERT_EQ(wrapped_into_period(on_face.x, 0.0, 0.5), 0.0);
  // On the max face a particle has left, outlet or inlet (flow towards -x): wrapped, it
  // would turn into fluid at x = 0. On the min face, x = 0 is inside.
  OpenBoundaryZone in = out;
  in.inlet = true;
  in.surface_z = 1;
  OpenBoundaryZone low = outlet_xmax();
  low.inward = 1, low.face = 0, low.width = 0.04, low.plane = 0.04;
  const std::vector<OpenBoundaryZone> zones = {out, in, low};
  ParticleSet p;
  p.add(on_face, {0.4f, 0, 0}, 1000, ParticleKind::Buffer, 0);
  p.add({0.49, 0, 0.1}, {0.4f, 0, 0}, 1000, ParticleKind::Buffer, 0);  // inside: stays
  p.add(on_face, {-0.4f, 0, 0}, 1000, ParticleKind::Buffer, 1);
  p.add({0.0, 0, 0.1}, {-0.4f, 0, 0}, 1000, ParticleKind::Buffer, 2);  // on the min face: stays
  const OpenBoundaryCounts c = update_open_boundary_particles(p, zones);
  EXPECT_EQ(c.removed, 2u);
  EXPECT_TRUE(std::isnan(p.pos[0].x));
  EXPECT_EQ(p.pos[1].x, 0.49);
  EXPECT_TRUE(std::isnan(p.pos[2].x));
  EXPECT_EQ(p.pos[3].x, 0.0);
  // A particle created one width behind one that only just entered the fluid lands inside
  // the range, however the subtraction rounds: below 0.5 at the max face, at or above 0 at
  // the min face.
  OpenBoundaryZone in_low = low;
  in_low.inlet = true;
  for (double x = out.plane, k = 0; k < 64; ++k) {
    x = std::nextafter(x, -1.0);  // just across the max face's interface, into the fluid
    EXPECT_LT(created_buffer_position(in.geometry(), {x, 0, 0.1}).x, 0.5) << k;
  }
  for (double x = in_low.plane, k = 0; k < 64; ++k) {
    x = std::nextafter(x, 1.0);
    EXPECT_GE(created_buffer_position(in_low.geometry(), {x, 0, 0.1}).x, 0.0) << k;
  }
  // Put on the face (0.46 + 0.04 rounds to 0.5), it is moved just inside.
  ASSERT_EQ(0.46 + 0.04, 0.5);
  EXPECT_EQ(created_buffer_position(in.geometry(), {0.46, 0, 0.1}).x, std::nextafter(0.5, 0.0));
}

// ---------------------------------------------------------------------------------------------
// Wall velocity history

TEST(VelocityHistory, EmptyIsAtRest) {
  const VelocityHistory m;
  EXPECT_FALSE(m.moving());
  for (double t : {-1.0, 0.0, 3.5}) expect_vec_near(m.at(t), {0, 0, 0}, 0);
}

TEST(VelocityHistory, OnePointIsConstant) {
  VelocityHistory m;
  m.times = {0.0};
  m.velocities = {{0.3, 0, -0.1}};
  EXPECT_TRUE(m.moving());
  for (double t : {-1.0, 0.0, 0.5, 100.0}) expect_vec_near(m.at(t), {0.3, 0, -0.1}, 0);
}

TEST(VelocityHistory, LinearInterpolationHeldAtTheEnds) {
  VelocityHistory m;
  m.times = {0.5, 1.0, 3.0};
  m.velocities = {{0, 0, 0}, {1, 0, 2}, {1, -2, 0}};
  expect_vec_near(m.at(0.0), {0, 0, 0}, 1e-15);  // held before the first time
  expect_vec_near(m.at(0.5), {0, 0, 0}, 1e-15);
  expect_vec_near(m.at(0.75), {0.5, 0, 1}, 1e-12);
  expect_vec_near(m.at(1.0), {1, 0, 2}, 1e-12);
  expect_vec_near(m.at(2.0), {1, -1, 1}, 1e-12);
  expect_vec_near(m.at(2.5), {1, -1.5, 0.5}, 1e-12);
  expect_vec_near(m.at(3.0), {1, -2, 0}, 1e-12);
  expect_vec_near(m.at(10.0), {1, -2, 0}, 1e-15);  // held after the last time
  // Continuous across the knots.
  for (double t : {1.0, 3.0}) expect_vec_near(m.at(t - 1e-9), m.at(t + 1e-9), 1e-8);
}

}  // namespace
}  // namespace netsph
