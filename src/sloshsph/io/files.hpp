#pragma once
// Small file helpers: atomic writes (temporary file + rename) so that no output is
// ever half-written, and the run directory guard.
#include <string>

namespace sloshsph {

// Writes `content` to `path` through `path.tmp` and a rename.
void write_file_atomic(const std::string& path, const std::string& content);

// Reads a whole file; throws InputError(path) when it cannot.
std::string read_file(const std::string& path);

}  // namespace sloshsph
