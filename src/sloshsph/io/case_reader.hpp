#pragma once
// TOML case file -> validated CaseSpec (SI units). Every key is checked: unknown
// keys, wrong types and impossible values throw InputError naming file, line and key.
// The full list of keys, units and defaults is docs/case-format.md.
#include <string>
#include <vector>

#include "sloshsph/core/case_spec.hpp"

namespace sloshsph {

// Reads `path`, applies each "KEY=VALUE" of `overrides` (the --set options) in order.
CaseSpec read_case_file(const std::string& path, const std::vector<std::string>& overrides = {});

// The bytes of the case file at `path`, as read_case_file reads them; InputError(path) when there
// is no such file or it cannot be read.
std::string read_case_file_text(const std::string& path);

// The same from text; `source` names it in messages.
CaseSpec read_case_text(const std::string& text, const std::string& source,
                        const std::vector<std::string>& overrides = {});

// The case's TOML with each override applied in order, nothing resolved or checked beyond the
// overrides themselves (a case written back by the Python module). Throws InputError as
// read_case_text does for a TOML syntax error or a bad override.
std::string case_text_with_overrides(const std::string& text, const std::string& source,
                                     const std::vector<std::string>& overrides);

// The built-in default case run by `sloshsph run` with no CASE.
const std::string& default_case_text();

// The case with every value resolved (defaults filled in), as TOML: the copy kept in a run directory.
std::string resolved_case_toml(const CaseSpec& spec);

}  // namespace sloshsph
