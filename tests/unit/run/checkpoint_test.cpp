// Checkpoints (issue: hard to break): a simulation restored from a checkpoint continues
// exactly as the original: bitwise equal particles after the same number of steps.
#include <gtest/gtest.h>

#include <cstdint>


#include "sloshsph/core/errors.hpp"
#include "sloshsph/io/case_reader.hpp"
#include "sloshsph/run/simulation.hpp"
#include "same_bits.hpp"

namespace sloshsph {
namespace {

CaseSpec small_case(const std::vector<std::string>& extra) {
  // A settle of its own, which the resumed simulation skips (SimulationStart::for_checkpoint).
  std::vector<std::string> sets = {"particles.dp=0.02", "time.end=10", "time.settle=0.2", "output.snapshot_interval=0"};
  sets.insert(sets.end(), extra.begin(), extra.end());
  return resolve_case(read_case_file(std::string(SLOSHSPH_SOURCE_DIR) + "/cases/liu_lin_2008.toml", sets));
}

using test::same_bits;

// Reference: the uninterrupted run. Tolerance: none (bitwise), for the same thread count: the
// checkpoint holds every evolving quantity, the neighbour list included, so the restored run
// sums in the same order.
template <int D = 2>
void expect_bitwise_resume(const CaseSpec& spec) {
  BasicSimulation<D> original(spec);
  for (int n = 0; n < 150; ++n) original.step();  // past several neighbour rebuilds
  StateWriter w;
  original.save_state(w);
  for (int n = 0; n < 150; ++n) original.step();

  BasicSimulation<D> resumed(spec, SimulationStart::for_checkpoint);
  StateReader r(w.bytes(), "memory");
  resumed.load_state(r);
  EXPECT_TRUE(r.at_end());
  for (int n = 0; n < 150; ++n) resumed.step();

  EXPECT_EQ(resumed.steps(), original.steps());
  EXPECT_EQ(resumed.time(), original.time());
  EXPECT_TRUE(same_bits(resumed.particles().position, original.particles().position));
  EXPECT_TRUE(same_bits(resumed.particles().velocity, original.particles().velocity));
  EXPECT_TRUE(same_bits(resumed.particles().pressure, original.particles().pressure));
  EXPECT_EQ(resumed.sample(), original.sample());
}

TEST(Checkpoint, IsphResumesBitwise) { expect_bitwise_resume(small_case({})); }

TEST(Checkpoint, WcsphResumesBitwise) {
  expect_bitwise_resume(small_case({"scheme={type=\"wcsph\", turbulence=\"sps\", xsph=0.05, shepard_interval=20}"}));
}

// A 3D case (issue 31) resumes bitwise too: the box of cases/box3d_diagonal.toml, coarser.
TEST(Checkpoint, ThreeDimensionalCaseResumesBitwise) {
  const CaseSpec spec = resolve_case(read_case_file(std::string(SLOSHSPH_SOURCE_DIR) + "/cases/box3d_diagonal.toml",
                                                    {"particles.dp=0.02", "time.settle=0.05", "time.dt=0.002",
                                                     "output.snapshot_interval=0"}));
  ASSERT_EQ(spec.tank.dimensions, 3);
  expect_bitwise_resume<3>(spec);
}

// The WCSPH scheme in 3D resumes bitwise too (its rates, XSPH velocities and neighbour list).
TEST(Checkpoint, ThreeDimensionalWcsphResumesBitwise) {
  const CaseSpec spec = resolve_case(read_case_file(std::string(SLOSHSPH_SOURCE_DIR) + "/cases/box3d_diagonal.toml",
                                                    {"particles.dp=0.02", "time.settle=0.05", "time.dt=0.002",
                                                     "output.snapshot_interval=0", "scheme.type=\"wcsph\""}));
  expect_bitwise_resume<3>(spec);
}

// The same box on a 2-DOF structure (issue 31, section 3), the base motion its ground: both sway
// modes, their force histories and the y interval sums are in the checkpoint.
TEST(Checkpoint, TwoDofStructureResumesBitwise) {
  const std::string structure = "structure={mass=20.0, frequency=0.8, damping_ratio=0.01, ground=\"excitation\", "
                                "y={mass=15.0, frequency=1.1, damping_ratio=0.02, initial_velocity=0.02}}";
  const CaseSpec spec = resolve_case(read_case_file(std::string(SLOSHSPH_SOURCE_DIR) + "/cases/box3d_diagonal.toml",
                                                    {"particles.dp=0.02", "time.settle=0.05", "time.dt=0.002",
                                                     "output.snapshot_interval=0", structure}));
  ASSERT_TRUE(spec.structure_y);
  expect_bitwise_resume<3>(spec);
}

// Particle shifting (issue 30) keeps nothing between steps but the count of cut shifts, which the
// checkpoint holds: resumed runs with it on are bitwise too.
TEST(Checkpoint, ShiftingResumesBitwise) {
  expect_bitwise_resume(small_case({"scheme.shifting=lind"}));
  expect_bitwise_resume(small_case({"scheme={type=\"wcsph\", shifting=\"delta_plus\"}"}));
}

// A record that a later version added is read only if it is there (StateReader::next_is), so that
// a checkpoint written before it (before sim.pair_contacts, 2026-12-06) still resumes.
TEST(Checkpoint, RecordAddedLaterIsOptional) {
  StateWriter old_version;
  old_version.value("sim.wall_contacts", std::uint64_t{3});
  old_version.value("sim.acc_dt", 0.5);
  StateReader r(old_version.bytes(), "old.bin");
  EXPECT_TRUE(r.next_is("sim.wall_contacts"));
  EXPECT_EQ(r.value<std::uint64_t>("sim.wall_contacts"), 3u);
  EXPECT_FALSE(r.next_is("sim.pair_contacts"));
  EXPECT_FALSE(r.next_is("sim.acc"));  // a prefix of the next record's name is not it
  EXPECT_TRUE(r.next_is("sim.acc_dt"));
  EXPECT_EQ(r.value<double>("sim.acc_dt"), 0.5);
  EXPECT_FALSE(r.next_is("sim.acc_dt"));  // at the end
  EXPECT_TRUE(r.at_end());
}

// A damaged checkpoint is an InputError naming the record, never garbage.
TEST(Checkpoint, TruncatedCheckpointIsReported) {
  const CaseSpec spec = small_case({});
  Simulation sim(spec);
  StateWriter w;
  sim.save_state(w);
  const std::string cut = w.bytes().substr(0, w.bytes().size() / 2);
  StateReader r(cut, "cut.bin");
  Simulation other(spec);
  try {
    other.load_state(r);
    FAIL() << "a truncated checkpoint was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("truncated"), std::string::npos) << e.what();
  }
  EXPECT_THROW(StateReader("not a checkpoint", "x.bin"), InputError);
}

}  // namespace
}  // namespace sloshsph
