#include "netsph/solver/net_coupling.hpp"

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
  switch (k.geometry.shape) {
    case KnotShape::SquarePlate:
      b.shape_name = "square_plate";
      b.shape = BodyShape::Box;
      b.lengths = {k.geometry.thickness, k.geometry.size, k.geometry.size};
      break;
    case KnotShape::CircularPlate:
      b.shape_name = "circular_plate";
      b.shape = BodyShape::Cylinder;
      b.diameter = k.geometry.size;
      b.length = k.geometry.thickness;
      break;
    case KnotShape::Sphere:
      b.shape_name = "sphere";
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
    c.sinker_reach.assign(c.model.knots.size(), SinkerSamples{});
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

void sample_sinker_flows(std::vector<CoupledNet>& nets, const std::vector<RigidBody>& bodies,
                         const FluidSampler& sample) {
  struct Share {
    CoupledNet* net;
    std::size_t knot;
    SinkerSamples samples;
  };
  std::vector<Share> shares;
  std::vector<Vec3d> points;
  for (CoupledNet& c : nets) {
    NetModel& net = c.model;
    for (std::size_t k = 0; k < net.knots.size(); ++k) {
      net.knots[k].position = bodies[c.first_body + k].state.com;
      net.knots[k].velocity = bodies[c.first_body + k].state.vel;
    }
    for (std::size_t k = 0; k < net.knots.size(); ++k) {
      if (net.knots[k].sinker_length <= 0) continue;
      Share& s = shares.emplace_back(Share{&c, k, {}});
      sinker_sample_points(net, net.knots[k], s.samples);
      points.insert(points.end(), s.samples.points, s.samples.points + s.samples.count);
    }
  }
  if (points.empty()) return;
  std::vector<ShepardValue> values(points.size());
  sample(points, values);
  // Each share's flow: the weighted mean over its points in the water. Its reaction goes to
  // the water by the same weights, each wet point's part moved downstream along the share's
  // drag by CoupledNet::reaction_offset (below).
  std::vector<Vec3d> downstream(points.size());
  const ShepardValue* v = values.data();
  Vec3d* moved = downstream.data();
  for (const Share& s : shares) {
    Vec3d sum{};
    double weight = 0;
    for (int i = 0; i < s.samples.count; ++i) {
      if (v[i].coverage < kSinkerWetCoverage) continue;
      sum += v[i].velocity * s.samples.weights[i];
      weight += s.samples.weights[i];
    }
    CoupledNet& c = *s.net;
    c.sinker_wet[s.knot] = weight > 0;
    c.sinker_flow[s.knot] = weight > 0 ? sum / weight : Vec3d{};
    const Vec3d drag = sinker_drag(c.model, c.model.knots[s.knot], c.sinker_flow[s.knot], 1.0);
    const double size = norm(drag);
    const Vec3d along = size > 0 ? drag / size : Vec3d{};
    SinkerSamples& reach = c.sinker_reach[s.knot];
    reach = s.samples;
    for (int i = 0; i < s.samples.count; ++i) {
      const bool wet = v[i].coverage >= kSinkerWetCoverage;
      reach.weights[i] = wet ? s.samples.weights[i] / weight : 0;
      moved[i] = s.samples.points[i] + along * c.reaction_offset;
    }
    v += s.samples.count;
    moved += s.samples.count;
  }
  // The fluid's mass weight sum_j m_j W where each part goes (sum V W rho, sph/shepard.hpp):
  // downstream where the water is, else at the sample point itself.
  std::vector<ShepardValue> there(points.size());
  sample(downstream, there);
  std::size_t p = 0;
  for (const Share& s : shares) {
    SinkerSamples& reach = s.net->sinker_reach[s.knot];
    for (int i = 0; i < reach.count; ++i, ++p) {
      if (reach.weights[i] <= 0) continue;
      const bool moves = there[p].coverage >= kSinkerWetCoverage;
      const ShepardValue& at = moves ? there[p] : values[p];
      if (moves) reach.points[i] = downstream[p];
      reach.weights[i] /= at.coverage * at.density;
    }
  }
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
                     : Vec3d{};
    }
    for (std::size_t k = 0; k < nk; ++k) {
      RigidBody& b = bodies[c.first_body + k];
      b.modelled_force = sinker(net, k);
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
    for (std::size_t k = 0; k < c.sinker_reach.size(); ++k) {
      const SinkerSamples& reach = c.sinker_reach[k];
      const Vec3d reaction = -c.sinker_stage_drag[k];
      for (int i = 0; i < reach.count; ++i) {
        if (reach.weights[i] > 0) loads.push_back({reach.points[i], reaction * reach.weights[i]});
      }
    }
  }
}

}  // namespace netsph
