#pragma once
// Runs a case in memory and keeps its time series, for the validation tests.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "sloshsph/io/case_reader.hpp"
#include "sloshsph/run/simulation.hpp"

namespace sloshsph::testing {

inline std::string case_path(const std::string& name) { return std::string(SLOSHSPH_SOURCE_DIR) + "/cases/" + name; }

struct RunResult {
  std::map<std::string, std::vector<double>> series;  // column name -> samples
  std::size_t leaked = 0;
  double max_speed_end = 0.0;
  double wall_seconds = 0.0;
  std::size_t steps = 0;
  const std::vector<double>& operator[](const std::string& c) const { return series.at(c); }
  // The largest sample of column c (counts such as plate_crossings or plate_inside).
  double max(const std::string& c) const {
    const std::vector<double>& v = series.at(c);
    return *std::max_element(v.begin(), v.end());
  }
  // The mean of the samples of column c with from <= t <= to (NaN if none).
  double mean(const std::string& c, double from, double to) const {
    const std::vector<double>& t = series.at("time");
    const std::vector<double>& v = series.at(c);
    double sum = 0.0;
    int n = 0;
    for (std::size_t k = 0; k < t.size(); ++k)
      if (t[k] >= from && t[k] <= to) {
        sum += v[k];
        ++n;
      }
    return n > 0 ? sum / n : std::nan("");
  }
};

// Reads the case file at `path` (run_case_in_memory: cases/<name>) with the overrides, runs it to time.end sampling every
// output.sample_interval, and returns the columns. `inspect` sees the final simulation. D = 3 for
// a case with tank.dimensions = 3.
template <int D = 2, class Inspect>
RunResult run_file_in_memory(const std::string& path, const std::vector<std::string>& overrides, Inspect&& inspect) {
  const CaseSpec spec = resolve_case(read_case_file(path, overrides));
  const auto start = std::chrono::steady_clock::now();
  BasicSimulation<D> sim(spec);
  RunResult r;
  auto record = [&](const std::vector<double>& row) {
    for (std::size_t k = 0; k < row.size(); ++k) r.series[sim.columns()[k].name].push_back(row[k]);
  };
  record(sim.sample());
  double next = spec.output.sample_interval;
  while (!sim.finished()) {
    sim.step();
    if (sim.time() >= next - 1e-9 || sim.finished()) {
      record(sim.sample());
      while (next <= sim.time() + 1e-9) next += spec.output.sample_interval;
    }
  }
  r.leaked = sim.leaked();
  r.max_speed_end = sim.max_speed();
  r.steps = sim.steps();
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  inspect(sim);
  return r;
}

template <class Inspect>
RunResult run_case_in_memory(const std::string& name, const std::vector<std::string>& overrides, Inspect&& inspect) {
  return run_file_in_memory(case_path(name), overrides, std::forward<Inspect>(inspect));
}

inline RunResult run_case_in_memory(const std::string& name, const std::vector<std::string>& overrides) {
  return run_case_in_memory(name, overrides, [](const Simulation&) {});
}

// Records a measured number in the test output (and the XML report) for docs/validation.md.
inline void report(const std::string& key, double value) {
  ::testing::Test::RecordProperty(key, std::to_string(value));
  std::printf("  measured %s = %.6g\n", key.c_str(), value);
}

}  // namespace sloshsph::testing
