#pragma once
// Front-position data and their comparison with a simulated front (dam-break validations).
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "validation_check.hpp"

namespace sloshsph::testing {

struct Sample {
  double t = 0.0;  // s
  double x = 0.0;  // m
};

// Koshizuka & Oka (1996) as shipped by DualSPHysics: a citation line, a header, then
// "time<TAB>x" rows (s, m). Rows beyond the far wall of the 4 m tank (x > 4 m) are left out.
inline std::vector<Sample> read_front_data(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::getline(in, line);
  std::vector<Sample> out;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    Sample s;
    if (row >> s.t >> s.x && s.x <= 4.0) out.push_back(s);
  }
  return out;
}

// The simulated front at time t, linear between samples (NaN outside the series).
inline double front_at(const std::vector<Sample>& run, double t) {
  for (std::size_t i = 1; i < run.size(); ++i)
    if (run[i].t >= t && run[i - 1].t <= t) {
      const double w = (t - run[i - 1].t) / (run[i].t - run[i - 1].t);
      return run[i - 1].x + w * (run[i].x - run[i - 1].x);
    }
  return std::numeric_limits<double>::quiet_NaN();
}

// RMS of simulated minus measured front, the data's clock started `shift` s late (the
// simulation is compared at t_data - shift).
inline double front_rms(const std::vector<Sample>& run, const std::vector<Sample>& data, double shift) {
  double sum = 0.0;
  int n = 0;
  for (const Sample& d : data) {
    const double x = front_at(run, d.t - shift);
    if (std::isnan(x)) continue;
    sum += (x - d.x) * (x - d.x);
    ++n;
  }
  return n > 0 ? std::sqrt(sum / n) : std::numeric_limits<double>::infinity();
}

struct Shift {
  double shift = 0.0;  // s
  double rms = 0.0;    // m
};

// The shift in [lo, hi] (1 ms steps) with the smallest RMS.
inline Shift best_shift(const std::vector<Sample>& run, const std::vector<Sample>& data, double lo, double hi) {
  Shift best{lo, front_rms(run, data, lo)};
  for (double s = lo; s <= hi + 1e-12; s += 0.001) {
    const double r = front_rms(run, data, s);
    if (r < best.rms) best = {s, r};
  }
  return best;
}

// The simulated front beside the experiment's points, as a comparison curve (record_curve).
inline void record_front_curve(const std::string& name, const std::string& title, const std::string& y_label,
                               const std::vector<Sample>& run, const std::vector<Sample>& data,
                               const std::string& data_label) {
  Curve c{name, title, "time (s)", y_label, {}, {}, data_label, {}, {}};
  for (const Sample& s : run) {
    c.x.push_back(s.t);
    c.measured.push_back(s.x);
  }
  for (const Sample& d : data) {
    c.reference_x.push_back(d.t);
    c.reference_y.push_back(d.x);
  }
  record_curve(c);
}

}  // namespace sloshsph::testing
