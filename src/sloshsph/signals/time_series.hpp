#pragma once
// A sampled signal (time, value) and its linear interpolation.
#include <cstddef>
#include <string>
#include <vector>

namespace sloshsph {

// Standard gravity (BIPM / ISO 80000-3), used to convert records given in g to m/s^2.
inline constexpr double kStandardGravity = 9.80665;  // m/s^2

// A signal sampled at strictly increasing times (not necessarily uniform).
struct TimeSeries {
  std::vector<double> t;      // s
  std::vector<double> value;  // SI unit of the quantity (m/s^2 for an acceleration record, N for a force)

  std::size_t size() const { return t.size(); }
  double start() const { return t.front(); }
  double end() const { return t.back(); }
};

// Samples t_i = t0 + i dt for the given values.
TimeSeries uniform_series(double dt, std::vector<double> values, double t0 = 0.0);

// Linear interpolation of the series at time t. Outside [start, end] the signal is ZERO:
// a record describes an excitation that has not started yet or is over (an acceleration
// or a force). Integrated quantities (velocity, displacement) do not follow this rule:
// see base_motion_record.hpp. The series must have at least 2 samples.
// Cost: O(log n) (binary search).
double sample(const TimeSeries& series, double t);

// Throws std::invalid_argument unless the series has >= 2 samples, equal lengths and
// strictly increasing finite times (`what` names the series in the message).
void check_time_series(const TimeSeries& series, const std::string& what);

}  // namespace sloshsph
