#include "netsph/solver/net_coupling.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "netsph/net/current_loads.hpp"
#include "netsph/net/knot_spring_solver.hpp"
#include "netsph/net/net_generator.hpp"

namespace netsph {
namespace {

BodySpec knot_body(const NetSpec& net_spec, const NetModel& net, const NetKnot& k) {
  BodySpec b;
  b.name = fmt::format("{}.knot{}_{}", net.name, k.row, k.column);
  b.group = net.name;
  b.where = net_spec.where;
  b.center = k.position;
  // Local x along the net normal (plate thickness), y across, z up.
  b.orientation = Quat::from_frame(net.normal, net.across, net.up);
  b.shape_name = std::string(name_of(k.geometry.shape));
  switch (k.geometry.shape) {
    case KnotShape::SquarePlate:
      b.shape = BodyShape::Box;
      b.lengths = {k.geometry.thickness, k.geometry.size, k.geometry.size};
      break;
    case KnotShape::CircularPlate:
      b.shape = BodyShape::Cylinder;
      b.diameter = k.geometry.size;
      b.length = k.geometry.thickness;
      break;
    case KnotShape::Sphere:
      b.shape = BodyShape::Sphere;
      b.diameter = k.geometry.size;
      break;
  }
  b.motion = k.fixed ? BodyMotion::Fixed : BodyMotion::Floating;
  b.mass = k.mass;
  b.layers = -1;  // knots are thin: solid
  // Cd of the whole net on its outline (force groups take the first body's reference).
  b.reference_velocity = net_spec.reference_velocity;
  b.reference_area = net_spec.width * net_spec.height;
  return b;
}

}  // namespace

CaseSpec spec_with_net_knots(const CaseSpec& spec) {
  CaseSpec expanded = spec;
  if (spec.net_only()) return expanded;
  const NetEnvironment env = net_environment(spec);
  for (const NetSpec& ns : spec.nets) {
    const NetModel net = generate_net(ns, env);
    for (const NetKnot& k : net.knots) expanded.bodies.push_back(knot_body(ns, net, k));
  }
  return expanded;
}

std::vector<CoupledNet> coupled_nets(const CaseSpec& expanded) {
  std::vector<CoupledNet> nets;
  if (expanded.net_only() || expanded.nets.empty()) return nets;
  const NetEnvironment env = net_environment(expanded);
  std::size_t knots = 0;
  for (const NetSpec& ns : expanded.nets) {
    CoupledNet c;
    c.model = generate_net(ns, env);
    knots += c.model.knots.size();
    for (const NetKnot& k : c.model.knots) c.initial.push_back(k.position);
    c.water_density = env.water_density;
    c.reaction_offset =
        kSinkerReactionOffsetSupports * 2 * expanded.simulation.h_over_dp * expanded.simulation.dp;
    c.sinker_flow.assign(c.model.knots.size(), Vec3d{});
    c.sinker_wet.assign(c.model.knots.size(), 0);
    c.sinker_stage_drag.assign(c.model.knots.size(), Vec3d{});
    nets.push_back(std::move(c));
  }
  std::size_t first = expanded.bodies.size() - knots;
  for (CoupledNet& c : nets) {
    c.first_body = first;
    first += c.model.knots.size();
  }
  return nets;
}

void buoy_resolved_knots_by_their_particles(std::vector<CoupledNet>& nets,
                                            const std::vector<RigidBody>& bodies,
                                            const CaseSpec& expanded) {
  const NetEnvironment env = net_environment(expanded);
  if (env.knot_buoyancy) return;  // the constant force carries the whole buoyancy
  const double dp = expanded.simulation.dp;
  const double cell = dp * dp * dp;  // nets are 3D
  for (CoupledNet& c : nets) {
    for (std::size_t k = 0; k < c.model.knots.size(); ++k) {
      NetKnot& knot = c.model.knots[k];
      const double lattice = static_cast<double>(bodies.at(c.first_body + k).count) * cell;
      const double assumed = resolved_knot_volume(knot.geometry, env.resolved_dp);
      // The generator added rho g V_assumed (down) against the water's rho g V_assumed (up);
      // the water gives rho g V_lattice.
      knot.constant_force += env.gravity * (env.water_density * (lattice - assumed));
    }
  }
}

namespace {

/// One knot's share of a sinker bar at the stage being sampled.
struct SinkerShare {
  CoupledNet* net;
  std::size_t knot;
  SinkerSamples samples;
  /// Where its reaction goes if none goes downstream: its wet sample points on the bar (at
  /// most as many as its samples; a fixed array, as theirs: no allocation per stage).
  CoupledNet::ReactionPoint at_bar[sizeof(SinkerSamples::points) / sizeof(Vec3d)];
  int at_bar_count = 0;
};

/// CoupledNet::sinker_reach from the shares' flows: points along each wet share, moved
/// downstream, sampled for the fluid's mass weight there; a share with no water downstream
/// (or no drag direction yet: the sub-steps may still give it drag) gives its reaction at
/// its wet sample points on the bar instead.
void place_sinker_reactions(const std::vector<SinkerShare>& shares, const FluidSampler& sample) {
  // Each wet share's line along the bar (end, the bar at the knot, end: the ends are its
  // sample points'), cut into pieces at most reaction_spacing long, a point at each piece's
  // middle weighted by its length, moved downstream along the share's drag.
  struct Candidate {
    const SinkerShare* share;
    Vec3d point;
    double length;
  };
  std::vector<Candidate> candidates;
  for (const SinkerShare& s : shares) {
    CoupledNet& c = *s.net;
    const NetModel& net = c.model;
    const NetKnot& knot = net.knots[s.knot];
    if (!c.sinker_wet[s.knot]) continue;
    // Only the drag's direction matters here (hence unit density).
    const Vec3d drag = sinker_drag(net, knot, c.sinker_flow[s.knot], 1.0);
    if (!(norm(drag) > 0)) {
      c.sinker_reach.insert(c.sinker_reach.end(), s.at_bar, s.at_bar + s.at_bar_count);
      continue;
    }
    const Vec3d downstream = drag * (c.reaction_offset / norm(drag));
    const Vec3d here = sinker_point(net, knot);
    Vec3d line[3];
    int n = 0;
    line[n++] = here;
    for (int i = 0; i < s.samples.count; ++i) {
      if (norm(s.samples.points[i] - here) > 0) line[n++] = s.samples.points[i];
    }
    if (n == 3) std::swap(line[0], line[1]);  // end -> here -> end
    for (int seg = 0; seg + 1 < n; ++seg) {
      const Vec3d a = line[seg], b = line[seg + 1];
      const double length = norm(b - a);
      const int pieces = c.reaction_spacing > 0
                             ? std::max(1, static_cast<int>(std::ceil(length / c.reaction_spacing)))
                             : 1;
      for (int piece = 0; piece < pieces; ++piece) {
        candidates.push_back(
            {&s, a + (b - a) * ((piece + 0.5) / pieces) + downstream, length / pieces});
      }
    }
  }
  if (candidates.empty()) return;
  // The fluid's mass weight sum_j m_j W at each point (sum V W rho, sph/shepard.hpp); points
  // out of the water take no part, the share's wet points share its reaction by length.
  std::vector<Vec3d> points;
  points.reserve(candidates.size());
  for (const Candidate& cand : candidates) points.push_back(cand.point);
  std::vector<ShepardValue> there(points.size());
  sample(points, there);
  for (std::size_t first = 0; first < candidates.size();) {
    const SinkerShare& s = *candidates[first].share;
    std::size_t end = first;
    double wet = 0;
    for (; end < candidates.size() && candidates[end].share == &s; ++end) {
      if (there[end].coverage >= kSinkerWetCoverage) wet += candidates[end].length;
    }
    std::vector<CoupledNet::ReactionPoint>& reach = s.net->sinker_reach;
    if (!(wet > 0)) {
      reach.insert(reach.end(), s.at_bar, s.at_bar + s.at_bar_count);
      if (s.net->reactions_at_bar++ == 0) s.net->first_knot_reacting_at_bar = s.knot;
    }
    for (std::size_t i = first; i < end && wet > 0; ++i) {
      if (there[i].coverage < kSinkerWetCoverage) continue;
      const double mass_weight = there[i].coverage * there[i].density;
      reach.push_back({s.knot, candidates[i].point, candidates[i].length / wet / mass_weight});
    }
    first = end;
  }
}

}  // namespace

void sample_sinker_flows(std::vector<CoupledNet>& nets, const std::vector<RigidBody>& bodies,
                         const FluidSampler& sample) {
  std::vector<SinkerShare> shares;
  std::vector<Vec3d> points;
  for (CoupledNet& c : nets) {
    c.sinker_reach.clear();
    NetModel& net = c.model;
    for (std::size_t k = 0; k < net.knots.size(); ++k) {
      net.knots[k].position = bodies[c.first_body + k].state.com;
      net.knots[k].velocity = bodies[c.first_body + k].state.vel;
    }
    for (std::size_t k = 0; k < net.knots.size(); ++k) {
      if (net.knots[k].sinker_length <= 0) continue;
      SinkerShare& s = shares.emplace_back(SinkerShare{&c, k, {}, {}, 0});
      sinker_sample_points(net, net.knots[k], s.samples);
      points.insert(points.end(), s.samples.points, s.samples.points + s.samples.count);
    }
  }
  if (points.empty()) return;
  std::vector<ShepardValue> values(points.size());
  sample(points, values);
  // Each share's flow: the weighted mean over its points in the water; those points, by their
  // weights over the mass weights there, are where its reaction goes if none goes downstream.
  const ShepardValue* v = values.data();
  for (SinkerShare& s : shares) {
    Vec3d sum{};
    double weight = 0;
    for (int i = 0; i < s.samples.count; ++i, ++v) {
      if (v->coverage < kSinkerWetCoverage) continue;
      sum += v->velocity * s.samples.weights[i];
      weight += s.samples.weights[i];
      s.at_bar[s.at_bar_count++] = {s.knot, s.samples.points[i],
                                    s.samples.weights[i] / (v->coverage * v->density)};
    }
    for (int i = 0; i < s.at_bar_count; ++i) s.at_bar[i].part_per_mass_weight /= weight;
    s.net->sinker_wet[s.knot] = weight > 0;
    s.net->sinker_flow[s.knot] = weight > 0 ? sum / weight : Vec3d{};
  }
  place_sinker_reactions(shares, sample);
}

void advance_coupled_nets(std::vector<CoupledNet>& nets, std::vector<RigidBody>& bodies,
                          double stage_dt) {
  for (CoupledNet& c : nets) {
    NetModel& net = c.model;
    for (std::size_t k = 0; k < net.knots.size(); ++k) {
      const RigidBody& b = bodies[c.first_body + k];
      net.knots[k].position = b.start.com;
      net.knots[k].velocity = b.start.vel;
    }
    const auto sinker = [&](const NetModel& n, std::size_t k) {
      return c.sinker_wet[k] ? sinker_drag(n, n.knots[k], c.sinker_flow[k], c.water_density)
                             : Vec3d{};
    };
    // The sinker's drag on each sub-step's knot velocity: the bar damps the net's swinging.
    // Velocity Verlet applies the loads of its calls with trapezoidal weights (the first and
    // the last half), so that is the stage's mean drag the water takes back.
    const std::size_t nk = net.knots.size();
    std::vector<Vec3d> drag_sum(nk), drag_first(nk), drag_last(nk);
    int calls = 0;
    const auto fluid = [&](const NetModel& n, std::vector<Vec3d>& f) {
      for (std::size_t k = 0; k < n.knots.size(); ++k) {
        const RigidBody& b = bodies[c.first_body + k];
        const Vec3d drag = sinker(n, k);
        f[k] += b.fluid_force + b.contact_force + drag;
        if (calls == 0) drag_first[k] = drag;
        drag_last[k] = drag;
        drag_sum[k] += drag;
      }
      ++calls;
    };
    KnotSpringSolver solver(net);
    solver.advance(stage_dt, fluid);
    for (std::size_t k = 0; k < nk; ++k) {
      c.sinker_stage_drag[k] =
          calls >= 2 ? (drag_sum[k] - (drag_first[k] + drag_last[k]) * 0.5) / double(calls - 1)
                     : Vec3d{};  // no sub-step (stage_dt 0): no drag applied
    }
    for (std::size_t k = 0; k < nk; ++k) {
      RigidBody& b = bodies[c.first_body + k];
      // The drag the stage applied, as the water takes it back: after the corrector (a stage
      // over the whole step) the step's mean, so that the net's force columns integrate to
      // the momentum the bar gave the net and took from the water.
      b.modelled_force = c.sinker_stage_drag[k];
      b.modelled_torque =
          cross(sinker_point(net, net.knots[k]) - net.knots[k].position, b.modelled_force);
      if (b.motion != BodyMotion::Floating) continue;
      b.state.com = net.knots[k].position;
      b.state.vel = net.knots[k].velocity;
    }
  }
}

void add_sinker_reactions(const std::vector<CoupledNet>& nets, std::vector<FluidPointLoad>& loads) {
  for (const CoupledNet& c : nets) {
    for (const CoupledNet::ReactionPoint& r : c.sinker_reach)
      loads.push_back({r.point, -c.sinker_stage_drag[r.knot] * r.part_per_mass_weight});
  }
}

}  // namespace netsph
