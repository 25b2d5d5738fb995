#include "sloshsph/run/run_case.hpp"

#include <omp.h>
#include <sys/resource.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <nlohmann/json.hpp>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/core/state_io.hpp"
#include "sloshsph/core/version.hpp"
#include "sloshsph/io/case_reader.hpp"
#include "sloshsph/io/csv_writer.hpp"
#include "sloshsph/io/files.hpp"
#include "sloshsph/io/vtk_writer.hpp"
#include "sloshsph/run/probe_summary.hpp"
#include "sloshsph/run/progress.hpp"
#include "sloshsph/run/response.hpp"
#include "sloshsph/run/screen_summary.hpp"
#include "sloshsph/run/structure_summary.hpp"
#include "sloshsph/run/simulation.hpp"
#include "sloshsph/run/tank_as_tmd.hpp"

namespace sloshsph {
namespace fs = std::filesystem;
namespace {

// The process's peak resident set (getrusage; Linux gives KiB): everything the run held at its
// largest, the program and libraries included. 0 if the system does not say.
double peak_resident_bytes() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) return 0.0;
  return static_cast<double>(usage.ru_maxrss) * 1024.0;
}

std::atomic<bool> g_stop{false};

void on_signal(int) { request_stop(); }

std::string now_iso8601() {
  const std::time_t t = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return buf;
}

std::string host_name() {
  char buf[256] = {0};
  if (gethostname(buf, sizeof buf - 1) != 0) return "unknown";
  return buf;
}

struct Snapshots;

// What a run writes into its directory, and the lock it holds on it.
struct RunFiles {
  std::unique_ptr<RunDirectoryLock> lock;  // first, so that it is released last
  std::string dir;
  nlohmann::json meta;
  std::unique_ptr<CsvWriter> csv;
  std::unique_ptr<Snapshots> snaps;
};

// Refuses a directory that is not one, or is not empty unless forced: before the case is set up
// (its settle can take minutes), so that a bad --out is reported at once. A directory with files
// in it may be another run's, still going, so it is locked now: --force must not empty it under
// that run. (An empty one is left as it is until the case has been accepted.)
void check_directory(RunFiles& files, bool force) {
  const std::string& dir = files.dir;
  std::error_code ec;
  if (!fs::exists(dir, ec)) return;
  if (!fs::is_directory(dir, ec)) throw InputError("--out " + dir, "", "exists and is not a directory");
  if (fs::is_empty(dir, ec)) return;
  if (!force)
    throw InputError("--out " + dir, "", "the run directory exists and is not empty; choose another --out or pass --force");
  files.lock = std::make_unique<RunDirectoryLock>(dir);
}

// Creates the checked directory, locks it if it is new, and empties it under --force (only now
// that the case has been accepted, and never under a run that is still going: it is locked).
void prepare_directory(RunFiles& files, bool force) {
  const std::string& dir = files.dir;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw InputError("--out " + dir, "", "cannot create the run directory: " + ec.message());
  if (!files.lock) files.lock = std::make_unique<RunDirectoryLock>(dir);
  if (force) {
    for (const char* name : {"timeseries.csv", "summary.json", "run.json", "case.toml", "particles.pvd",
                             "response.csv", "admittance.csv", "checkpoint.bin", "report.html"})
      fs::remove(fs::path(dir) / name, ec);
    fs::remove_all(fs::path(dir) / "particles", ec);
  }
  fs::create_directories(fs::path(dir) / "particles", ec);
  if (ec) throw InputError("--out " + dir, "", "cannot create the run directory: " + ec.message());
}

nlohmann::json run_metadata(const CaseSpec& spec, const RunOptions& o) {
  return {{"program", "sloshsph"},
          {"version", kVersion},
          {"git_revision", kGitRevision},
          {"command", o.command_line},
          {"case", spec.source},
          {"threads", omp_get_max_threads()},
          {"host", host_name()},
          {"started", now_iso8601()}};
}

// The sampled rows, kept for the analysis written at the end of the run.
struct SampledSeries {
  std::vector<std::vector<double>> columns;
  void add(const std::vector<double>& row) {
    if (columns.empty()) columns.resize(row.size());
    for (std::size_t k = 0; k < row.size(); ++k) columns[k].push_back(row[k]);
  }
};

// Steady-state response (response.hpp) for periodic excitation; null for other runs.
template <int D>
nlohmann::json analyse_response(const CaseSpec& spec, const BasicSimulation<D>& sim, const SampledSeries& series,
                                const std::string& dir) {
  const ExcitationSpec& e = spec.excitation;
  if ((e.type != ExcitationType::harmonic && e.type != ExcitationType::pitch) || !(e.omega > 0.0) ||
      series.columns.empty())
    return nullptr;
  std::vector<std::string> names, units;
  for (const BasicColumn<D>& c : sim.columns()) {
    names.push_back(c.name);
    units.push_back(c.unit);
  }
  const Response r = steady_state_response(names, units, series.columns,
                                           response_options(spec, sim.scene().initial_fluid_mass, D == 3));
  if (r.note.empty()) write_file_atomic((fs::path(dir) / "response.csv").string(), response_csv(r));
  return response_json(r);
}

struct Snapshots {
  std::string dir;
  bool walls;
  PvdIndex index;
  int count = 0;
  template <int D>
  void write(const BasicParticles<D>& p, double time) {
    char name[64];
    std::snprintf(name, sizeof name, "particles/particles_%06d.vtu", count++);
    write_vtu((fs::path(dir) / name).string(), p, walls);
    index.add(time, name);
  }
};

}  // namespace

void install_stop_handlers() {
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
}

bool stop_requested() { return g_stop.load(); }

void request_stop() { g_stop.store(true); }

ScopedStopHandlers::ScopedStopHandlers() {
  g_stop.store(false);
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, &before_int_);
  sigaction(SIGTERM, &action, &before_term_);
}

ScopedStopHandlers::~ScopedStopHandlers() {
  sigaction(SIGINT, &before_int_, nullptr);
  sigaction(SIGTERM, &before_term_, nullptr);
}

namespace {

// Where a run stands between steps, beyond the simulation itself: what a checkpoint adds to
// the simulation's state so that a resumed run writes exactly what the uninterrupted one would.
struct RunProgress {
  double next_sample = 0.0;
  double next_snapshot = 0.0;
  double next_checkpoint = 0.0;
  double checkpoint_every = 0.0;  // s of simulated time (0: only when interrupted)
  double wall_before = 0.0;  // wall seconds spent before this session (resumed runs)
  std::size_t csv_rows = 0;  // data rows in timeseries.csv
  SampledSeries series;
};

std::string read_text_file(const fs::path& path, const std::string& what) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "", "cannot read the " + what);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// checkpoint.bin: the case it belongs to, the simulation, then the run's progress.
template <int D>
void write_checkpoint(const BasicSimulation<D>& sim, const RunProgress& progress, const RunFiles& files, double wall_now) {
  StateWriter w;
  w.text("case", read_text_file(fs::path(files.dir) / "case.toml", "case.toml of the run"));
  sim.save_state(w);
  w.value("run.next_sample", progress.next_sample);
  w.value("run.next_snapshot", progress.next_snapshot);
  w.value("run.next_checkpoint", progress.next_checkpoint);
  w.value("run.checkpoint_every", progress.checkpoint_every);
  w.value("run.wall_seconds", wall_now);
  w.value("run.csv_rows", static_cast<std::uint64_t>(progress.csv_rows));
  w.value("run.series_columns", static_cast<std::uint64_t>(progress.series.columns.size()));
  for (const auto& column : progress.series.columns) w.array("run.series", column);
  w.value("run.snapshots", static_cast<std::uint64_t>(files.snaps->index.entries().size()));
  for (const auto& [time, name] : files.snaps->index.entries()) {
    w.value("run.snapshot_time", time);
    w.text("run.snapshot_file", name);
  }
  write_file_atomic((fs::path(files.dir) / "checkpoint.bin").string(), w.bytes());
}

RunProgress read_progress(StateReader& r, Snapshots& snaps) {
  RunProgress p;
  p.next_sample = r.value<double>("run.next_sample");
  p.next_snapshot = r.value<double>("run.next_snapshot");
  p.next_checkpoint = r.value<double>("run.next_checkpoint");
  p.checkpoint_every = r.value<double>("run.checkpoint_every");
  p.wall_before = r.value<double>("run.wall_seconds");
  p.csv_rows = static_cast<std::size_t>(r.value<std::uint64_t>("run.csv_rows"));
  const auto columns = r.value<std::uint64_t>("run.series_columns");
  for (std::uint64_t k = 0; k < columns; ++k) p.series.columns.push_back(r.array<double>("run.series"));
  std::vector<std::pair<double, std::string>> entries;
  const auto count = r.value<std::uint64_t>("run.snapshots");
  for (std::uint64_t k = 0; k < count; ++k) {
    const double time = r.value<double>("run.snapshot_time");
    entries.emplace_back(time, r.text("run.snapshot_file"));
  }
  snaps.count = static_cast<int>(entries.size());
  snaps.index.restore(std::move(entries));
  return p;
}

template <int D>
std::vector<std::string> column_names(const BasicSimulation<D>& sim) {
  std::vector<std::string> names;
  for (const BasicColumn<D>& c : sim.columns()) names.push_back(c.name);
  return names;
}

template <int D>
int run_loop(const CaseSpec& spec, BasicSimulation<D>& sim, RunFiles& files, RunProgress& progress,
             const RunOptions& options);

template <int D>
int run_case_in(const CaseSpec& spec, const RunOptions& options);
template <int D>
int resume_run_in(const std::string& dir, const CaseSpec& spec, StateReader& reader,
                  std::unique_ptr<RunDirectoryLock> lock, const RunOptions& options);

}  // namespace

int run_case(const CaseSpec& spec, const RunOptions& options) {
  if (spec.tank.dimensions == 3) return run_case_in<3>(spec, options);
  return run_case_in<2>(spec, options);
}

namespace {

template <int D>
int run_case_in(const CaseSpec& spec, const RunOptions& options) {
  RunFiles files;
  files.dir = options.out_dir.empty() ? (fs::path("out") / spec.name).string() : options.out_dir;
  check_directory(files, options.force);
  // Everything that can reject the case happens before the directory is touched.
  BasicSimulation<D> sim(spec);
  prepare_directory(files, options.force);
  for (const std::string& w : sim.scene().warnings) std::fprintf(stderr, "sloshsph: warning: %s\n", w.c_str());
  write_file_atomic((fs::path(files.dir) / "case.toml").string(), resolved_case_toml(spec));
  files.meta = run_metadata(spec, options);
  write_file_atomic((fs::path(files.dir) / "run.json").string(), files.meta.dump(2) + "\n");
  files.csv = std::make_unique<CsvWriter>((fs::path(files.dir) / "timeseries.csv").string(), column_names(sim));
  files.snaps = std::make_unique<Snapshots>(
      Snapshots{files.dir, spec.output.snapshot_walls, PvdIndex((fs::path(files.dir) / "particles.pvd").string())});
  RunProgress progress;
  const std::vector<double> row = sim.sample();
  files.csv->write_row(row);
  progress.series.add(row);
  progress.csv_rows = 1;
  if (spec.output.snapshot_interval > 0.0) files.snaps->write(sim.particles(), 0.0);
  progress.next_sample = spec.output.sample_interval;
  progress.next_snapshot = spec.output.snapshot_interval;
  progress.checkpoint_every = options.checkpoint_every;
  progress.next_checkpoint = options.checkpoint_every;
  return run_loop(spec, sim, files, progress, options);
}

}  // namespace

int resume_run(const std::string& dir, const RunOptions& options) {
  const fs::path case_path = fs::path(dir) / "case.toml";
  const fs::path checkpoint = fs::path(dir) / "checkpoint.bin";
  std::error_code ec;
  if (!fs::is_regular_file(case_path, ec)) throw InputError(dir, "", "not a run directory (no case.toml)");
  // Locked before anything is read: the run that holds it may be writing a checkpoint.
  auto lock = std::make_unique<RunDirectoryLock>(dir);
  if (!fs::is_regular_file(checkpoint, ec))
    throw InputError(dir, "", "no checkpoint.bin to resume from (a completed run has none; a run writes one with "
                              "--checkpoint-every, and when interrupted)");
  const std::string case_text = read_text_file(case_path, "case.toml of the run");
  CaseSpec spec = resolve_case(read_case_file(case_path.string(), {}));
  // Named after its file, the case would be called "case" in the messages: the run's directory
  // names it better.
  const fs::path run_path = fs::absolute(dir).lexically_normal();
  spec.name = (run_path.has_filename() ? run_path : run_path.parent_path()).filename().string();
  StateReader reader(read_text_file(checkpoint, "checkpoint"), checkpoint.string());
  if (reader.text("case") != case_text)
    throw InputError(case_path.string(), "", "case.toml changed since the checkpoint was written; refusing to resume");
  if (spec.tank.dimensions == 3) return resume_run_in<3>(dir, spec, reader, std::move(lock), options);
  return resume_run_in<2>(dir, spec, reader, std::move(lock), options);
}

namespace {

template <int D>
int resume_run_in(const std::string& dir, const CaseSpec& spec, StateReader& reader,
                  std::unique_ptr<RunDirectoryLock> lock, const RunOptions& options) {
  const fs::path checkpoint = fs::path(dir) / "checkpoint.bin";
  BasicSimulation<D> sim(spec, SimulationStart::for_checkpoint);
  sim.load_state(reader);
  RunFiles files;
  files.lock = std::move(lock);
  files.dir = dir;
  files.snaps = std::make_unique<Snapshots>(
      Snapshots{dir, spec.output.snapshot_walls, PvdIndex((fs::path(dir) / "particles.pvd").string())});
  RunProgress progress = read_progress(reader, *files.snaps);
  if (!reader.at_end()) throw InputError(checkpoint.string(), "", "trailing data after the last record");
  files.csv = std::make_unique<CsvWriter>((fs::path(dir) / "timeseries.csv").string(), column_names(sim),
                                          progress.csv_rows);
  try {
    files.meta = nlohmann::json::parse(read_text_file(fs::path(dir) / "run.json", "run.json"));
  } catch (const nlohmann::json::exception&) {
    files.meta = run_metadata(spec, options);
  }
  files.meta["resumed"].push_back({{"at_time_s", sim.time()}, {"started", now_iso8601()}, {"command", options.command_line},
                                   {"threads", omp_get_max_threads()}});
  write_file_atomic((fs::path(dir) / "run.json").string(), files.meta.dump(2) + "\n");
  std::fprintf(stderr, "sloshsph: resuming %s at t = %.6g s (step %zu)\n", dir.c_str(), sim.time(), sim.steps());
  // The resumed run keeps checkpointing as planned (the same times: the results do not depend
  // on where a run was interrupted), unless --checkpoint-every gives a new interval.
  if (options.checkpoint_every > 0.0 && options.checkpoint_every != progress.checkpoint_every) {
    progress.checkpoint_every = options.checkpoint_every;
    progress.next_checkpoint = sim.time() + options.checkpoint_every;
  }
  return run_loop(spec, sim, files, progress, options);
}

// A warning for each of the first steps whose pressure solve found a block of fluid that no p = 0
// condition reaches and set it to p = 0 (IsphScheme::pin_unanchored_blocks); summary.json counts
// them all.
template <int D>
void warn_pinned(const BasicSimulation<D>& sim) {
  constexpr std::size_t kWarnings = 10;
  if (sim.last_step_pinned() == 0 || sim.pinned_steps() > kWarnings) return;
  std::fprintf(stderr,
               "sloshsph: warning: t = %.6g s: %zu fluid particles in a pressure block that no free surface reaches "
               "(a jet pressed against a wall?) set to p = 0 for this step%s\n",
               sim.time(), sim.last_step_pinned(),
               sim.pinned_steps() == kWarnings ? " (further cases are counted in summary.json, not shown)" : "");
}

// One sway direction of the structure (summary.json `key`): RMS and peak response, and under a noise
// load the admittance, the effective damping and the linear equivalent TMD; its admittance file.
void summarise_sway(nlohmann::json& s, const std::string& key, const StructureSeries& ss, const StructureSpec& mode,
                    const CaseSpec& spec, bool along_y, const fs::path& admittance_file) {
  s[key] = structure_summary(ss, mode);
  if (spec.structure->tanks >= 1 && mode.load.type == StructureLoadType::noise) {
    const nlohmann::json& admittance = s[key].value("admittance", nlohmann::json::object());
    std::optional<double> measured;
    if (admittance.contains("effective_damping_ratio")) measured = admittance["effective_damping_ratio"].get<double>();
    s[key]["equivalent_tmd"] = equivalent_tmd_summary(spec, measured, along_y);
  }
  if (auto a = structure_admittance(ss, mode)) write_file_atomic(admittance_file.string(), admittance_csv(*a));
}

template <int D>
int run_loop(const CaseSpec& spec, BasicSimulation<D>& sim, RunFiles& files, RunProgress& progress,
             const RunOptions& options) {
  const std::string& dir = files.dir;
  const double counted_since = sim.time();
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] { return progress.wall_before + std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  Progress bar(spec.time.end, options.progress);
  auto write_sample = [&] {
    const std::vector<double> row = sim.sample();
    files.csv->write_row(row);
    progress.series.add(row);
    ++progress.csv_rows;
    if (options.on_sample) options.on_sample(sim.time(), spec.time.end, sim.steps());
  };
  const bool snapshots = spec.output.snapshot_interval > 0.0;
  const double tol = 1e-9;
  const double every = progress.checkpoint_every;

  std::string status = "completed", failure;
  int code = kExitSuccess;
  try {
    while (!sim.finished()) {
      if (stop_requested()) {
        status = "interrupted";
        code = kExitInterrupted;
        write_checkpoint(sim, progress, files, elapsed());
        break;
      }
      sim.step();
      warn_pinned(sim);
      if (sim.time() >= progress.next_sample - tol || sim.finished()) {
        write_sample();
        while (progress.next_sample <= sim.time() + tol) progress.next_sample += spec.output.sample_interval;
      }
      if (snapshots && sim.time() >= progress.next_snapshot - tol) {
        files.snaps->write(sim.particles(), sim.time());
        while (progress.next_snapshot <= sim.time() + tol) progress.next_snapshot += spec.output.snapshot_interval;
      }
      if (every > 0.0 && sim.time() >= progress.next_checkpoint - tol && !sim.finished()) {
        while (progress.next_checkpoint <= sim.time() + tol) progress.next_checkpoint += every;
        write_checkpoint(sim, progress, files, elapsed());
      }
      bar.update(sim.time(), sim.steps());
    }
  } catch (const RunFailure& e) {
    status = "failed";
    failure = e.what();
    code = kExitRunFailed;
    // The state the failure was found in (the step that failed has run: it may hold the
    // non-finite values that failed it). A sample of it that fails in turn must not lose the
    // summary: its reason is added to the failure's.
    try {
      write_sample();
      if (snapshots) files.snaps->write(sim.particles(), sim.time());
    } catch (const std::exception& again) {
      failure += std::string("; the failed state could not be sampled: ") + again.what();
    }
  }
  bar.finish(sim.time(), sim.steps());
  const double wall = elapsed();
  if (status == "completed") fs::remove(fs::path(dir) / "checkpoint.bin");
  const SampledSeries& series = progress.series;
  nlohmann::json& meta = files.meta;
  const BasicParticles<D>& p = sim.particles();
  const double total_particles = static_cast<double>(p.size() + sim.leaked());
  nlohmann::json s;
  s["status"] = status;
  s["steps"] = sim.steps();
  s["simulated_time_s"] = sim.time();
  s["wall_time_s"] = wall;
  s["fluid_particles"] = sim.scene().initial_fluid_count;
  s["wall_particles"] = p.n_wall();
  s["leaked_particles"] = sim.leaked();
  s["wall_contacts"] = sim.wall_contacts();
  s["pair_contacts"] = sim.pair_contacts();
  if (sim.spec().scheme.shifting != ShiftingModel::none) s["shifts_limited"] = sim.shifts_limited();
  s["pressure_pinned"] = {{"steps", sim.pinned_steps()},
                          {"particles", sim.pinned_particles()},
                          {"counted_since_s", counted_since}};  // this process's start (not in checkpoints)
  s["particle_steps_per_second"] = wall > 0 ? total_particles * sim.steps() / wall : 0.0;
  s["fluid_particle_steps_per_second"] =
      wall > 0 ? static_cast<double>(sim.scene().initial_fluid_count) * sim.steps() / wall : 0.0;
  s["wall_seconds_per_simulated_second"] = sim.time() > 0 ? wall / sim.time() : 0.0;
  s["threads"] = omp_get_max_threads();
  s["dp_m"] = spec.particles.dp;
  s["h_m"] = sim.scene().h;
  s["dt_s"] = spec.time.dt;
  s["dt_adaptive"] = spec.time.adaptive;
  if (spec.time.dt_min > 0.0)
    s["dt_floor"] = {{"dt_min_s", spec.time.dt_min},
                     {"steps", sim.floor_steps()},
                     {"largest_cfl", sim.largest_floor_cfl()},
                     {"counted_since_s", counted_since}};
  if constexpr (D == 2) {
    s["fluid_mass_kg_per_m"] = sim.scene().initial_fluid_mass;
    s["final_fluid_mass_kg_per_m"] = sim.fluid_mass();
  } else {
    s["dimensions"] = 3;
    s["fluid_mass_kg"] = sim.scene().initial_fluid_mass;
    s["final_fluid_mass_kg"] = sim.fluid_mass();
  }
  // Computed once at the start (run_case), so no input error can surface after the directory exists.
  s["omega1_linear_rad_s"] = sim.linear_omega();
  if (spec.excitation.type != ExcitationType::none) s["excitation_omega_rad_s"] = spec.excitation.omega;
  s["neighbour_list_builds"] = sim.scheme().neighbours().builds();
  MemoryParts memory = sim.scheme().memory_parts();
  memory.push_back({"pair_contact", sim.pair_contact_memory_bytes()});
  s["memory_bytes_per_particle"] = static_cast<double>(total_bytes(memory)) / total_particles;
  nlohmann::json by_part = nlohmann::json::object();
  for (const MemoryPart& part : memory) by_part[part.name] = static_cast<double>(part.bytes) / total_particles;
  s["memory_bytes_per_particle_by_part"] = by_part;
  s["peak_resident_memory_bytes"] = peak_resident_bytes();
  nlohmann::json units = nlohmann::json::object();
  for (const BasicColumn<D>& c : sim.columns()) units[c.name] = c.unit;
  s["columns"] = units;
  s["version"] = kVersion;
  s["git_revision"] = kGitRevision;
  if (nlohmann::json response = analyse_response(spec, sim, series, dir); !response.is_null())
    s["response"] = response;
  if (!sim.screens().elements.empty()) s["screens"] = screens_summary(sim.screens().elements);
  if (!spec.pressure_probes.empty())
    s["pressure_probes"] =
        pressure_probes_summary(spec.pressure_probes, sim.scene().pressure_sensors, column_names(sim), series.columns);
  if (spec.structure_y && !series.columns.empty()) {
    // 3D: the sway along y, analysed as the sway along x below (summary "structure_y",
    // admittance_y.csv; the equivalent TMD of a box's mode across the breadth).
    StructureSeries ss = structure_series(column_names(sim), series.columns, "", "_y");
    if (spec.structure->ground_from_excitation)
      for (const double t : ss.time) ss.ground_acceleration.push_back(sim.ground_motion(t).acceleration_y);
    summarise_sway(s, "structure_y", ss, *spec.structure_y, spec, true, fs::path(dir) / "admittance_y.csv");
  }
  if (spec.structure && !series.columns.empty()) {
    // RMS and peak response, and for noise loads the admittance and effective damping.
    StructureSeries ss = structure_series(column_names(sim), series.columns);
    if (spec.structure->ground_from_excitation)  // the same ground motion for the structure without tanks
      for (const double t : ss.time) ss.ground_acceleration.push_back(sim.ground_motion(t).acceleration.x);
    summarise_sway(s, "structure", ss, *spec.structure, spec, false, fs::path(dir) / "admittance.csv");
  }
  if (!sim.plates().empty()) {
    nlohmann::json plates = nlohmann::json::array();
    const std::string up = D == 2 ? "y" : "z";  // the section's height: y in 2D, z in 3D
    for (const BasicPlateCoupling<D>& pl : sim.plates()) {
      const Vec2 tip = pl.tip_displacement();
      nlohmann::json j = {{"name", pl.spec().name},
                          {"max_abs_tip_dx_m", pl.max_abs_tip_dx()},
                          {"final_tip_dx_m", tip.x},
                          {"final_tip_d" + up + "_m", tip.y},
                          {"length_m", pl.beam().length()},
                          {"elements", pl.beam().element_count()},
                          {"wall_particles", pl.count()},
                          {"width_m", pl.width()},
                          {"bending_stiffness_N_m", pl.beam().section().bending},
                          {"mass_per_length_kg_per_m2", pl.spec().density * pl.spec().thickness},
                          {"crossings", pl.crossings()},
                          {"contacts", pl.contacts()}};
      if (pl.crossings() > 0) {
        const PlateCrossing& c = pl.first_crossing();
        j["first_crossing_time_s"] = c.time;
        j["first_crossing_id"] = c.id;
        j["first_crossing_x"] = c.position.x;
        j["first_crossing_" + up] = c.position.y;
        j["first_crossing_arc_length_m"] = c.arc_length;
      }
      plates.push_back(j);
    }
    s["plates"] = plates;
  }
  if (!failure.empty()) s["failure"] = failure;
  if (!sim.scene().warnings.empty()) s["warnings"] = sim.scene().warnings;
  if (sim.leaked() > 0) {
    nlohmann::json leaks = nlohmann::json::array();
    for (const BasicLeakRecord<D>& l : sim.leaks()) {
      if (leaks.size() >= 100) break;
      nlohmann::json leak = {{"time_s", l.time}, {"id", l.id}, {"x", l.position.x}, {"y", l.position.y}};
      if constexpr (D == 3) leak["z"] = l.position.z;
      leaks.push_back(leak);
    }
    s["leaks_first_100"] = leaks;
  }
  write_file_atomic((fs::path(dir) / "summary.json").string(), s.dump(2) + "\n");
  meta["finished"] = now_iso8601();
  meta["status"] = status;
  write_file_atomic((fs::path(dir) / "run.json").string(), meta.dump(2) + "\n");

  if (code == kExitRunFailed) std::fprintf(stderr, "sloshsph: run failed: %s\n", failure.c_str());
  if (code == kExitInterrupted)
    std::fprintf(stderr, "sloshsph: interrupted at t = %.4f s; outputs are consistent up to that time\n", sim.time());
  std::fprintf(stderr, "sloshsph: %s %s in %s (%zu steps, %.3g particle-steps/s) -> %s\n", status.c_str(),
               spec.name.c_str(), format_duration(wall).c_str(), sim.steps(),
               s["particle_steps_per_second"].get<double>(), dir.c_str());
  return code;
}

}  // namespace
}  // namespace sloshsph
