#pragma once
// Rigid bodies made of boundary particles (Monaghan et al. 2003; Canelas et al. 2015 as
// DualSPHysics treats floating objects): the fluid force and torque on a body are the sums of
// m_i a_i over its particles; a floating body then moves in 6 degrees of freedom (3 in 2D:
// x, z and the rotation about y) with the same symplectic stages as the fluid, and its
// particles follow it rigidly.
//
//   predictor:  c* = c + dt/2 V          V* = V + dt/2 A^n
//               q* = rot(dt/2 w) q       w* = w + dt/2 alpha^n
//   corrector:  V' = V + dt A*           c' = c + dt/2 (V + V')
//               w' = w + dt alpha*       q' = rot(dt/2 (w + w')) q
//   A = F / M + g,  alpha = R I^-1 (R^T T - w_b x I w_b)   (Euler's equations, body frame)
#include <cstdint>
#include <string>
#include <vector>

#include "netsph/core/host_device.hpp"
#include "netsph/core/periodic_image.hpp"
#include "netsph/core/physics_options.hpp"
#include "netsph/core/quaternion.hpp"
#include "netsph/core/vec3.hpp"

namespace netsph {

struct RigidState {
  Vec3d com{};    ///< centre of mass, m
  Quat q{};       ///< body frame -> world frame
  Vec3d vel{};    ///< m/s
  Vec3d omega{};  ///< rad/s, world frame
};

struct RigidInertia {
  double mass = 0;    ///< kg (kg/m in 2D)
  Vec3d principal{};  ///< principal moments about the centre, body frame, kg m^2
  int dims = 3;
};

/// Linear and angular acceleration from the total force and torque (about the centre).
struct RigidAcceleration {
  Vec3d linear{};
  Vec3d angular{};
};

NETSPH_HD RigidAcceleration rigid_acceleration(const RigidInertia& in, const RigidState& s,
                                               const Vec3d& force, const Vec3d& torque,
                                               const Vec3d& gravity) {
  RigidAcceleration a;
  a.linear = force / in.mass + gravity;
  if (in.dims == 2) {
    // Motion in the x-z plane: no y translation, rotation about y only.
    a.linear.y = 0;
    a.angular = {0, torque.y / in.principal.y, 0};
    return a;
  }
  const Vec3d wb = rotate_inverse(s.q, s.omega), tb = rotate_inverse(s.q, torque);
  const Vec3d iw{in.principal.x * wb.x, in.principal.y * wb.y, in.principal.z * wb.z};
  const Vec3d rhs = tb - cross(wb, iw);
  a.angular =
      rotate(s.q, Vec3d(rhs.x / in.principal.x, rhs.y / in.principal.y, rhs.z / in.principal.z));
  return a;
}

NETSPH_HD RigidState rigid_predict(const RigidState& s0, const RigidAcceleration& a, double dt) {
  RigidState s;
  s.com = s0.com + s0.vel * (0.5 * dt);
  s.vel = s0.vel + a.linear * (0.5 * dt);
  s.q = normalized(Quat::from_rotation_vector(s0.omega * (0.5 * dt)) * s0.q);
  s.omega = s0.omega + a.angular * (0.5 * dt);
  return s;
}

NETSPH_HD RigidState rigid_correct(const RigidState& s0, const RigidAcceleration& a_half,
                                   double dt) {
  RigidState s;
  s.vel = s0.vel + a_half.linear * dt;
  s.com = s0.com + (s0.vel + s.vel) * (0.5 * dt);
  s.omega = s0.omega + a_half.angular * dt;
  s.q = normalized(Quat::from_rotation_vector((s0.omega + s.omega) * (0.5 * dt)) * s0.q);
  return s;
}

/// Velocity of a body point at world offset r from the centre.
NETSPH_HD Vec3d rigid_point_velocity(const RigidState& s, const Vec3d& r) {
  return s.vel + cross(s.omega, r);
}

/// A body particle's lever arm: its world offset from the centre of mass. The centre follows
/// the body without being wrapped into periodic axes; the particle is wrapped with the fluid,
/// so the offset is taken at its nearest image (`period`: domain length along periodic axes,
/// else 0). Unique while the body is narrower than half a period (checked at set-up,
/// body_wider_than_half_period).
NETSPH_HD Vec3d rigid_lever_arm(const RigidState& s, const Vec3d& pos, const Vec3d& period) {
  return nearest_image_offset(pos - s.com, period);
}

/// A body particle's mDBC ghost vector in the world frame from its body-frame one.
NETSPH_HD Vec3f rigid_ghost(const RigidState& s, const Vec3f& ghost_offset, int dims) {
  Vec3d g = rotate(s.q, Vec3d(ghost_offset));
  if (dims == 2) g.y = 0;  // rotation round-off must not leave the x-z plane
  return Vec3f(g);
}

/// Places one body particle on its body's state: world position from its body-frame offset,
/// the rotated mDBC ghost vector, and (when the body shows its own velocity) the rigid
/// velocity there. Returns the displacement squared from where it was. Both backends place
/// body particles through this.
///
/// Along a periodic axis (`period` > 0) the particle goes to the image of centre + offset
/// nearest where it was: the neighbour search finds it through the cell it was sorted into
/// (positions are wrapped only when sorting), whatever number of periods the centre has
/// travelled, so a body may cross a periodic end.
NETSPH_HD double place_rigid_particle(const RigidState& s, const Vec3f& offset,
                                      const Vec3f& ghost_offset, int dims, bool shows_own_velocity,
                                      const Vec3d& period, Vec3d& pos, Vec3f& vel, Vec3f& ghost) {
  Vec3d r = rotate(s.q, Vec3d(offset));
  if (dims == 2) r.y = 0;  // rotation round-off must not leave the x-z plane
  const Vec3d previous = pos;
  pos = s.com + r;
  pos -= nearest_image_correction(pos - previous, period);
  if (shows_own_velocity) vel = Vec3f(rigid_point_velocity(s, r));
  ghost = rigid_ghost(s, ghost_offset, dims);
  const Vec3d d = pos - previous;
  return d.x * d.x + d.y * d.y + d.z * d.z;
}

/// One rigid body: its kinematics, mass properties and particles (ids first_id ..
/// first_id + count - 1, with their body-frame offsets and mDBC ghost vectors).
struct RigidBody {
  std::string name;
  std::string group;
  BodyMotion motion = BodyMotion::Fixed;
  WallModel model = WallModel::Mdbc;
  WallSlip slip = WallSlip::WallVelocity;
  RigidInertia inertia;
  RigidState state, start;  ///< current, and at the start of the step
  std::uint32_t first_id = 0, count = 0;
  std::vector<Vec3f> offsets;                 ///< body frame, from the centre of mass
  std::vector<Vec3f> ghosts;                  ///< body frame, particle -> ghost node (mDBC)
  Vec3d fluid_force{}, fluid_torque{};        ///< last stage, world frame, torque about com
  Vec3d contact_force{}, contact_torque{};    ///< from walls and other bodies
  Vec3d external_force{}, external_torque{};  ///< hooks (twines, sinkers)
  /// Hydrodynamic load on parts too small to resolve that move with the body (a net knot's
  /// share of the sinker bar, solver/net_coupling.hpp), from a model; torque about com.
  Vec3d modelled_force{}, modelled_torque{};
  bool shows_own_velocity() const {
    return model == WallModel::Dbc || slip == WallSlip::WallVelocity;
  }
};

}  // namespace netsph
