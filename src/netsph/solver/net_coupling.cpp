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
    c.sinker_flow.assign(c.model.knots.size(), Vec3d{});
    c.sinker_wet.assign(c.model.knots.size(), 0);
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
    for (std::size_t k = 0; k < net.knots.size(); ++k)
      net.knots[k].position = bodies[c.first_body + k].state.com;
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
  // Each share's flow: the weighted mean over its points in the water.
  const ShepardValue* v = values.data();
  for (const Share& s : shares) {
    Vec3d sum{};
    double weight = 0;
    for (int i = 0; i < s.samples.count; ++i, ++v) {
      if (v->coverage < kSinkerWetCoverage) continue;
      sum += v->velocity * s.samples.weights[i];
      weight += s.samples.weights[i];
    }
    s.net->sinker_wet[s.knot] = weight > 0;
    s.net->sinker_flow[s.knot] = weight > 0 ? sum / weight : Vec3d{};
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
    const auto fluid = [&](const NetModel& n, std::vector<Vec3d>& f) {
      for (std::size_t k = 0; k < n.knots.size(); ++k) {
        const RigidBody& b = bodies[c.first_body + k];
        f[k] += b.fluid_force + b.contact_force + sinker(n, k);
      }
    };
    KnotSpringSolver solver(net);
    solver.advance(stage_dt, fluid);
    for (std::size_t k = 0; k < net.knots.size(); ++k) {
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

}  // namespace netsph
