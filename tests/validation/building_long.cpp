// Thesis chapter 4 building with the four tanks of Table 4.1 (FR, SF, PF, TLD) under one hour of
// band-limited white-noise wind force (cases/building_<tank>_<level>mg.toml), against thesis
// Table 4.3 (effective damping of the structure-TLD system) and Table 4.4 (peak structural
// acceleration). Label `long`: one test per level, each four one-hour runs in sequence at the cases'
// dp = 0.1 m, h = 1.8 dp and the midpoint predictor (since 2026-12-07): at 10 milli-g (the adaptive
// step under 15 ms) about 35-60 min a run on one thread; at 44 milli-g 1.4-1.8 h a run on two threads
// for FR and SF (a fixed 5 ms: the adaptive step follows their spray) and 1.7-2.2 h on one thread for
// PF and TLD (adaptive) (ctest -j 2 runs the two levels side by side). Beside them, one test per run (BuildingRun, at the end of this file), so that a machine
// with more cores makes the eight runs at once and the two level tests then only compare.
//
// The bar: every run completes with no particle lost; the effective damping and the peak
// acceleration of each tank within 25% of the tables; the four tanks in the tables' order at each
// level. The order is checked as the number of pairs of tanks ranked the other way round than in
// the table (0 allowed). Several of the table's values differ by less than the 25% allowed on each
// (FR, SF, PF at 10 milli-g: 1.50, 1.53, 1.54%), so the order is the stricter check.
//
// Recorded beside them, not asserted: the perforated floor's RMS acceleration against Table 4.2,
// and, once a level, the structure without a tank under the same recorded load (the Newmark
// solution that summary.json also reports): its effective damping by the same estimator against
// its own 1%, and its peak against Table 4.4's STR row.
//
// Table 4.4's header gives m/s^2; its structure-alone row (10.16 and 44.75 under mean hourly peaks
// of 10 and 44 milli-g) shows the values are in milli-g, which is how they are compared here.
// The effective damping and the peak are those summary.json reports (run/structure_summary.hpp:
// zeta_eff from the variance of the whole record, Vickery et al. 1983; the peak of |a_s|).
//
// Each run is a run directory that outlives the test, $SLOSHSPH_LONG_RUN_DIR/building_<tank>_<level>mg
// (default <build>/long-runs), checkpointed every 60 s of simulated time. A test stopped on the way
// (Ctrl-C, ctest's timeout, the machine going down) loses at most that; run it again and it resumes
// each unfinished run and reuses each finished one. A run directory whose case.toml is not the case
// file's resolved case now (the case changed) fails the test: delete it to start that run again.
// So the eight runs (about 6.5 h each on one thread of the 2-core machine) can be spread over days,
// or made with `sloshsph run CASE --checkpoint-every 60 --out DIR` and placed there. A level test
// takes a run it does not find complete there from its committed record, docs/validation/runs/
// (run_record_dir below), so that the runs of several sessions and machines add up.
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <unistd.h>

#include "run_support.hpp"
#include "sloshsph/analysis/stats.hpp"
#include "sloshsph/core/errors.hpp"
#include "sloshsph/io/files.hpp"
#include "sloshsph/run/run_case.hpp"
#include "sloshsph/run/structure_summary.hpp"
#include "sloshsph/run/tank_as_tmd.hpp"
#include "validation_check.hpp"

namespace sloshsph {
namespace {

using testing::check_at_most;
using testing::check_relative;
using testing::report;

struct ThesisRow {
  std::string tank;          // case name part: fr, sf, pf, tld
  double zeta_percent;       // Table 4.3
  double peak_milli_g;       // Table 4.4
  double rms_milli_g = NAN;  // Table 4.2 (the perforated floor only)
};

struct Measured {
  double zeta_percent = NAN;
  double peak_milli_g = NAN;
  double rms_milli_g = NAN;
  // The structure without a tank under the run's recorded load (Newmark, as in summary.json):
  // the same estimator on the same hour, and Table 4.4's STR row.
  double zeta_without_tank_percent = NAN;
  double peak_without_tank_milli_g = NAN;
};

// Recorded beside a reference, not asserted (not in the bar).
void record(const std::string& what, const std::string& unit, double measured, double reference, double tolerance,
            const std::string& source) {
  testing::Check c{what, unit, measured, testing::Tolerance::relative, reference, tolerance, source};
  c.asserted = false;
  testing::check(c);
}

// Pairs (i, j) ranked one way by `ours` and the other way by `thesis` (a tie in either never counts).
int order_disagreements(const std::vector<double>& ours, const std::vector<double>& thesis) {
  int count = 0;
  for (std::size_t i = 0; i < ours.size(); ++i)
    for (std::size_t j = i + 1; j < ours.size(); ++j)
      if ((ours[i] - ours[j]) * (thesis[i] - thesis[j]) < 0.0) ++count;
  return count;
}

namespace fs = std::filesystem;

fs::path long_run_dir(const std::string& stem) {
  const char* env = std::getenv("SLOSHSPH_LONG_RUN_DIR");
  const fs::path base = env && *env ? fs::path(env) : fs::path(SLOSHSPH_BINARY_DIR) / "long-runs";
  return base / stem;
}

nlohmann::json read_json(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The settings of a resolved case, without the comment lines above its first blank line: those
// name the case file, by a relative path in a run made by hand from the project folder and by an
// absolute one here, and the two are the same case (as case_reader_test compares resolved cases).
std::string case_settings(const std::string& resolved) {
  const std::size_t body = resolved.find("\n\n");
  return body == std::string::npos ? resolved : resolved.substr(body);
}

// Whether the case.toml in `dir` (a run directory or a committed record) is `spec` resolved now.
bool holds_case(const fs::path& dir, const CaseSpec& spec) {
  return case_settings(read_text(dir / "case.toml")) == case_settings(resolved_case_toml(spec));
}

// Waits while another process holds the run directory's lock: a BuildingRun test beside this one
// (ctest -j), or a run made by hand.
void wait_while_another_process_runs(const fs::path& dir) {
  bool told = false;
  for (long pid; (pid = run_directory_lock_holder(dir.string())) > 0 && pid != ::getpid();) {
    if (!told) std::printf("  %s: process %ld is making this run; waiting for it to end\n", dir.c_str(), pid);
    told = true;
    std::this_thread::sleep_for(std::chrono::seconds(20));
  }
}

// Whether `dir` holds a completed run (its summary.json says so).
bool completed_in(const fs::path& dir) {
  const nlohmann::json done = read_json(dir / "summary.json");
  return done.is_object() && done.value("status", "") == "completed";
}

// Runs the case into `dir`, resumes it from its checkpoint, or finds it complete; returns whether
// `dir` holds the completed run of exactly this case (the test has failed otherwise). Where two
// tests start the same run at once, the one that locks the directory first makes it and the other
// waits for it.
bool complete_run(const CaseSpec& spec, const fs::path& dir) {
  for (int attempt = 1;; ++attempt) {
    wait_while_another_process_runs(dir);
    if (fs::exists(dir / "case.toml") && !holds_case(dir, spec)) {
      ADD_FAILURE() << dir << " holds a run of another version of " << spec.source
                    << " (its case.toml differs from the resolved case); delete the directory to run it again";
      return false;
    }
    if (completed_in(dir)) return true;
    install_stop_handlers();
    RunOptions o;
    o.out_dir = dir.string();
    o.progress = false;
    o.checkpoint_every = 60.0;
    o.command_line = "test_long --gtest_filter=" + testing::detail::current_test_name();
    int code = 0;
    std::string why;
    try {
      if (fs::exists(dir / "checkpoint.bin")) {
        code = resume_run(dir.string(), o);
      } else {
        o.force = true;  // a start that never reached its first checkpoint is begun again
        code = run_case(spec, o);
      }
    } catch (const InputError& e) {
      code = kExitBadInput;
      why = e.what();
    }
    // Another process locked the directory between the wait and the start: wait for that one.
    if (code == kExitBadInput && attempt < 3 && run_directory_lock_holder(dir.string()) > 0) continue;
    EXPECT_EQ(code, 0) << dir << ": the run "
                       << (code == kExitInterrupted ? "was interrupted (run the test again to resume it)"
                           : why.empty()            ? "failed (its summary.json says why)"
                                                    : "could not start: " + why);
    return code == 0;
  }
}

std::string building_stem(const std::string& tank, int level) {
  return "building_" + tank + "_" + std::to_string(level) + "mg";
}

CaseSpec building_case(const std::string& stem) {
  return resolve_case(read_case_file(testing::case_path(stem + ".toml"), {}));
}

// The bar for every run: no particle left the tank.
void check_no_leaks(const nlohmann::json& summary, const std::string& tank) {
  check_at_most("particles leaked from the tank in one hour, " + tank, summary.at("leaked_particles").get<double>(), 0.0,
                "none may leave");
}

// Makes, resumes or finds the completed run of `spec` (the case of `tank`) in `dir` and checks that
// no particle left the tank; returns its summary.json, or nothing when the run failed.
std::optional<nlohmann::json> completed_run_without_leaks(const CaseSpec& spec, const std::string& tank,
                                                          const fs::path& dir) {
  if (!complete_run(spec, dir)) return std::nullopt;
  nlohmann::json summary = read_json(dir / "summary.json");
  check_no_leaks(summary, tank);
  return summary;
}

void record_admittance_curve(const fs::path& dir, const std::string& tank, int level, const nlohmann::json& admittance);

// The committed record of a run (docs/validation/runs/<stem>/: summary.json, admittance.csv,
// case.toml, run.json, a few tens of kB; the hour's timeseries.csv is not kept) for a level test
// on a machine that has not made that run itself: a session of a few hours can make two of the
// eight runs, and its machine may not outlive it. Taken only when the run directory holds no
// completed run, when the record's case.toml is the case file's resolved case now, and unless
// SLOSHSPH_IGNORE_RUN_RECORDS is set (then every run is made here). A record says the git
// revision that made it; a change of the physics since is the reason to set that variable.
fs::path run_record_dir(const std::string& stem) {
  return fs::path(SLOSHSPH_SOURCE_DIR) / "docs" / "validation" / "runs" / stem;
}

std::optional<fs::path> usable_run_record(const CaseSpec& spec, const std::string& stem) {
  const char* ignore = std::getenv("SLOSHSPH_IGNORE_RUN_RECORDS");
  if ((ignore && *ignore) || completed_in(long_run_dir(stem))) return std::nullopt;
  const fs::path record = run_record_dir(stem);
  if (!completed_in(record)) return std::nullopt;
  if (!holds_case(record, spec)) {
    std::printf("  %s: a record of another version of the case; the run is made here\n", record.c_str());
    return std::nullopt;
  }
  return record;
}

// The run of `tank` at `level`: its directory and summary.json, made, resumed or found complete,
// or its committed record; nothing when the run failed (the test has failed then).
std::optional<std::pair<fs::path, nlohmann::json>> building_run(const CaseSpec& spec, const std::string& tank,
                                                                  const std::string& stem) {
  if (const std::optional<fs::path> record = usable_run_record(spec, stem)) {
    nlohmann::json summary = read_json(*record / "summary.json");
    check_no_leaks(summary, tank);
    return std::make_pair(*record, std::move(summary));
  }
  const fs::path dir = long_run_dir(stem);
  std::optional<nlohmann::json> completed = completed_run_without_leaks(spec, tank, dir);
  if (!completed) return std::nullopt;
  return std::make_pair(dir, std::move(*completed));
}

// The structure's summary: worked out again from the run's time series, or for a committed record
// (which has none) summary.json's (the same function wrote it at the end of the run).
nlohmann::json structure_summary_of(const CaseSpec& spec, const fs::path& dir, const nlohmann::json& summary,
                                    bool record) {
  if (record) return summary.at("structure");
  const CsvTable table = read_csv_table((dir / "timeseries.csv").string());
  return structure_summary(structure_series(table.names, table.columns), *spec.structure);
}

std::optional<Measured> run_building(const std::string& tank, int level) {
  const std::string stem = building_stem(tank, level);
  const CaseSpec spec = building_case(stem);
  const auto run = building_run(spec, tank, stem);
  if (!run) return std::nullopt;
  const auto& [dir, summary] = *run;
  const bool record = !fs::exists(dir / "timeseries.csv");
  const nlohmann::json meta = read_json(dir / "run.json");
  std::printf("  %s: git revision %s, %zu resumes, %.0f s of wall time%s\n", dir.c_str(),
              meta.value("git_revision", "?").c_str(), meta.contains("resumed") ? meta["resumed"].size() : 0,
              summary.value("wall_time_s", NAN), record ? " (committed record)" : "");
  const nlohmann::json s = structure_summary_of(spec, dir, summary, record);
  Measured m;
  m.zeta_percent = 100.0 * s.at("admittance").at("effective_damping_ratio").get<double>();
  m.peak_milli_g = s.at("acceleration").at("peak_milli_g").get<double>();
  m.rms_milli_g = s.at("acceleration").at("rms_milli_g").get<double>();
  const nlohmann::json& alone = s.at("structure_without_tank");
  m.zeta_without_tank_percent = 100.0 * alone.at("effective_damping_ratio").get<double>();
  m.peak_without_tank_milli_g = alone.at("acceleration").at("peak_milli_g").get<double>();
  const std::string key = stem + "_";
  report(key + "zeta_eff_percent", m.zeta_percent);
  report(key + "peak_acceleration_milli_g", m.peak_milli_g);
  report(key + "rms_acceleration_milli_g", m.rms_milli_g);
  // Against the structure alone under the same recorded load (Table 4.4's STR row is that for the thesis).
  report(key + "peak_acceleration_ratio_to_without_tank",
         s.at("acceleration").at("peak_ratio_to_without_tank").get<double>());
  report(key + "rms_acceleration_ratio_to_without_tank", s.at("acceleration").at("rms_ratio_to_without_tank").get<double>());
  report(key + "wall_seconds", summary.value("wall_time_s", NAN));
  // What the measured zeta_eff means as the damping of a linear TMD of this tank's mass and tuning
  // (run/tank_as_tmd.hpp; NaN where no linear tank gives it).
  const nlohmann::json tmd = equivalent_tmd_summary(spec, m.zeta_percent / 100.0);
  const nlohmann::json z = tmd.value("tank_damping_for_measured_effective_damping", nlohmann::json());
  report(key + "linear_tmd_tank_damping_percent", z.is_number() ? 100.0 * z.get<double>() : NAN);
  record_admittance_curve(dir, tank, level, s.at("admittance"));
  return m;
}

// The run's mechanical admittance (admittance.csv, thesis eq. 4.30) beside the structure alone's,
// within the load's band and up to 2.5 f_n (summary.json's `admittance` block gives both): the
// comparison plot of docs/validation.md.
void record_admittance_curve(const fs::path& dir, const std::string& tank, int level, const nlohmann::json& admittance) {
  const CsvTable adm = read_csv_table((dir / "admittance.csv").string());
  const std::vector<double>& f = adm.column("f_Hz");
  const std::vector<double>& with_tank = adm.column("H2_displacement");
  const std::vector<double>& alone = adm.column("H2_structure_alone");
  const double lo = admittance.at("band_Hz").at(0).get<double>();
  const double hi = std::min(admittance.at("band_Hz").at(1).get<double>(),
                             2.5 * admittance.at("natural_frequency_Hz").get<double>());
  std::string name = tank;
  for (char& ch : name) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  testing::Curve c{"admittance_" + tank,
                   "Mechanical admittance of the displacement, " + name + " tank, " + std::to_string(level) + " milli-g",
                   "frequency (Hz)", "|H(f)|^2", {}, {}, "structure alone (1% damping)", {}, {}, false, true};
  for (std::size_t k = 0; k < f.size(); ++k) {
    if (f[k] < lo || f[k] > hi) continue;
    c.x.push_back(f[k]);
    c.measured.push_back(with_tank[k]);
    c.reference_x.push_back(f[k]);
    c.reference_y.push_back(alone[k]);
  }
  testing::record_curve(c);
}

// `structure_peak_milli_g`: Table 4.4's STR row, the structure without a tank.
void compare_with_tables(int level, double structure_peak_milli_g, const std::vector<ThesisRow>& table) {
  const std::string at = std::to_string(level) + " milli-g";
  std::vector<double> zeta, peak, zeta_thesis, peak_thesis;
  for (const ThesisRow& row : table) {
    const std::optional<Measured> run = run_building(row.tank, level);
    if (!run) return;  // failed above with the reason; an interrupted test stops here
    const Measured& m = *run;
    check_relative("effective damping, " + row.tank + ", " + at, m.zeta_percent, row.zeta_percent, 0.25,
                   "thesis Table 4.3", "%");
    check_relative("peak structural acceleration, " + row.tank + ", " + at, m.peak_milli_g, row.peak_milli_g, 0.25,
                   "thesis Table 4.4 (values in milli-g)", "milli-g");
    if (!std::isnan(row.rms_milli_g)) {
      // Not in the bar, so recorded only. Table 4.2 is also at odds with Table 4.3: an
      // SDOF's RMS response goes as 1 / sqrt(zeta), and the structure alone (RMS 2.76 milli-g for
      // a mean hourly peak of 10.16, Davenport's peak factor 3.68) with zeta_eff = 1.54% would have
      // 2.22 milli-g, not 1.69.
      record("RMS structural acceleration, " + row.tank + ", " + at, "milli-g", m.rms_milli_g, row.rms_milli_g, 0.25,
             "thesis Table 4.2 (read in milli-g; at 10 milli-g its ER column, at 44 its MM column: the ER value is "
             "lost in the extracted text)");
    }
    if (zeta.empty()) {
      // The load is the same for the four tanks (one seed, one level), so once a level. The
      // estimator on the structure alone reads its own damping within 10% (the unit test's bar for
      // a white-noise response); a mean hourly peak is the level, one hour's peak scatters about it.
      record("effective damping of the structure without a tank, same load, " + at, "%", m.zeta_without_tank_percent,
             1.0, 0.10, "its own damping ratio, 1% (the estimator's reading of the structure alone)");
      record("peak acceleration of the structure without a tank, " + at, "milli-g", m.peak_without_tank_milli_g,
             structure_peak_milli_g, 0.25, "thesis Table 4.4, row STR");
    }
    zeta.push_back(m.zeta_percent);
    peak.push_back(m.peak_milli_g);
    zeta_thesis.push_back(row.zeta_percent);
    peak_thesis.push_back(row.peak_milli_g);
  }
  // The four tanks side by side (x: 1 FR, 2 SF, 3 PF, 4 TLD) against the tables.
  const std::vector<double> index = {1, 2, 3, 4};
  testing::record_curve({"effective_damping", "Effective damping, tanks 1 FR, 2 SF, 3 PF, 4 TLD, " + at, "tank",
                         "zeta_eff (%)", index, zeta, "thesis Table 4.3", index, zeta_thesis});
  testing::record_curve({"peak_acceleration", "Peak structural acceleration, tanks 1 FR, 2 SF, 3 PF, 4 TLD, " + at,
                         "tank", "peak a_s (milli-g)", index, peak, "thesis Table 4.4", index, peak_thesis});
  check_at_most("pairs of tanks ordered otherwise than Table 4.3 (effective damping), " + at,
                order_disagreements(zeta, zeta_thesis), 0.0, "thesis Table 4.3: the same order of FR, SF, PF, TLD");
  check_at_most("pairs of tanks ordered otherwise than Table 4.4 (peak acceleration), " + at,
                order_disagreements(peak, peak_thesis), 0.0, "thesis Table 4.4: the same order of FR, SF, PF, TLD");
}

TEST(ValidationLong, BuildingTanksAgainstTables43And44At10MilliG) {
  compare_with_tables(10, 10.16, {{"fr", 1.50, 7.35}, {"sf", 1.53, 5.26}, {"pf", 1.54, 5.98, 1.69}, {"tld", 2.25, 5.01}});
}

TEST(ValidationLong, BuildingTanksAgainstTables43And44At44MilliG) {
  compare_with_tables(44, 44.75, {{"fr", 0.94, 31.60}, {"sf", 2.28, 24.87}, {"pf", 1.97, 26.10, 7.43}, {"tld", 1.81, 24.67}});
}

// The TLD at 10 milli-g with the step three times larger (issue 29), the evidence for the step the
// building cases at 10 milli-g take since 2026-12-07: the midpoint position predictor, the density
// term relaxed over 50 ms, and the adaptive step (CFL 0.1 on the largest speed) under a 15 ms
// ceiling, against the case as it was before (Euler predictor, alpha = 0.01, a fixed 5 ms), both at
// h = 1.4 dp without the pair contact, as those runs were made. The reference is its committed
// record only (building_tld_10mg_h14_fixed_step, f1de608; the case file no longer holds it); the
// run at the larger step is the case file now with h = 1.4 dp and no pair contact, made here or
// taken from its record. Not the tables: the same run at the larger step. The bar is the issue's
// for a larger step (its Tait test: 2% on the crest, trough and energy per cycle), applied to what
// the building test reads: the effective damping, the peak and the RMS acceleration of the
// structure. Measured 2026-12-07: -1.9%, +1.3%, +1.0%; 241,574 steps against 720,000, 23:27 min of
// wall time on one thread beside another one-hour run.
const std::vector<std::string> kTheCaseAtKernelRatio14 = {"particles.kernel_ratio=1.4", "scheme.pair_contact=false",
                                                          "output.snapshot_interval=0"};

TEST(ValidationLong, BuildingTLD10MilliGAtTheAdaptiveMidpointStep) {
  const fs::path reference_record = run_record_dir("building_tld_10mg_h14_fixed_step");
  ASSERT_TRUE(completed_in(reference_record)) << reference_record << " holds no completed run";
  const nlohmann::json reference = read_json(reference_record / "summary.json");
  const CaseSpec spec =
      resolve_case(read_case_file(testing::case_path("building_tld_10mg.toml"), kTheCaseAtKernelRatio14));
  const auto run = building_run(spec, "tld", "building_tld_10mg_h14_adaptive_midpoint");
  if (!run) return;
  const nlohmann::json& summary = run->second;
  const nlohmann::json& s = summary.at("structure");
  const nlohmann::json& r = reference.at("structure");
  const std::string source = "the committed record of the case before (fixed 5 ms, Euler predictor; " +
                             reference.value("git_revision", std::string("?")) + ")";
  check_relative("effective damping, TLD, 10 milli-g, adaptive midpoint step",
                 100.0 * s.at("admittance").at("effective_damping_ratio").get<double>(),
                 100.0 * r.at("admittance").at("effective_damping_ratio").get<double>(), 0.02, source, "%");
  check_relative("peak structural acceleration, TLD, 10 milli-g, adaptive midpoint step",
                 s.at("acceleration").at("peak_milli_g").get<double>(),
                 r.at("acceleration").at("peak_milli_g").get<double>(), 0.02, source, "milli-g");
  check_relative("RMS structural acceleration, TLD, 10 milli-g, adaptive midpoint step",
                 s.at("acceleration").at("rms_milli_g").get<double>(),
                 r.at("acceleration").at("rms_milli_g").get<double>(), 0.02, source, "milli-g");
  report("building_tld_10mg_adaptive_midpoint_steps", summary.at("steps").get<double>());
  report("building_tld_10mg_adaptive_midpoint_wall_seconds", summary.value("wall_time_s", NAN));
}

// One test per run, ValidationLong.BuildingRun<tank><level>MilliG, so that a machine with the cores
// makes the eight runs at once (OMP_NUM_THREADS=1 ctest -L long -R BuildingRun -j 8, or sloshsph
// validate --long --filter BuildingRun --jobs 8); the two tests above then find them complete. Run
// beside those, each run is made once: the process that locks its directory first makes it, the
// others wait for it (complete_run).
void make_building_run(const std::string& tank, int level) {
  const std::string stem = building_stem(tank, level);
  completed_run_without_leaks(building_case(stem), tank, long_run_dir(stem));
}

TEST(ValidationLong, BuildingRunFR10MilliG) { make_building_run("fr", 10); }
TEST(ValidationLong, BuildingRunSF10MilliG) { make_building_run("sf", 10); }
TEST(ValidationLong, BuildingRunPF10MilliG) { make_building_run("pf", 10); }
TEST(ValidationLong, BuildingRunTLD10MilliG) { make_building_run("tld", 10); }
TEST(ValidationLong, BuildingRunFR44MilliG) { make_building_run("fr", 44); }
TEST(ValidationLong, BuildingRunSF44MilliG) { make_building_run("sf", 44); }
TEST(ValidationLong, BuildingRunPF44MilliG) { make_building_run("pf", 44); }
TEST(ValidationLong, BuildingRunTLD44MilliG) { make_building_run("tld", 44); }

}  // namespace
}  // namespace sloshsph
