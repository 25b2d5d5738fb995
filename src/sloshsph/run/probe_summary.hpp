#pragma once
// The pressure probes of a run as summary.json reports them (key `pressure_probes`): where each
// reads (a point or a sensor face) and the first impact peak of its record (analysis/impact_peak.hpp).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sloshsph/core/case_spec.hpp"
#include "sloshsph/geometry/scene.hpp"

namespace sloshsph {

// One object per [[probes.pressure]], in case order:
//   name, column ("p:<name>"), from, to ([x, y] in 2D, [x, y, z] in 3D, m: equal for a point),
//   face_length_m (0 for a point), impact_peak: null when the record never rises above its first
//   sample, otherwise baseline_Pa, peak_Pa, peak_time_s, rise_start_s, rise_end_s, rise_time_s,
//   end_s, impulse_Pa_s.
// `names` and `columns` are the sampled series (the columns of timeseries.csv, "time" among them).
template <int D>
nlohmann::json pressure_probes_summary(const std::vector<PressureProbeSpec>& probes,
                                       const std::vector<BasicPressureSensor<D>>& sensors,
                                       const std::vector<std::string>& names,
                                       const std::vector<std::vector<double>>& columns);

}  // namespace sloshsph
