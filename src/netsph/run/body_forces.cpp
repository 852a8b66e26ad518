#include "netsph/run/body_forces.hpp"

#include <algorithm>
#include <map>

#include "netsph/core/error.hpp"

namespace netsph {

std::vector<ForceGroup> force_groups(const Simulation& sim) {
  std::vector<ForceGroup> groups;
  std::map<std::string, std::size_t> index;
  const auto& bodies = sim.bodies();
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const auto [it, added] = index.emplace(bodies[b].group, groups.size());
    if (added) groups.push_back({bodies[b].group, {}, {}, {}, {}});
    ForceGroup& g = groups[it->second];
    g.bodies.push_back(b);
    const BodySpec& spec = sim.spec().bodies[b];
    if (!g.reference_velocity && spec.reference_velocity) {
      g.reference_velocity = spec.reference_velocity;
      g.reference_area = spec.reference_area;
    }
  }
  // The bodies' centres as the case places them (not where they are now: a restarted run
  // must measure moments about the same point as the run it continues).
  for (auto& g : groups) {
    for (std::size_t b : g.bodies) {
      Vec3d c = sim.spec().bodies[b].center;
      if (sim.model().dims == 2) c.y = 0;
      g.reference_point += c;
    }
    g.reference_point = g.reference_point / static_cast<double>(g.bodies.size());
  }
  return groups;
}

GroupLoad group_load(const Simulation& sim, const ForceGroup& g) {
  GroupLoad load;
  for (std::size_t b : g.bodies) {
    const RigidBody& body = sim.bodies()[b];
    // What the bodies take from the water: the resolved fluid's force and the modelled
    // drag of their unresolved parts (a net's sinker bar), as a load cell reads them both.
    const Vec3d force = body.fluid_force + body.modelled_force;
    load.force += force;
    load.moment +=
        body.fluid_torque + body.modelled_torque + cross(body.state.com - g.reference_point, force);
  }
  if (g.reference_velocity && g.reference_area) {
    const double u = *g.reference_velocity;
    load.cd = load.force.x / (0.5 * sim.model().eos.rho0 * u * u * *g.reference_area);
  }
  return load;
}

BodyForceRecorder::BodyForceRecorder(const Simulation& sim, double window_start, double window_end)
    : groups_(force_groups(sim)),
      t0_(window_start),
      t1_(window_end),
      dims_(sim.model().dims),
      sums_(groups_.size()) {}

ForceUnits force_units(int dims) {
  // 2D particles carry mass per metre of depth (rho dp^2): forces per metre, moments N m/m.
  return dims == 2 ? ForceUnits{"N/m", "N"} : ForceUnits{"N", "N m"};
}

std::vector<CsvColumn> BodyForceRecorder::series_columns() const {
  std::vector<CsvColumn> cols;
  for (const auto& g : groups_) {
    const ForceUnits u = force_units(dims_);
    for (const char* c : {"Fx", "Fy", "Fz"}) cols.push_back({g.name + "_" + c, u.force});
    for (const char* c : {"Mx", "My", "Mz"}) cols.push_back({g.name + "_" + c, u.moment});
    if (g.reference_velocity) cols.push_back({g.name + "_Cd", ""});
  }
  return cols;
}

void BodyForceRecorder::append_series_values(const Simulation& sim,
                                             std::vector<double>& row) const {
  for (const auto& g : groups_) {
    const GroupLoad l = group_load(sim, g);
    for (int a = 0; a < 3; ++a) row.push_back(l.force[a]);
    for (int a = 0; a < 3; ++a) row.push_back(l.moment[a]);
    if (g.reference_velocity) row.push_back(l.cd);
  }
}

void BodyForceRecorder::accumulate(const Simulation& sim) {
  const double t = sim.time(), dt = sim.last_dt();
  if (t < t0_ || t > t1_ || !(dt > 0)) return;
  for (std::size_t k = 0; k < groups_.size(); ++k) {
    const GroupLoad l = group_load(sim, groups_[k]);
    sums_[k].force += l.force * dt;
    sums_[k].moment += l.moment * dt;
    sums_[k].cd += l.cd * dt;
  }
  weight_ += dt;
}

nlohmann::json BodyForceRecorder::summary() const {
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t k = 0; k < groups_.size(); ++k) {
    const ForceGroup& g = groups_[k];
    nlohmann::json j;
    j["group"] = g.name;
    j["bodies"] = g.bodies.size();
    j["window_s"] = {t0_, t1_};
    j["averaged_over_s"] = weight_;
    if (weight_ > 0) {
      const Vec3d f = sums_[k].force / weight_, m = sums_[k].moment / weight_;
      // The keys keep their 3D names; in 2D the values are per metre of depth (the units).
      j["force_N"] = {f.x, f.y, f.z};
      j["moment_N_m"] = {m.x, m.y, m.z};
      const ForceUnits u = force_units(dims_);
      j["force_unit"] = u.force;
      j["moment_unit"] = u.moment;
      if (g.reference_velocity) {
        j["cd"] = sums_[k].cd / weight_;
        j["reference_velocity_m_s"] = *g.reference_velocity;
        j["reference_area"] = *g.reference_area;
      }
    }
    j["moment_reference_point_m"] = {g.reference_point.x, g.reference_point.y, g.reference_point.z};
    out.push_back(j);
  }
  return out;
}

std::vector<double> BodyForceRecorder::state() const {
  std::vector<double> s;
  for (const GroupLoad& l : sums_) {
    for (int a = 0; a < 3; ++a) s.push_back(l.force[a]);
    for (int a = 0; a < 3; ++a) s.push_back(l.moment[a]);
    s.push_back(l.cd);
  }
  s.push_back(weight_);
  return s;
}

void BodyForceRecorder::restore(const std::vector<double>& s) {
  if (s.size() != 7 * sums_.size() + 1) throw Error("checkpoint", "force groups differ");
  for (std::size_t k = 0; k < sums_.size(); ++k) {
    const double* v = s.data() + 7 * k;
    sums_[k].force = {v[0], v[1], v[2]};
    sums_[k].moment = {v[3], v[4], v[5]};
    sums_[k].cd = v[6];
  }
  weight_ = s.back();
}

std::vector<CsvColumn> body_state_columns(int dims) {
  const std::string f = force_units(dims).force, m = force_units(dims).moment;
  return {{"time", "s"},    {"body", ""},  {"x", "m"},    {"y", "m"},        {"z", "m"},
          {"vx", "m/s"},    {"vy", "m/s"}, {"vz", "m/s"}, {"qw", ""},        {"qx", ""},
          {"qy", ""},       {"qz", ""},    {"Fx", f},     {"Fy", f},         {"Fz", f},
          {"Mx", m},        {"My", m},     {"Mz", m},     {"contact_Fx", f}, {"contact_Fy", f},
          {"contact_Fz", f}};
}

void append_body_rows(const Simulation& sim, CsvSeries& csv) {
  const auto& bodies = sim.bodies();
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const RigidBody& r = bodies[b];
    // Contact moves only a floating body; a fixed or prescribed one (a flap against the bed it
    // turns on) touches walls by design, and the contact model's push there means nothing.
    const Vec3d contact = r.motion == BodyMotion::Floating ? r.contact_force : Vec3d{};
    const double row[] = {sim.time(),       static_cast<double>(b),
                          r.state.com.x,    r.state.com.y,
                          r.state.com.z,    r.state.vel.x,
                          r.state.vel.y,    r.state.vel.z,
                          r.state.q.w,      r.state.q.x,
                          r.state.q.y,      r.state.q.z,
                          r.fluid_force.x,  r.fluid_force.y,
                          r.fluid_force.z,  r.fluid_torque.x,
                          r.fluid_torque.y, r.fluid_torque.z,
                          contact.x,        contact.y,
                          contact.z};
    csv.append(row);
  }
}

}  // namespace netsph
