// The analysis functions of src/sloshsph/analysis on NumPy arrays (copied in, copied out), the
// same code the runs' summary.json and `sloshsph report` use.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "sloshsph/analysis/admittance.hpp"
#include "sloshsph/analysis/filter.hpp"
#include "sloshsph/analysis/spectrum.hpp"
#include "sloshsph/analysis/steady_state.hpp"
#include "sloshsph/run/response.hpp"

namespace py = pybind11;

namespace sloshsph::python {
namespace {

using Series = std::vector<double>;

py::array_t<double> to_array(const Series& x) { return py::array_t<double>(x.size(), x.data()); }

// A spectrum handed in as its frequencies and values: the grid must be uniform from f = 0, as
// welch_psd makes it.
Spectrum spectrum_of(const Series& f, const Series& value, const char* what) {
  if (f.size() != value.size()) throw std::invalid_argument(std::string(what) + ": f and values differ in length");
  if (f.size() < 2) throw std::invalid_argument(std::string(what) + ": needs at least two frequencies");
  Spectrum s;
  s.f = f;
  s.value = value;
  s.df = f[1] - f[0];
  if (!(s.df > 0.0)) throw std::invalid_argument(std::string(what) + ": frequencies must increase");
  return s;
}

}  // namespace

void bind_analysis(py::module_& m) {
  m.def(
      "lowpass",
      [](const Series& x, double dt, double cutoff_hz, int order) {
        return to_array(lowpass_zero_phase(x, dt, cutoff_hz, order));
      },
      py::arg("x"), py::arg("dt"), py::arg("cutoff_hz"), py::arg("order"));
  m.def(
      "steady_state_amplitude",
      [](const Series& t, const Series& x, double period, int cycles) {
        const SteadyAmplitude a = steady_state_amplitude(t, x, period, cycles);
        py::dict d;
        d["avg_max"] = a.avg_max;
        d["avg_min"] = a.avg_min;
        d["cycles"] = a.cycles;
        return d;
      },
      py::arg("t"), py::arg("x"), py::arg("period"), py::arg("cycles"));
  m.def(
      "energy_per_cycle",
      [](const Series& t, const Series& force, const Series& displacement, double period, int cycles) {
        const CycleEnergy e = energy_per_cycle(t, force, displacement, period, cycles);
        return py::make_tuple(e.energy, e.cycles);
      },
      py::arg("t"), py::arg("force"), py::arg("displacement"), py::arg("period"), py::arg("cycles"));
  m.def(
      "energy_per_cycle_from_work",
      [](const Series& t, const Series& work, double period, int cycles) {
        const CycleEnergy e = energy_per_cycle_from_work(t, work, period, cycles);
        return py::make_tuple(e.energy, e.cycles);
      },
      py::arg("t"), py::arg("work"), py::arg("period"), py::arg("cycles"));
  m.def("normalised_energy", &normalised_energy, py::arg("energy_per_cycle"), py::arg("water_mass"),
        py::arg("amplitude"), py::arg("omega"));
  m.def(
      "welch_psd",
      [](const Series& x, double dt, std::size_t segment_length, double overlap) {
        const Spectrum s = welch_psd(x, dt, segment_length, overlap);
        return py::make_tuple(to_array(s.f), to_array(s.value));
      },
      py::arg("x"), py::arg("dt"), py::arg("segment_length"), py::arg("overlap"));
  m.def(
      "spectrum_integral",
      [](const Series& f, const Series& value, double f_lo, double f_hi) {
        return spectrum_integral(spectrum_of(f, value, "spectrum_integral"), f_lo, f_hi);
      },
      py::arg("f"), py::arg("value"), py::arg("f_lo"), py::arg("f_hi"));
  m.def("dominant_frequency", &dominant_frequency_fft, py::arg("x"), py::arg("dt"));
  m.def("zero_crossing_period", &zero_crossing_period, py::arg("t"), py::arg("x"));
  m.def(
      "admittance_flat_force",
      [](const Series& f, const Series& response_psd, double force_psd_level, double stiffness) {
        return to_array(
            mechanical_admittance(spectrum_of(f, response_psd, "admittance"), force_psd_level, stiffness).value);
      },
      py::arg("f"), py::arg("response_psd"), py::arg("force_psd_level"), py::arg("stiffness"));
  m.def(
      "admittance_measured_force",
      [](const Series& f, const Series& response_psd, const Series& force_psd, double stiffness, double floor) {
        return to_array(mechanical_admittance(spectrum_of(f, response_psd, "admittance"),
                                              spectrum_of(f, force_psd, "admittance"), stiffness, floor)
                            .value);
      },
      py::arg("f"), py::arg("response_psd"), py::arg("force_psd"), py::arg("stiffness"), py::arg("floor"));
  m.def(
      "sdof_admittance",
      [](const Series& f, double natural_frequency, double zeta) {
        Series out(f.size());
        for (std::size_t k = 0; k < f.size(); ++k) out[k] = sdof_admittance(f[k], natural_frequency, zeta);
        return to_array(out);
      },
      py::arg("f"), py::arg("natural_frequency"), py::arg("zeta"));
  m.def(
      "effective_damping_ratio",
      [](const Series& f, const Series& admittance, double natural_frequency, double f_lo, double f_hi) {
        return effective_damping_ratio(spectrum_of(f, admittance, "effective_damping_ratio"), natural_frequency,
                                       f_lo, f_hi);
      },
      py::arg("f"), py::arg("admittance"), py::arg("natural_frequency"), py::arg("f_lo"), py::arg("f_hi"));
  m.def(
      "steady_state_response",
      [](const std::vector<std::string>& names, const std::vector<std::string>& units,
         const std::vector<Series>& columns, double period, int cycles, double cutoff_hz, double water_mass,
         double amplitude, bool energy) {
        ResponseOptions o;
        o.period = period;
        o.cycles = cycles;
        o.cutoff_hz = cutoff_hz;
        o.water_mass = water_mass;
        o.amplitude = amplitude;
        o.energy = energy;
        return response_json(steady_state_response(names, units, columns, o)).dump();
      },
      py::arg("names"), py::arg("units"), py::arg("columns"), py::arg("period"), py::arg("cycles"),
      py::arg("cutoff_hz"), py::arg("water_mass"), py::arg("amplitude"), py::arg("energy"),
      "summary.json's `response` of a run, as a JSON text.");
}

}  // namespace sloshsph::python
