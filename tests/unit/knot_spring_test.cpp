// Knot-spring dynamics against mechanics with known answers: a hanging mass's static stretch,
// critical damping, a slack twine, the pendulum period, energy conservation and the catenary.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "netsph/net/knot_spring_solver.hpp"
#include "netsph/net/twine_law.hpp"

namespace netsph {
namespace {

constexpr double kG = 9.81;

NetKnot knot(Vec3d position, double mass, bool fixed) {
  NetKnot k;
  k.position = position;
  k.mass = mass;
  k.fixed = fixed;
  k.constant_force = fixed ? Vec3d{} : Vec3d{0, 0, -kG * mass};
  return k;
}

NetTwine twine(int a, int b, double rest, double ea, double damping) {
  NetTwine t;
  t.a = a;
  t.b = b;
  t.rest = rest;
  t.law = {ea, 0};
  t.damping = damping;
  return t;
}

/// A mass m hanging from an anchor on one twine of rest length L and stiffness k = EA / L.
NetModel hanging_mass(double m, double length, double k, double zeta, Vec3d start) {
  NetModel net;
  net.knots = {knot({0, 0, 0}, 0, true), knot(start, m, false)};
  net.twines = {twine(0, 1, length, k * length, 2 * zeta * std::sqrt(k * m))};
  return net;
}

TEST(TwineLaw, TensionOnlyAndNonlinear) {
  const TwineLaw nylon{1160, 37300};  // REEF3D's nylon twine
  EXPECT_DOUBLE_EQ(twine_tension(nylon, -0.01), 0.0);
  EXPECT_NEAR(twine_tension(nylon, 0.02), 1160 * 0.02 + 37300 * 0.0004, 1e-12);
  // Energy is the integral of the tension: check by the derivative.
  const double e = 0.03, rest = 0.5, h = 1e-6;
  const double dE =
      (twine_energy(nylon, e + h, rest) - twine_energy(nylon, e - h, rest)) / (2 * h * rest);
  EXPECT_NEAR(dE, twine_tension(nylon, e), 1e-6);
}

TEST(KnotSpring, SlackTwineCarriesNoForce) {
  // Knots 0.8 L apart, closing at 1 m/s: no tension, no damping push.
  const Vec3d f =
      twine_force_on_a({1e4, 0}, 1.0, 50.0, {0, 0, 0}, {0.8, 0, 0}, {0.5, 0, 0}, {-0.5, 0, 0});
  EXPECT_EQ(norm(f), 0.0);
  NetModel net;
  net.knots = {knot({0, 0, 0}, 1, false), knot({0.8, 0, 0}, 1, false)};
  for (NetKnot& k : net.knots) k.constant_force = {};
  net.knots[0].velocity = {0.1, 0, 0};
  net.twines = {twine(0, 1, 1.0, 1e4, 50)};
  KnotSpringSolver solver(net);
  solver.advance(0.5, {});  // closes by 0.05 m: stays slack
  EXPECT_DOUBLE_EQ(net.knots[0].velocity.x, 0.1);
  EXPECT_DOUBLE_EQ(net.knots[1].velocity.x, 0.0);
  EXPECT_NEAR(net.knots[0].position.x, 0.05, 1e-12);
}

TEST(KnotSpring, StaticStretchUnderAHangingMass) {
  const double m = 0.5, length = 0.2, k = 2000;
  NetModel net = hanging_mass(m, length, k, 1.0, {0, 0, -length});
  KnotSpringSolver solver(net);
  solver.advance(2.0, {});
  const double stretch = -net.knots[1].position.z - length;
  std::printf("stretch %.6e m, m g / k = %.6e m\n", stretch, m * kG / k);
  EXPECT_NEAR(stretch / (m * kG / k), 1.0, 0.01);
  EXPECT_NEAR(solver.anchor_force().z, -m * kG, 0.01 * m * kG);
}

TEST(KnotSpring, CriticalDampingDoesNotOvershoot) {
  const double m = 0.5, length = 0.2, k = 2000;
  NetModel net = hanging_mass(m, length, k, 1.0, {0, 0, -length});
  KnotSpringSolver solver(net);
  const double target = m * kG / k;
  double largest = 0;
  for (int i = 0; i < 2000; ++i) {
    solver.advance(1e-3, {});
    largest = std::max(largest, -net.knots[1].position.z - length);
  }
  std::printf("largest stretch %.6e m, static %.6e m\n", largest, target);
  EXPECT_LE(largest, target * 1.001);
  EXPECT_GT(largest, target * 0.999);  // and it does get there
  // Half the critical damping overshoots (sanity check of the test itself).
  NetModel under = hanging_mass(m, length, k, 0.5, {0, 0, -length});
  KnotSpringSolver s2(under);
  double peak = 0;
  for (int i = 0; i < 500; ++i) {
    s2.advance(1e-3, {});
    peak = std::max(peak, -under.knots[1].position.z - length);
  }
  EXPECT_GT(peak, target * 1.1);
}

TEST(KnotSpring, PendulumPeriod) {
  // A stiff twine of 0.5 m; 5 degrees: T = 2 pi sqrt(L/g) (1 + theta0^2 / 16).
  const double m = 0.2, length = 0.5, k = 2e5, theta0 = 5 * std::numbers::pi / 180;
  const double stretched = length + m * kG / k;
  NetModel net = hanging_mass(m, length, k, 0.0,
                              {stretched * std::sin(theta0), 0, -stretched * std::cos(theta0)});
  KnotSpringSolver solver(net);
  double t = 0, previous = net.knots[1].position.x;
  std::vector<double> crossings;
  const double dt = 1e-3;
  while (crossings.size() < 11 && t < 30) {
    solver.advance(dt, {});
    t += dt;
    const double x = net.knots[1].position.x;
    if (previous > 0 && x <= 0) crossings.push_back(t - dt * x / (x - previous));
    previous = x;
  }
  ASSERT_EQ(crossings.size(), 11u);
  const double period = (crossings.back() - crossings.front()) / 10;
  const double expected =
      2 * std::numbers::pi * std::sqrt(stretched / kG) * (1 + theta0 * theta0 / 16);
  std::printf("period %.5f s, expected %.5f s\n", period, expected);
  EXPECT_NEAR(period / expected, 1.0, 0.01);
}

TEST(KnotSpring, UndampedEnergyIsConserved) {
  // A 7 x 7 net fixed on all four edges, pre-stretched 1%, no gravity, kicked out of its
  // plane: a vibrating membrane whose twines stay taut. Kinetic + strain energy stays within
  // 1% of the kick over 100 periods of the fundamental mode.
  NetModel net;
  const int n = 7;
  net.rows = net.columns = n;
  const double s = 0.05, m = 0.01, ea = 50;
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) {
      const bool edge = r == 0 || c == 0 || r == n - 1 || c == n - 1;
      NetKnot k = knot({0, c * s, r * s}, m, edge);
      k.constant_force = {};
      if (!edge)
        k.velocity = {0.05 * std::sin(std::numbers::pi * r / (n - 1)) * (1 + 0.2 * c), 0, 0};
      net.knots.push_back(k);
    }
  }
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) {
      if (c + 1 < n) net.twines.push_back(twine(r * n + c, r * n + c + 1, s / 1.01, ea, 0));
      if (r + 1 < n) net.twines.push_back(twine(r * n + c, (r + 1) * n + c, s / 1.01, ea, 0));
    }
  }
  KnotSpringSolver solver(net);
  auto energy = [&] { return solver.kinetic_energy() + solver.twine_energy(); };
  const double e0 = energy();
  const double kick = solver.kinetic_energy();
  // Fundamental mode of a square membrane: omega = c pi sqrt(2) / side, c = sqrt(T / rho_A)
  // with T the tension per unit width and rho_A the mass per area.
  const double tension = ea * 0.01 / s, rho = m / (s * s), side = (n - 1) * s;
  const double period = 2 * side / (std::sqrt(tension / rho) * std::sqrt(2.0));
  double worst = 0;
  for (int i = 0; i < 1000; ++i) {
    solver.advance(period / 10, {});
    worst = std::max(worst, std::abs(energy() - e0));
  }
  std::printf("largest energy error %.3e J of a %.3e J kick over 100 periods of %.3f s\n", worst,
              kick, period);
  EXPECT_LT(worst / kick, 0.01);
}

TEST(KnotSpring, SlackingNetStaysBounded) {
  // Hung from its top row with no damping and kicked, a net's twines keep going slack and
  // taut; the non-smooth tension then costs the integrator accuracy but must not feed
  // energy in without bound (it did with a 0.9 stability margin).
  NetModel net;
  const double s = 0.05;
  for (int r = 0; r < 5; ++r) {
    for (int c = 0; c < 5; ++c) {
      NetKnot k = knot({0, c * s, -(4 - r) * s}, 0.01, r == 4);
      if (!k.fixed) k.velocity = {0.05 * (1 + 0.1 * c), 0.02 * r, 0.0};
      net.knots.push_back(k);
    }
  }
  for (int r = 0; r < 5; ++r) {
    for (int c = 0; c < 5; ++c) {
      if (c < 4) net.twines.push_back(twine(r * 5 + c, r * 5 + c + 1, s, 1000 * s, 0));
      if (r < 4) net.twines.push_back(twine(r * 5 + c, (r + 1) * 5 + c, s, 1000 * s, 0));
    }
  }
  KnotSpringSolver solver(net);
  const double period = 2 * std::numbers::pi * std::sqrt(0.2 / kG);
  double largest_strain = 0;
  for (int i = 0; i < 1000; ++i) {
    solver.advance(period / 10, {});
    largest_strain = std::max(largest_strain, solver.max_strain());
  }
  // Static strain of the top twines: 4 knots of 0.01 kg on EA = 50 N: 0.8%.
  std::printf("largest strain over 100 periods %.4f\n", largest_strain);
  EXPECT_LT(largest_strain, 0.05);
}

TEST(KnotSpring, HangingChainIsACatenary) {
  // 40 links of 0.025 m (L = 1 m) between supports 0.8 m apart, stiff links; settled by a
  // weak viscous drag. Catenary: z = a cosh(x/a) + c with L = 2 a sinh(S / 2a).
  const int links = 40;
  const double link = 0.025, span = 0.8, m = 0.01;
  NetModel net;
  for (int i = 0; i <= links; ++i) {
    // Start on a triangle of the right length, so every link starts taut.
    const double x = span * i / links;
    const double half = span / 2, drop = std::sqrt(0.25 - half * half);
    const double z = -drop * (1 - std::abs(x - half) / half);
    net.knots.push_back(knot({x, 0, z}, m, i == 0 || i == links));
  }
  for (int i = 0; i < links; ++i) net.twines.push_back(twine(i, i + 1, link, 1e6 * link, 0));
  for (NetTwine& t : net.twines) t.damping = 2 * std::sqrt(t.law.c1 / t.rest * m / 2);
  KnotSpringSolver solver(net);
  const auto drag = [&](const NetModel& n, std::vector<Vec3d>& f) {
    for (std::size_t i = 0; i < n.knots.size(); ++i) f[i] -= n.knots[i].velocity * (0.5 * m);
  };
  solver.advance(20.0, drag);
  // a from L = 2 a sinh(S / 2a) by bisection.
  const double total = links * link;
  double lo = 0.01, hi = 10;
  for (int i = 0; i < 200; ++i) {
    const double a = 0.5 * (lo + hi);
    (2 * a * std::sinh(span / (2 * a)) > total ? lo : hi) = a;
  }
  const double a = 0.5 * (lo + hi);
  double worst = 0;
  for (const NetKnot& k : net.knots) {
    const double x = k.position.x - span / 2;
    const double z = a * std::cosh(x / a) - a * std::cosh(span / (2 * a));
    worst = std::max(worst, std::abs(k.position.z - z));
  }
  std::printf("a = %.4f m, largest deviation %.3e m (%.3f%% of the span)\n", a, worst,
              100 * worst / span);
  EXPECT_LT(worst, 0.01 * span);
  // Settled: kinetic energy a millionth of the chain's weight times its sag (about 1 J).
  EXPECT_LT(solver.kinetic_energy(), 1e-5);
}

}  // namespace
}  // namespace netsph
