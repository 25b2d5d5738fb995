// sloshsph._core: the engine for Python. Only plain data crosses: case texts and override lists
// in, exit codes, JSON texts, lists and NumPy arrays out.
#include "bindings.hpp"
#include "sloshsph/core/version.hpp"

PYBIND11_MODULE(_core, m) {
  m.doc() = "sloshsph engine (compiled part of the sloshsph package; use the package, not this module)";
  m.attr("version") = sloshsph::kVersion;
  m.attr("git_revision") = sloshsph::kGitRevision;
  sloshsph::python::bind_errors();
  sloshsph::python::bind_cases(m);
  sloshsph::python::bind_runs(m);
  sloshsph::python::bind_analysis(m);
}
