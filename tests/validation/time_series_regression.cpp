// Regression: the whole time series of short runs against references stored beside the tests
// (tests/regression/reference/<name>.csv), after SPHinXsys's regression tests.
//
// These tests detect change; they do not validate. A reference is what this code computed when
// the reference was written; the physics is checked against theory and experiments elsewhere
// (docs/validation.md). Each run is short (0.06 to 5 s simulated, seconds of CPU) and takes its
// own path through the schemes, tank shapes, excitations, porous elements, the elastic plate and
// the structure. A change meant to leave the results alone (a refactor, a speed-up) is then
// checked against every column the run writes, at every sample.
//
// Tolerance: every sample of every column must lie within 1e-8 of that column's largest magnitude
// in the reference. A column that is 0 throughout must stay 0, and nan must stay nan. The build
// does not use -march=native by default (CMakeLists.txt, SLOSHSPH_NATIVE), so the same compiler
// gives the same bits on any x86-64 machine: the margin covers only another libm's last bits,
// grown over a few hundred steps. (A native build contracts to fused multiply-adds and may differ
// by more; it was not tried.) It does not cover a change of the physics. A change that reorders a
// floating-point sum fails too, by design. Its author looks at the size of the difference that the
// failure prints, writes new references with
//   SLOSHSPH_UPDATE_REGRESSION=1 build/tests/validation/test_regression
// (each test then reports SKIPPED and names the file it wrote), and says why in the commit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <ostream>
#include <string>
#include <vector>

#include "run_support.hpp"
#include "sloshsph/analysis/stats.hpp"
#include "sloshsph/core/errors.hpp"

namespace sloshsph::testing {
namespace {

struct RegressionCase {
  std::string name;                    // the reference is tests/regression/reference/<name>.csv
  std::string case_file;               // relative to the source tree
  std::vector<std::string> overrides;  // --set overrides that make the run short
};

// What each run passes through (beyond the ISPH defaults: implicit PPE with the multigrid
// preconditioner, air free surface, SPS turbulence, Adami walls, wall contact):
const std::vector<RegressionCase> kCases = {
    // rectangle, harmonic excitation
    {"isph_linear_sloshing", "cases/linear_sloshing.toml", {"time.end=0.5"}},
    // two vertical Ergun screens
    {"isph_tait_ergun_screens", "cases/tait2005_screens.toml", {"time.end=0.5"}},
    // circular tank with a screen
    {"isph_circular_tank", "cases/shapes_circular.toml", {"time.end=0.5"}},
    // parabolic tank
    {"isph_parabolic_tank", "cases/shapes_parabolic.toml", {"particles.dp=0.01", "time.settle=0.1", "time.end=0.3"}},
    // a horizontal Ergun baffle from wall to wall
    {"isph_biswal_baffles", "cases/biswal_baffles.toml", {"time.end=0.5"}},
    // horizontal baffles built of wall particles (the explicit screen model)
    {"isph_biswal_explicit_slats", "cases/biswal_baffles_explicit.toml", {"time.end=0.1"}},
    // pitch (rotation) excitation
    {"isph_pitch", "cases/akyildiz_erdem_pitch.toml", {"time.end=0.5"}},
    // polyline tank, the El Centro record, an inclined Morison screen, pressure panel, surge front
    {"isph_polyline_record_screen", "tests/regression/cases/polyline_record_screen.toml", {}},
    // trapezoid, noise excitation, explicit pressure with the thesis's free surface, an Ergun
    // perforated floor and a screen with the Shepard velocity
    {"isph_noise_perforated_floor", "tests/regression/cases/noise_perforated_floor.toml", {}},
    // the SDOF building coupled both ways to a TLD with Morison screens, noise force
    {"building_tld_coupled", "cases/building_tld_10mg_short.toml", {"time.end=5"}},
    // WCSPH, Shao's corrections: repulsive walls, kernel gradient correction, Shepard filter,
    // Smagorinsky turbulence; pitch
    {"wcsph_shao_pitch_corrections",
     "cases/shao_pitch.toml",
     {"particles.dp=0.006", "time.end=0.3", "scheme.kernel_gradient_correction=true",
      "scheme.shepard_interval=20", "scheme.turbulence=\"smagorinsky\""}},
    // WCSPH dam break with the leapfrog integrator, XSPH and SPS turbulence
    {"wcsph_dambreak_leapfrog",
     "cases/dambreak_koshizuka_wcsph.toml",
     {"time.end=0.15", "scheme.integrator=\"leapfrog\"", "scheme.xsph=0.05", "scheme.turbulence=\"sps\""}},
    // WCSPH with the elastic plate (beam FEM) under the cosine pulse
    {"wcsph_plate_pulse",
     "cases/elastic_plate_pulse.toml",
     {"particles.dp=0.0018", "time.settle=0.01", "excitation.start=0", "time.end=0.06"}},
};

// gtest names a failing case by this, instead of the struct's bytes.
void PrintTo(const RegressionCase& c, std::ostream* os) { *os << c.name; }

constexpr double kRelativeTolerance = 1e-8;

std::string source_path(const std::string& relative) { return std::string(SLOSHSPH_SOURCE_DIR) + "/" + relative; }

std::string reference_path(const std::string& name) {
  return source_path("tests/regression/reference/" + name + ".csv");
}

// The run's columns in the order the run writes them.
CsvTable run_table(const RegressionCase& c) {
  CsvTable t;
  const RunResult r = run_file_in_memory(source_path(c.case_file), c.overrides, [&](const Simulation& sim) {
    for (const auto& column : sim.columns()) t.names.push_back(column.name);
  });
  for (const std::string& name : t.names) t.columns.push_back(r[name]);
  return t;
}

// Written with 15 significant digits (timeseries.csv keeps 10) and a comment line naming the run;
// read back by read_csv_table, which skips the comment.
void write_table(const CsvTable& t, const std::string& path, const RegressionCase& c) {
  std::ofstream out(path);
  out << "# sloshsph regression reference: " << c.case_file;
  for (const std::string& o : c.overrides) out << " --set " << o;
  out << "\n";
  for (std::size_t k = 0; k < t.names.size(); ++k) out << (k ? "," : "") << t.names[k];
  out << "\n";
  char buffer[32];
  for (std::size_t row = 0; row < t.rows(); ++row) {
    for (std::size_t k = 0; k < t.columns.size(); ++k) {
      std::snprintf(buffer, sizeof buffer, "%.15g", t.columns[k][row]);
      out << (k ? "," : "") << buffer;
    }
    out << "\n";
  }
  if (!out) ADD_FAILURE() << "could not write " << path;
}

double largest_magnitude(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) {
    if (std::isfinite(x)) m = std::max(m, std::abs(x));
  }
  return m;
}

// Compares one column: every sample within kRelativeTolerance of the reference's largest
// magnitude; nan where the reference has nan. Reports the worst sample.
void expect_same_column(const std::string& name, const std::vector<double>& time, const std::vector<double>& ref,
                        const std::vector<double>& now) {
  const double allowed = kRelativeTolerance * largest_magnitude(ref);
  double worst = 0.0;
  std::size_t worst_row = 0;
  std::size_t nan_mismatches = 0;
  for (std::size_t row = 0; row < ref.size(); ++row) {
    if (std::isnan(ref[row]) || std::isnan(now[row])) {
      nan_mismatches += std::isnan(ref[row]) != std::isnan(now[row]) ? 1 : 0;
      continue;
    }
    const double difference = std::abs(now[row] - ref[row]);
    if (difference > worst) {
      worst = difference;
      worst_row = row;
    }
  }
  EXPECT_EQ(nan_mismatches, 0u) << "column " << name << ": nan in one run and not in the other at "
                                << nan_mismatches << " samples";
  EXPECT_LE(worst, allowed) << "column " << name << ": at t = " << time[worst_row] << " s, " << now[worst_row]
                            << " against the reference's " << ref[worst_row] << " (difference " << worst
                            << ", allowed " << allowed << " = " << kRelativeTolerance
                            << " x the column's largest magnitude)";
}

class TimeSeriesRegression : public ::testing::TestWithParam<RegressionCase> {};

TEST_P(TimeSeriesRegression, MatchesStoredReference) {
  const RegressionCase& c = GetParam();
  const CsvTable now = run_table(c);
  ASSERT_FALSE(now.names.empty());
  const std::string path = reference_path(c.name);
  const char* update = std::getenv("SLOSHSPH_UPDATE_REGRESSION");
  if (update && std::string(update) == "1") {
    write_table(now, path, c);
    GTEST_SKIP() << "SLOSHSPH_UPDATE_REGRESSION=1: wrote " << path << " (" << now.rows()
                 << " samples of " << now.names.size() << " columns); nothing compared";
  }
  CsvTable ref;
  try {
    ref = read_csv_table(path);
  } catch (const InputError& e) {
    FAIL() << e.what() << " (write the reference with SLOSHSPH_UPDATE_REGRESSION=1)";
  }
  ASSERT_EQ(now.rows(), ref.rows()) << "number of samples";
  for (std::size_t k = 0; k < ref.names.size(); ++k) {
    if (!now.has(ref.names[k])) {
      ADD_FAILURE() << "column " << ref.names[k] << " of the reference is no longer written";
      continue;
    }
    expect_same_column(ref.names[k], ref.columns.front(), ref.columns[k], now.column(ref.names[k]));
  }
  for (const std::string& name : now.names) {
    if (!ref.has(name)) std::printf("  column %s is new (not in the reference; not compared)\n", name.c_str());
  }
}

INSTANTIATE_TEST_SUITE_P(Runs, TimeSeriesRegression, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<RegressionCase>& info) { return info.param.name; });

}  // namespace
}  // namespace sloshsph::testing
