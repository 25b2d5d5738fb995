// Runs from Python: the command line's run_case and resume_run, without Python's global lock while
// the engine steps, with SIGINT/SIGTERM stopping the run as they stop `sloshsph run`, and a
// progress callback called (under the lock) after every sample.
#include <omp.h>
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "sloshsph/analysis/stats.hpp"
#include "sloshsph/io/case_reader.hpp"
#include "sloshsph/run/run_case.hpp"
#include "sloshsph/run/simulation.hpp"
#include "sloshsph/run/sweep.hpp"

namespace py = pybind11;

namespace sloshsph::python {
namespace {

// The thread count of this run (0: the default), restored afterwards: omp_set_num_threads sets
// the calling thread's value only.
class Threads {
 public:
  explicit Threads(int threads) : before_(omp_get_max_threads()) {
    if (threads > 0) omp_set_num_threads(threads);
  }
  ~Threads() { omp_set_num_threads(before_); }
  Threads(const Threads&) = delete;
  Threads& operator=(const Threads&) = delete;

 private:
  int before_;
};

// The Python progress callback, called after every sample. An exception in it stops the run (as
// a stop request does) and is raised again once the run has written its outputs; a callback that
// returns False stops the run the same way.
struct Callback {
  py::object function;
  py::object error;  // the exception the callback raised, if any
  bool stopped_by_callback = false;

  void attach(RunOptions& options) {
    if (function.is_none()) return;
    options.on_sample = [this](double time, double end_time, std::size_t steps) {
      if (!error.is_none() || stopped_by_callback) return;
      py::gil_scoped_acquire gil;
      // Nothing may escape into the run loop: it would leave the run directory without its summary.
      try {
        const py::object result = function(time, end_time, steps);
        if (result.ptr() == Py_False) {  // False itself: None (a callback that returns nothing) goes on
          stopped_by_callback = true;
          request_stop();
        }
      } catch (py::error_already_set& e) {
        error = e.value();
        request_stop();
      } catch (const std::exception& e) {
        error = py::module_::import("builtins").attr("RuntimeError")(std::string("progress callback: ") + e.what());
        request_stop();
      }
    };
  }
  void raise_if_failed() {
    if (error.is_none()) return;
    PyErr_SetObject(reinterpret_cast<PyObject*>(Py_TYPE(error.ptr())), error.ptr());
    throw py::error_already_set();
  }
};

int run_with(py::object progress, int threads, const std::function<int(const RunOptions&)>& body,
             RunOptions options) {
  Callback callback{std::move(progress), py::none()};
  callback.attach(options);
  int code = 0;
  {
    py::gil_scoped_release release;
    // While the run goes on, SIGINT and SIGTERM stop it after its step with a checkpoint, as they
    // stop `sloshsph run`; Python's own handlers are put back afterwards.
    ScopedStopHandlers signals;
    Threads scope(threads);
    code = body(options);
  }
  callback.raise_if_failed();
  return code;
}

py::list sweep_points_to_python(const std::vector<SweepPoint>& points) {
  py::list out;
  for (const SweepPoint& p : points) {
    py::dict d;
    d["beta"] = p.beta;
    d["label"] = p.label;
    d["overrides"] = p.overrides;
    d["axis_values"] = p.axis_values;
    d["directory"] = p.directory;
    out.append(d);
  }
  return out;
}

SweepPoint sweep_point_from_python(const py::dict& d) {
  SweepPoint p;
  p.beta = d["beta"].cast<double>();
  p.label = d["label"].cast<std::string>();
  p.overrides = d["overrides"].cast<std::vector<std::string>>();
  p.axis_values = d["axis_values"].cast<std::vector<std::string>>();
  p.directory = d["directory"].cast<std::string>();
  return p;
}

std::vector<SweepPoint> sweep_points_from_python(const py::list& list) {
  std::vector<SweepPoint> points;
  for (const py::handle h : list) points.push_back(sweep_point_from_python(py::reinterpret_borrow<py::dict>(h)));
  return points;
}

std::vector<SweepAxis> axes_from_python(const std::vector<std::pair<std::string, std::vector<std::string>>>& axes) {
  std::vector<SweepAxis> out;
  for (const auto& [key, values] : axes) out.push_back({key, values});
  return out;
}

}  // namespace

void bind_runs(py::module_& m) {
  m.def(
      "run_case",
      [](const std::string& text, const std::string& source, const std::string& name,
         const std::vector<std::string>& overrides, const std::string& out_dir, bool force, int threads,
         double checkpoint_every, const std::string& command_line, py::object progress) {
        RunOptions options;
        options.out_dir = out_dir;
        options.force = force;
        options.progress = false;  // the Python side draws its own bar from the callback
        options.command_line = command_line;
        options.checkpoint_every = checkpoint_every;
        return run_with(std::move(progress), threads,
                        [&](const RunOptions& o) {
                          const CaseSpec spec = load_case(text, source, name, overrides);
                          return run_case(spec, o);
                        },
                        options);
      },
      py::arg("text"), py::arg("source"), py::arg("name"), py::arg("overrides"), py::arg("out_dir"),
      py::arg("force"), py::arg("threads"), py::arg("checkpoint_every"), py::arg("command_line"),
      py::arg("progress"), "Runs a case as `sloshsph run`; returns the exit code (0, 3 or 4).");
  m.def(
      "resume_run",
      [](const std::string& dir, int threads, double checkpoint_every, const std::string& command_line,
         py::object progress) {
        RunOptions options;
        options.progress = false;
        options.command_line = command_line;
        options.checkpoint_every = checkpoint_every;
        return run_with(std::move(progress), threads, [&](const RunOptions& o) { return resume_run(dir, o); },
                        options);
      },
      py::arg("dir"), py::arg("threads"), py::arg("checkpoint_every"), py::arg("command_line"), py::arg("progress"),
      "Continues an interrupted run as `sloshsph resume`; returns the exit code.");

  m.def(
      "read_csv_table",
      [](const std::string& path) {
        const CsvTable table = read_csv_table(path);
        py::list columns;
        for (const auto& c : table.columns) columns.append(py::array_t<double>(c.size(), c.data()));
        return py::make_tuple(table.names, columns);
      },
      py::arg("path"), "Reads a CSV table as timeseries.csv is written: (names, list of float64 arrays).");

  m.def(
      "split_sweep_sets",
      [](const std::vector<std::string>& sets) {
        const SweepSets s = split_sweep_sets(sets);
        std::vector<std::pair<std::string, std::vector<std::string>>> axes;
        for (const SweepAxis& a : s.axes) axes.emplace_back(a.key, a.values);
        return py::make_tuple(s.fixed, axes);
      },
      py::arg("sets"), "--set texts of a sweep -> (fixed, [(key, values)]).");
  m.def("parse_beta_range", &parse_beta_range, py::arg("text"), py::arg("where") = "beta");
  m.def(
      "plan_sweep",
      [](const std::string& text, const std::string& source, const std::string& name,
         const std::vector<std::string>& fixed, const std::vector<double>& betas,
         const std::vector<std::pair<std::string, std::vector<std::string>>>& axes, const std::string& dir) {
        const CaseSpec spec = load_case(text, source, name, fixed);
        std::vector<SweepPoint> points = plan_sweep(spec, betas, axes_from_python(axes), dir);
        for (SweepPoint& p : points) {
          // Every point is read before anything runs (as `sloshsph sweep` does): a bad point
          // fails the sweep at once, and a point without --beta gets its case's own ratio.
          std::vector<std::string> sets = fixed;
          sets.insert(sets.end(), p.overrides.begin(), p.overrides.end());
          const CaseSpec point = load_case(text, source, name, sets);
          if (betas.empty()) p.beta = excitation_beta(point);
        }
        return sweep_points_to_python(points);
      },
      py::arg("text"), py::arg("source"), py::arg("name"), py::arg("fixed"), py::arg("betas"), py::arg("axes"),
      py::arg("dir"), "The points of a sweep, as `sloshsph sweep` plans them.");
  m.def("point_status", &point_status, py::arg("directory"));
  m.def(
      "point_finished",
      [](const py::dict& point, bool retry_failed, const std::function<std::string()>& expected_case_toml) {
        return point_finished(sweep_point_from_python(point), retry_failed, expected_case_toml);
      },
      py::arg("point"), py::arg("retry_failed"), py::arg("expected_case_toml"),
      "Whether a point need not run again (as `sloshsph sweep` decides); CaseError for another case's run.");
  m.def(
      "point_resumable", [](const py::dict& point) { return point_resumable(sweep_point_from_python(point)); },
      py::arg("point"), "Whether a point was interrupted with a checkpoint to resume from.");
  m.def(
      "frequency_response_csv",
      [](const std::string& text, const std::string& source, const std::string& name,
         const std::vector<std::string>& fixed,
         const std::vector<std::pair<std::string, std::vector<std::string>>>& axes, const py::list& points) {
        const CaseSpec spec = load_case(text, source, name, fixed);
        return frequency_response_csv(spec, axes_from_python(axes), sweep_points_from_python(points));
      },
      py::arg("text"), py::arg("source"), py::arg("name"), py::arg("fixed"), py::arg("axes"), py::arg("points"),
      "frequency_response.csv of a sweep, from its points' summary.json files.");
}

}  // namespace sloshsph::python
