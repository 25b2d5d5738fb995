#pragma once
// One input for the case reader or the record readers, checked the way the command line uses
// them: it must be read, or rejected with InputError (exit code 2). Anything else (another
// exception, a crash, a hang, a result that breaks the reader's own contract) is a failure.
// Shared by the seeded mutation test (case_mutation_test.cpp, ctest label `unit`) and the
// libFuzzer targets (fuzz_case_reader.cpp, fuzz_record_readers.cpp; clang only).
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/io/case_reader.hpp"
#include "sloshsph/signals/record_readers.hpp"

namespace sloshsph::fuzz {

enum class Outcome { accepted, rejected };

// Reads a case text with --set overrides. Returns accepted/rejected; throws std::logic_error
// naming the broken contract, and lets any other exception through (a failure).
inline Outcome check_case_text(const std::string& text, const std::string& source,
                               const std::vector<std::string>& overrides = {}) {
  CaseSpec spec;
  try {
    spec = read_case_text(text, source, overrides);
  } catch (const InputError& e) {
    if (std::string(e.what()).empty()) throw std::logic_error("InputError with an empty message");
    return Outcome::rejected;
  }
  // An accepted case is written into its run directory as case.toml (resolved_case_toml);
  // that copy must be accepted again, or the run directory could not be re-run.
  const std::string resolved = resolved_case_toml(spec);
  try {
    read_case_text(resolved, source);
  } catch (const InputError& e) {
    throw std::logic_error(std::string("the resolved case.toml of an accepted case is rejected: ") + e.what() +
                           "\n--- resolved case ---\n" + resolved);
  }
  return Outcome::accepted;
}

// The contract of a record that was read: at least 2 samples, finite strictly increasing
// times, finite values (record_readers.hpp).
inline void check_series(const TimeSeries& s, const char* reader) {
  auto fail = [&](const std::string& what) { throw std::logic_error(std::string(reader) + " returned " + what); };
  if (s.t.size() != s.value.size()) fail("times and values of different lengths");
  if (s.t.size() < 2) fail("fewer than 2 samples");
  for (std::size_t i = 0; i < s.t.size(); ++i) {
    if (!std::isfinite(s.t[i])) fail("a non-finite time at sample " + std::to_string(i));
    if (!std::isfinite(s.value[i])) fail("a non-finite value at sample " + std::to_string(i));
    if (i > 0 && !(s.t[i] > s.t[i - 1])) fail("times not strictly increasing at sample " + std::to_string(i));
  }
}

// Writes `bytes` to `path` and reads it with both record readers (whatever its extension).
// Returns how many of the two accepted it.
inline int check_record_bytes(const std::string& bytes, const std::string& path) {
  {
    // A new file each time: rewriting a truncated file makes ext4 flush it on close
    // (auto_da_alloc), which costs milliseconds per input.
    std::remove(path.c_str());
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  }
  int accepted = 0;
  try {
    const GroundRecord r = read_peer_at2(path, "excitation.file", 1.0);
    check_series(r.acceleration, "read_peer_at2");
    if (!(r.dt > 0.0) || !std::isfinite(r.dt)) throw std::logic_error("read_peer_at2 returned a bad dt");
    ++accepted;
  } catch (const InputError&) {
  }
  try {
    CsvRecordOptions o;
    o.value_factor = kStandardGravity;
    check_series(read_two_column_csv(path, "excitation.file", o), "read_two_column_csv");
    ++accepted;
  } catch (const InputError&) {
  }
  return accepted;
}

}  // namespace sloshsph::fuzz
