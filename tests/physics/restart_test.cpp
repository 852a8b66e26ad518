// Checkpoint and restart (solver/simulation_checkpoint.cpp, io/checkpoint_file.hpp): a run
// split in two through a checkpoint file matches the uninterrupted run bit for bit (same
// build, same threads), on a case with everything a step carries: open inlet and outlet,
// moving walls, a coupled net (floating and fixed knot bodies, a twine, a sinker) and
// shifting (tests/cases/good/plot_smoke.toml), its particles written in blocks of rows. A
// checkpoint of another case is refused, and so is one whose particles were damaged after it
// was written (garbage inside an intact file), before any step runs on them.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <limits>

#include "case_runs.hpp"
#include "netsph/io/checkpoint_file.hpp"

namespace netsph {
namespace {

CaseSpec smoke_case() {
  return read_case_file(std::string(NETSPH_TEST_CASES_DIR) + "/good/plot_smoke.toml");
}

void step_n(Simulation& sim, int n) {
  for (int i = 0; i < n; ++i) sim.step();
}

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

TEST(Restart, SplitRunMatchesTheUninterruptedRunBitForBit) {
  const CaseSpec spec = smoke_case();
  Simulation whole(spec);
  step_n(whole, 40);
  CheckpointData saved;
  whole.save_global_state(saved);
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / "netsph_restart_test.h5";
  // The particles in blocks of 97 rows, as a run writes them (in blocks of 2^18).
  int blocks = 0;
  write_checkpoint_file(file, saved, [&](const auto& add) {
    Simulation::particle_state_blocks(
        whole.particles(),
        [&](const CheckpointData& block) {
          ++blocks;
          add(block);
        },
        97);
  });
  EXPECT_EQ(blocks, static_cast<int>((whole.particles().size() + 96) / 97));
  step_n(whole, 40);

  Simulation resumed(spec);
  resumed.restore_state(read_checkpoint_file(file));
  EXPECT_EQ(resumed.steps(), 40);
  step_n(resumed, 40);

  const ParticleSet& a = whole.particles();
  const ParticleSet& b = resumed.particles();
  ASSERT_EQ(a.size(), b.size());
  EXPECT_GT(whole.diagnostics().open.entered_fluid, 0u);  // the inlet was at work
  EXPECT_TRUE(same_bits(a.pos, b.pos));
  EXPECT_TRUE(same_bits(a.vel, b.vel));
  EXPECT_TRUE(same_bits(a.rho, b.rho));
  EXPECT_TRUE(same_bits(a.id, b.id));
  EXPECT_EQ(whole.time(), resumed.time());
  ASSERT_EQ(whole.bodies().size(), resumed.bodies().size());
  for (std::size_t i = 0; i < whole.bodies().size(); ++i) {
    const RigidBody& x = whole.bodies()[i];
    const RigidBody& y = resumed.bodies()[i];
    EXPECT_EQ(x.state.com.x, y.state.com.x) << x.name;
    EXPECT_EQ(x.state.com.z, y.state.com.z) << x.name;
    EXPECT_EQ(x.fluid_force.x, y.fluid_force.x) << x.name;
  }
  // The knot moved: the comparison covers the coupling, not a body at rest.
  EXPECT_NE(whole.nets()[0].model.knots[0].position.x, whole.nets()[0].initial[0].x);
  std::filesystem::remove(file);
}

// A paddle with active absorption: its correction and the elevations its delay still needs are
// in the checkpoint, so the paddle (and with it the water) continues bit for bit. Coarse (dp
// 0.04 m) and at full height from the first step (no ramp); saved before the gauge-to-paddle
// delay (0.15 s) has passed, so the restored history is what the correction then reads.
TEST(Restart, AbsorbingPaddleContinuesBitForBit) {
  const CaseSpec spec =
      read_case_file(std::string(NETSPH_CASES_DIR) + "/waves/absorbing_piston2d.toml",
                     {"simulation.dp=0.04", "waves.ramp=0.0"});
  Simulation whole(spec);
  step_n(whole, 150);
  CheckpointData saved;
  whole.save_state(saved);
  ASSERT_LT(whole.time(), spec.waves.absorption.delay);
  step_n(whole, 250);
  ASSERT_GT(whole.time(), spec.waves.absorption.delay);
  ASSERT_NE(whole.absorber(), nullptr);
  EXPECT_NE(whole.absorber()->velocity(), 0.0);

  Simulation resumed(spec);
  resumed.restore_state(saved);
  step_n(resumed, 250);
  EXPECT_TRUE(same_bits(whole.particles().pos, resumed.particles().pos));
  EXPECT_TRUE(same_bits(whole.particles().vel, resumed.particles().vel));
  EXPECT_EQ(whole.absorber()->velocity(), resumed.absorber()->velocity());
  EXPECT_EQ(whole.absorber()->excursion(), resumed.absorber()->excursion());
}

// A flap paddle: a prescribed body turning about its hinge continues from its checkpointed
// state (orientation, centre, rate) bit for bit, turning from the first step (no ramp).
TEST(Restart, FlapPaddleContinuesBitForBit) {
  const CaseSpec spec = read_case_file(std::string(NETSPH_CASES_DIR) + "/waves/regular_flap2d.toml",
                                       {"simulation.dp=0.04", "waves.ramp=0.0"});
  Simulation whole(spec);
  step_n(whole, 100);
  CheckpointData saved;
  whole.save_state(saved);
  step_n(whole, 150);
  ASSERT_EQ(whole.bodies().size(), 1u);
  EXPECT_NE(whole.bodies()[0].state.omega.y, 0.0);

  Simulation resumed(spec);
  resumed.restore_state(saved);
  step_n(resumed, 150);
  EXPECT_TRUE(same_bits(whole.particles().pos, resumed.particles().pos));
  EXPECT_TRUE(same_bits(whole.particles().vel, resumed.particles().vel));
  const RigidState &a = whole.bodies()[0].state, &b = resumed.bodies()[0].state;
  EXPECT_EQ(a.com.x, b.com.x);
  EXPECT_EQ(a.com.z, b.com.z);
  EXPECT_EQ(a.q.w, b.q.w);
  EXPECT_EQ(a.q.y, b.q.y);
}

TEST(Restart, CheckpointOfAnotherCaseIsRefused) {
  Simulation net_case(smoke_case());
  CheckpointData saved;
  net_case.save_state(saved);
  saved.source = "test checkpoint";
  Simulation other(test::load_case("dambreak2d.toml"));
  EXPECT_THROW(other.restore_state(saved), Error);
}

TEST(Restart, CorruptParticleStateIsRefusedNamingTheParticle) {
  const CaseSpec spec = test::load_case("dambreak2d.toml");
  Simulation sim(spec);
  CheckpointData saved;
  sim.save_state(saved);
  saved.source = "damaged/checkpoint.h5";
  EXPECT_NO_THROW(Simulation(spec).restore_state(saved));  // the intact state
  constexpr std::size_t kRow = 1234;
  const std::string id = "particle id " + std::to_string(saved.u32.at("particles.id")[kRow]);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto refused = [&](const char* what, auto&& damage) {
    CheckpointData c = saved;
    damage(c);
    try {
      Simulation(spec).restore_state(c);
      ADD_FAILURE() << what << ": a damaged checkpoint was restored";
    } catch (const Error& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("damaged/checkpoint.h5: the checkpoint is corrupt"), std::string::npos) << m;
      EXPECT_NE(m.find(id), std::string::npos) << m;
      EXPECT_NE(m.find(what), std::string::npos) << m;
    }
  };
  refused("not finite", [&](CheckpointData& c) { c.f64["particles.pos"][3 * kRow + 2] = nan; });
  refused("far outside the domain",
          [&](CheckpointData& c) { c.f64["particles.pos"][3 * kRow] = 3e291; });
  refused("100 times the sound speed",
          [&](CheckpointData& c) { c.f32["particles.vel"][3 * kRow + 1] = -2.5e33f; });
  refused("density 0", [&](CheckpointData& c) { c.f32["particles.rho"][kRow] = 0; });
  refused("kind 255", [&](CheckpointData& c) { c.u8["particles.kind"][kRow] = 255; });
}

TEST(Restart, MissingOrForeignFileIsAClearError) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path();
  EXPECT_THROW(read_checkpoint_file(dir / "netsph_no_such_checkpoint.h5"), Error);
  const std::filesystem::path text = dir / "netsph_not_a_checkpoint.h5";
  {
    std::FILE* f = std::fopen(text.c_str(), "w");
    std::fputs("hello", f);
    std::fclose(f);
  }
  try {
    read_checkpoint_file(text);
    FAIL() << "a text file was read as a checkpoint";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("netsph_not_a_checkpoint.h5"), std::string::npos);
  }
  std::filesystem::remove(text);
}

}  // namespace
}  // namespace netsph
