#pragma once
// One validation check = one row of the table in docs/validation.md: a measured number, the
// reference it is compared with (and where that reference comes from), the tolerance, and the
// verdict. Each check is asserted with gtest (a failed check fails the test, with the numbers in
// the message) and, when $SLOSHSPH_VALIDATION_RECORD names a folder, appended as one JSON line to
// <folder>/<Suite.Test>.jsonl, which `sloshsph validate` (tools/validate/validate.py) turns into
// the table. Curves (measured beside reference over time or frequency) go to
// <folder>/<Suite.Test>.<name>.curve.json and become the comparison plots.
//
// The tolerance kinds:
//   check_relative(q, measured, reference, tol)  |measured / reference - 1| <= tol
//   check_absolute(q, measured, reference, tol)  |measured - reference| <= tol
//   check_at_most(q, measured, bound)            measured <= bound
//   check_at_least(q, measured, bound)           measured >= bound
//   check_between(q, measured, low, high)        low <= measured <= high
// A Check with `asserted = false` is recorded with its verdict but does not fail the test: for a
// number the issue sets a bar for that we knowingly miss and explain (the table says so).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace sloshsph::testing {

enum class Tolerance { relative, absolute, at_most, at_least, between };

struct Check {
  std::string quantity;    // what is measured, e.g. "mid-span deflection"
  std::string unit;        // of measured and reference ("" for ratios and counts)
  double measured = NAN;
  Tolerance kind = Tolerance::relative;
  double reference = NAN;  // the reference value (relative/absolute), or the bound
  double tolerance = NAN;  // relative/absolute: the allowed deviation; between: the upper bound
  std::string source;      // where the reference comes from: theory, a table, an experiment
  bool asserted = true;    // false: recorded only, explained in the notes
};

namespace detail {

inline bool passes(const Check& c) {
  if (!std::isfinite(c.measured)) return false;
  switch (c.kind) {
    case Tolerance::relative: return std::abs(c.measured / c.reference - 1.0) <= c.tolerance;
    case Tolerance::absolute: return std::abs(c.measured - c.reference) <= c.tolerance;
    case Tolerance::at_most: return c.measured <= c.reference;
    case Tolerance::at_least: return c.measured >= c.reference;
    case Tolerance::between: return c.measured >= c.reference && c.measured <= c.tolerance;
  }
  return false;
}

inline const char* kind_name(Tolerance k) {
  switch (k) {
    case Tolerance::relative: return "relative";
    case Tolerance::absolute: return "absolute";
    case Tolerance::at_most: return "at_most";
    case Tolerance::at_least: return "at_least";
    case Tolerance::between: return "between";
  }
  return "?";
}

inline std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char ch : s) {
    if (ch == '"' || ch == '\\') out += '\\';
    if (ch == '\n') {
      out += "\\n";
      continue;
    }
    out += ch;
  }
  return out + "\"";
}

inline std::string json_number(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

inline std::string current_test_name() {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return info ? std::string(info->test_suite_name()) + "." + info->name() : "unknown";
}

// The record file of the running test; truncated at its first use in this process, so that a
// re-run replaces the old rows instead of adding to them.
inline std::string record_path(const std::string& suffix) {
  const char* dir = std::getenv("SLOSHSPH_VALIDATION_RECORD");
  if (!dir || !*dir) return "";
  return std::string(dir) + "/" + current_test_name() + suffix;
}

inline std::ofstream open_for_test(const std::string& path) {
  static std::set<std::string> opened;
  const bool first = opened.insert(path).second;
  return std::ofstream(path, first ? std::ios::trunc : std::ios::app);
}

inline std::string describe(const Check& c) {
  std::ostringstream s;
  s << c.quantity << " = " << c.measured << (c.unit.empty() ? "" : " " + c.unit);
  switch (c.kind) {
    case Tolerance::relative: s << ", reference " << c.reference << " +/- " << 100.0 * c.tolerance << "%"; break;
    case Tolerance::absolute: s << ", reference " << c.reference << " +/- " << c.tolerance; break;
    case Tolerance::at_most: s << ", bound <= " << c.reference; break;
    case Tolerance::at_least: s << ", bound >= " << c.reference; break;
    case Tolerance::between: s << ", bounds [" << c.reference << ", " << c.tolerance << "]"; break;
  }
  s << " (" << c.source << ")";
  return s.str();
}

}  // namespace detail

// Evaluates, asserts (unless c.asserted is false), prints and records one check; returns the verdict.
inline bool check(const Check& c) {
  const bool pass = detail::passes(c);
  std::printf("  check %s: %s%s\n", pass ? "pass" : "FAIL", detail::describe(c).c_str(),
              c.asserted ? "" : " [recorded, not asserted]");
  if (c.asserted) {
    EXPECT_TRUE(pass) << detail::describe(c);
  }
  if (const std::string path = detail::record_path(".jsonl"); !path.empty()) {
    std::ofstream out = detail::open_for_test(path);
    out << "{\"test\": " << detail::json_string(detail::current_test_name())
        << ", \"quantity\": " << detail::json_string(c.quantity) << ", \"unit\": " << detail::json_string(c.unit)
        << ", \"measured\": " << detail::json_number(c.measured) << ", \"kind\": \"" << detail::kind_name(c.kind)
        << "\", \"reference\": " << detail::json_number(c.reference)
        << ", \"tolerance\": " << detail::json_number(c.tolerance)
        << ", \"source\": " << detail::json_string(c.source) << ", \"asserted\": " << (c.asserted ? "true" : "false")
        << ", \"pass\": " << (pass ? "true" : "false") << "}\n";
  }
  return pass;
}

inline bool check_relative(const std::string& quantity, double measured, double reference, double tolerance,
                           const std::string& source, const std::string& unit = "") {
  return check({quantity, unit, measured, Tolerance::relative, reference, tolerance, source});
}
inline bool check_absolute(const std::string& quantity, double measured, double reference, double tolerance,
                           const std::string& source, const std::string& unit = "") {
  return check({quantity, unit, measured, Tolerance::absolute, reference, tolerance, source});
}
inline bool check_at_most(const std::string& quantity, double measured, double bound, const std::string& source,
                          const std::string& unit = "") {
  return check({quantity, unit, measured, Tolerance::at_most, bound, NAN, source});
}
inline bool check_at_least(const std::string& quantity, double measured, double bound, const std::string& source,
                           const std::string& unit = "") {
  return check({quantity, unit, measured, Tolerance::at_least, bound, NAN, source});
}
inline bool check_between(const std::string& quantity, double measured, double low, double high,
                          const std::string& source, const std::string& unit = "") {
  return check({quantity, unit, measured, Tolerance::between, low, high, source});
}

// A curve for the comparison plots: the measured series and, when there is one, the reference
// series (theory or experiment), on their own abscissae.
struct Curve {
  std::string name;     // file-name part, [a-z0-9_]
  std::string title;
  std::string x_label, y_label;
  std::vector<double> x, measured;
  std::string reference_label;  // e.g. "Koshizuka & Oka (1996), experiment"; empty: none
  std::vector<double> reference_x, reference_y;
  bool reference_as_points = true;  // experiments as markers, theory as a line
  bool log_y = false;               // a logarithmic ordinate (spectra, admittances)
};

inline void record_curve(const Curve& c) {
  const std::string path = detail::record_path("." + c.name + ".curve.json");
  if (path.empty()) return;
  auto array = [](const std::vector<double>& v) {
    std::string s = "[";
    for (std::size_t k = 0; k < v.size(); ++k) s += (k ? ", " : "") + detail::json_number(v[k]);
    return s + "]";
  };
  std::ofstream out(path, std::ios::trunc);
  out << "{\"test\": " << detail::json_string(detail::current_test_name()) << ", \"name\": " << detail::json_string(c.name)
      << ", \"title\": " << detail::json_string(c.title) << ", \"x_label\": " << detail::json_string(c.x_label)
      << ", \"y_label\": " << detail::json_string(c.y_label) << ", \"x\": " << array(c.x)
      << ", \"measured\": " << array(c.measured) << ", \"reference_label\": " << detail::json_string(c.reference_label)
      << ", \"reference_x\": " << array(c.reference_x) << ", \"reference_y\": " << array(c.reference_y)
      << ", \"reference_as_points\": " << (c.reference_as_points ? "true" : "false")
      << ", \"log_y\": " << (c.log_y ? "true" : "false") << "}\n";
}

// A pressure probe's final value beside its hydrostatic one; record_profile_curve sorts them by
// height into the comparison curve "pressure_profile".
struct ProfilePoint {
  double y = 0.0;          // m
  double measured = 0.0;   // Pa
  double reference = 0.0;  // Pa
};

inline void record_profile_curve(const std::string& title, std::vector<ProfilePoint> points,
                                 const std::string& reference_label) {
  std::sort(points.begin(), points.end(), [](const ProfilePoint& a, const ProfilePoint& b) { return a.y < b.y; });
  Curve c{"pressure_profile", title, "height y (m)", "pressure (Pa)", {}, {}, reference_label, {}, {}, false};
  for (const ProfilePoint& p : points) {
    c.x.push_back(p.y);
    c.measured.push_back(p.measured);
    c.reference_x.push_back(p.y);
    c.reference_y.push_back(p.reference);
  }
  record_curve(c);
}

}  // namespace sloshsph::testing
