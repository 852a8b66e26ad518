// The paper's single-element flow domain (section 3.1.1) with no element: inlet and outlet
// buffers on x, walls moving with the stream at U and periodic in x (their particles wrap
// around). Over one flow-through time the flow must stay uniform: the velocity averaged over
// each (y, z) cell of the mid-domain section within 2% of U.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "case_runs.hpp"

namespace netsph {
namespace {

TEST(ElementDomain, EmptyDomainFlowStaysUniform) {
  Simulation sim(test::load_case("element_domain.toml", {"simulation.end_time=8"}));
  const double U = 0.5, dp = sim.spec().simulation.dp;
  const std::size_t walls = sim.particles().count(ParticleKind::Wall);
  test::run_until(sim, 8.0);
  const ParticleSet& p = sim.particles();
  // Mid-domain section |x| < 0.2 m, binned into dp x dp cells over (y, z).
  std::map<std::pair<int, int>, std::pair<double, int>> cells;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!is_fluid(p.kind[i]) || std::fabs(p.pos[i].x) > 0.2) continue;
    auto& c = cells[{static_cast<int>(std::floor(p.pos[i].y / dp)),
                     static_cast<int>(std::floor(p.pos[i].z / dp))}];
    c.first += p.vel[i].x, ++c.second;
  }
  ASSERT_GT(cells.size(), 100u);
  for (const auto& [key, c] : cells) {
    EXPECT_NEAR(c.first / c.second, U, 0.02 * U) << "cell y " << key.first << " z " << key.second;
  }
  // The walls travelled one domain length and wrapped around; none was lost.
  EXPECT_EQ(p.count(ParticleKind::Wall), walls);
  EXPECT_EQ(sim.diagnostics().lost_total, 0u);
  EXPECT_GT(sim.diagnostics().open.entered_fluid, 0u);
}

}  // namespace
}  // namespace netsph
