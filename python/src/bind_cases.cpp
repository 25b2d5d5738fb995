// Cases from Python: a case is its TOML text, the name of its source and the --set overrides
// applied to it; the engine reads, checks and resolves it exactly as the command line does.
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "sloshsph/core/errors.hpp"
#include "sloshsph/geometry/tank.hpp"
#include "sloshsph/io/case_reader.hpp"
#include "sloshsph/linear/tuning.hpp"
#include "sloshsph/run/linear_case.hpp"
#include "sloshsph/run/modes_summary.hpp"
#include "sloshsph/run/simulation.hpp"

namespace py = pybind11;

namespace sloshsph::python {

CaseSpec load_case(const std::string& text, const std::string& source, const std::string& name,
                   const std::vector<std::string>& overrides) {
  CaseSpec spec = read_case_text(text, source, overrides);
  if (!name.empty()) spec.name = name;
  return resolve_case(spec);
}

void bind_errors() {
  // The classes live in sloshsph/errors.py (so that they have docstrings and attributes); they are
  // looked up when an error is raised, by which time the package is imported.
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      py::object cls = py::module_::import("sloshsph.errors").attr("CaseError");
      PyErr_SetObject(cls.ptr(), py::make_tuple(e.what(), e.where(), e.key(), e.message()).ptr());
    } catch (const RunFailure& e) {  // before the run directory exists (a settle that blows up)
      py::object cls = py::module_::import("sloshsph.errors").attr("RunFailed");
      PyErr_SetObject(cls.ptr(), py::make_tuple(std::string("run failed: ") + e.what()).ptr());
    } catch (const Interrupted& e) {
      py::object cls = py::module_::import("sloshsph.errors").attr("Interrupted");
      PyErr_SetObject(cls.ptr(), py::make_tuple(e.what()).ptr());
    }
  });
}

void bind_cases(py::module_& m) {
  m.def("default_case_text", [] { return default_case_text(); }, "The built-in default case (TOML).");
  m.def(
      "check_case",
      [](const std::string& text, const std::string& source, const std::string& name,
         const std::vector<std::string>& overrides) {
        const CaseSpec spec = load_case(text, source, name, overrides);
        return py::make_tuple(spec.name, resolved_case_toml(spec));
      },
      py::arg("text"), py::arg("source"), py::arg("name"), py::arg("overrides"),
      "Reads and resolves a case; returns (name, resolved TOML). Raises CaseError.");
  m.def(
      "read_case_file_text", [](const std::string& path) { return py::bytes(read_case_file_text(path)); },
      py::arg("path"), "The bytes of a case file; raises CaseError as the program does.");
  m.def("case_text_with_overrides", &case_text_with_overrides, py::arg("text"), py::arg("source"),
        py::arg("overrides"), "The case's TOML with the overrides applied (not resolved).");
  m.def(
      "modes",
      [](const std::string& text, const std::string& source, const std::string& name,
         const std::vector<std::string>& overrides, int count, const std::vector<double>& tank_damping,
         double frequency_scale) {
        const CaseSpec spec = load_case(text, source, name, overrides);
        return modes_json(modes_summary(spec, count, tank_damping, frequency_scale)).dump();
      },
      py::arg("text"), py::arg("source"), py::arg("name"), py::arg("overrides"), py::arg("count"),
      py::arg("tank_damping"), py::arg("frequency_scale"), "`sloshsph modes --json` as a JSON text.");
  m.def(
      "linear",
      [](const std::string& text, const std::string& source, const std::string& name,
         const std::vector<std::string>& overrides, int modes, const std::string& damping, bool screens) {
        const CaseSpec spec = load_case(text, source, name, overrides);
        const LinearCase r = linear_case_response(spec, LinearCaseOptions{modes, damping, screens});
        py::dict series;
        series["time"] = r.response.time;
        for (std::size_t g = 0; g < r.gauge_names.size(); ++g) series[("eta:" + r.gauge_names[g]).c_str()] = r.response.elevation[g];
        series["F_w"] = r.response.wall_force;
        series["F_sw"] = r.response.sloshing_force;
        py::list mode_list;
        for (std::size_t n = 0; n < r.modes.size(); ++n) {
          py::dict d;
          d["omega"] = r.modes[n].omega;
          d["zeta"] = r.damping[n];
          d["horizontal_forcing"] = r.modes[n].horizontal_forcing;
          mode_list.append(d);
        }
        py::dict out;
        out["series"] = series;
        out["modes"] = mode_list;
        out["damping_model"] = r.damping_model;
        py::list screen_list;
        for (const LinearScreen& s : r.screens) {
          py::dict d;
          d["x"] = s.x;
          d["z_from"] = s.z_from;
          d["z_to"] = s.z_to;
          d["loss_coefficient"] = s.loss_coefficient;
          d["linear_resistance"] = s.linear_resistance;
          screen_list.append(d);
        }
        out["screens"] = screen_list;
        out["ignored"] = r.ignored;
        return out;
      },
      py::arg("text"), py::arg("source"), py::arg("name"), py::arg("overrides"), py::arg("modes"),
      py::arg("damping"), py::arg("screens"), "`sloshsph linear` as a dict (run/linear_case.hpp).");
  m.def(
      "tune",
      [](const std::string& text, const std::string& source, const std::string& name,
         const std::vector<std::string>& overrides, double target_omega, std::optional<double> mass) {
        const CaseSpec spec = load_case(text, source, name, overrides);
        const TankGeometry tank = make_tank(spec.tank, spec.where("tank.shape"));
        const TunedTank t = tune_for_omega(tank, target_omega, spec.fluid.gravity, mass, spec.fluid.density);
        py::dict d;
        d["target_omega"] = target_omega;
        d["depth"] = t.depth;
        d["omega"] = t.omega;
        d["area"] = t.area;
        if (t.width) {
          d["mass"] = *t.water_mass;
          d["width"] = *t.width;
        }
        return d;
      },
      py::arg("text"), py::arg("source"), py::arg("name"), py::arg("overrides"), py::arg("target_omega"),
      py::arg("mass"), "`sloshsph tune --json` as a dict.");
}

}  // namespace sloshsph::python
