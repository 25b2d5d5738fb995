#pragma once
// The pieces of the compiled module sloshsph._core (python/sloshsph/ wraps them in the public API,
// docs/python.md). Each bind_* registers one group of functions.
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "sloshsph/core/case_spec.hpp"

namespace sloshsph::python {

// As the command line's load_case: the text read with the overrides applied in order, renamed
// (unless `name` is empty: the source's stem), resolved. Throws InputError.
CaseSpec load_case(const std::string& text, const std::string& source, const std::string& name,
                   const std::vector<std::string>& overrides);

void bind_errors();  // InputError -> sloshsph.CaseError, RunFailure -> RunFailed, Interrupted -> Interrupted
void bind_cases(pybind11::module_& m);     // reading, checking and writing cases; modes, tune
void bind_runs(pybind11::module_& m);      // run, resume, sweep plans, the CSV tables
void bind_analysis(pybind11::module_& m);  // filter, steady state, energy, spectra, admittance

}  // namespace sloshsph::python
