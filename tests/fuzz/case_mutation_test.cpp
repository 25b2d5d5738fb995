// Seeded mutation test of the case reader and the record readers (issue 9, "hostile input").
//
// Seeds: the repository's cases/*.toml, the built-in default case and the bad-case corpus
// (tests/cli/bad_cases/*.toml); for the record readers data/records/*, the corpus's
// records and a few synthetic AT2/CSV files. Each execution takes one seed and applies 1 to
// 4 seeded random mutations: byte flips, deletions, duplications, truncation, line swaps,
// inserted TOML (or record) fragments, numbers swapped for huge/negative/nan/inf/strings,
// enum strings swapped for other enum values; case inputs also get random --set overrides.
// Every input must be read or rejected with InputError (fuzz_inputs.hpp); any other
// exception, a crash or a hang (10 s per input) fails the test.
//
// Deterministic: execution i uses its own generator seeded by (--seed, i), so a failure is
// reproduced with --only i (which also writes the input to --work). Stops at --cases and
// --records executions or after --seconds, whichever comes first, and prints the counts.
//
// usage: case_mutation_test [--cases N] [--records N] [--seconds S] [--seed S] [--only I]
//                           [--work DIR] [--verbose]
#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <typeinfo>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

#include "fuzz_inputs.hpp"

namespace fs = std::filesystem;
using namespace sloshsph;

namespace {

struct Seed {
  std::string source;  // a path: relative record paths in a case resolve from its folder
  std::string text;
};

std::string read_all(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<Seed> files_in(const fs::path& dir, const std::vector<std::string>& extensions) {
  std::vector<Seed> out;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return out;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string ext = e.path().extension().string();
    if (e.is_regular_file() && std::find(extensions.begin(), extensions.end(), ext) != extensions.end())
      out.push_back({e.path().string(), read_all(e.path())});
  }
  std::sort(out.begin(), out.end(), [](const Seed& a, const Seed& b) { return a.source < b.source; });
  return out;
}

// ---- mutations -------------------------------------------------------------------------

using Rng = std::mt19937_64;

std::size_t pick(Rng& rng, std::size_t n) { return n == 0 ? 0 : std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); }

template <class T>
const T& pick(Rng& rng, const std::vector<T>& v) { return v[pick(rng, v.size())]; }

const std::vector<std::string> kHostileNumbers = {
    "1e308", "-1e308", "1.7976931348623157e308", "4.9e-324", "1e-300", "-0.0", "0", "-1", "-0.005", "nan", "+nan",
    "-nan", "inf", "-inf", "+inf", "9223372036854775807", "-9223372036854775808", "99999999999999999999",
    "0x7fffffffffffffff", "0b1", "0o7", "1_000", "1e", ".5", "5.", "\"abc\"", "\"0.5\"", "''", "true", "false",
    "[]", "[1, 2]", "[[1, 2], [3]]", "{}", "{ a = 1 }", "1979-05-27T07:32:00Z", "07:32:00", "1e400", "-1e-400",
    "1D+03", "1.0E+99999", "2", "1000000", "0.999", "89.9", "1e-9"};

const std::vector<std::string> kEnumWords = {
    "rectangle", "sloped", "triangle", "trapezoid", "parabolic", "circular", "polyline", "isph", "wcsph", "none",
    "harmonic", "pitch", "record", "pulse", "noise", "explicit", "implicit", "thesis", "air", "ergun", "morison",
    "modal", "sine", "cosine", "csv", "at2", "m/s2", "g", "clip", "keep", "sps", "smagorinsky", "adami",
    "repulsive", "symplectic", "leapfrog", "wendland", "cubic_spline", "excitation", "", "\\u0000", "\xff"};

const std::vector<std::string> kTomlFragments = {
    "[tank]\n", "[fill]\n", "[time]\n", "[particles]\n", "[scheme]\n", "[output]\n", "[run]\n", "[fluid]\n",
    "[[screens]]\nname = \"s9\"\nx = 0.2\nsolidity = 0.5\n",
    "[[screens]]\nname = \"s8\"\nfrom = [0.1, 0.0]\nto = [0.3, 0.2]\nmodel = \"explicit\"\nslat_height = 0.005\nslat_gap = 0.007\n",
    "[[probes.gauge]]\nname = \"g9\"\nx = 0.1\n", "[[probes.pressure]]\nname = \"p9\"\nx = 0.1\ny = 0.05\n",
    "[[probes.pressure]]\nname = \"p8\"\nx = 0.1\ny = 0.05\nto = [0.1, 0.15]\n",
    "[[probes.pressure]]\nname = \"p7\"\nx = 0.0\ny = 0.05\nsize = 0.009\n",
    "[structure]\nmass = 100.0\nfrequency = 0.8\ndamping_ratio = 0.02\n",
    "[structure]\nmass = 1e-300\nstiffness = 1e300\ndamping = 0\nground = \"excitation\"\n",
    "[structure.load]\ntype = \"noise\"\ntarget_peak_mg = 10\n",
    "[structure.load]\ntype = \"record\"\nfile = \"records/one_column.csv\"\n",
    "[excitation]\ntype = \"pitch\"\nangle = 5.0\npivot = [0.25, 0.2]\nbeta = 1.0\n",
    "[excitation]\ntype = \"noise\"\nrms = 0.1\nband = [0.1, 2.0]\n",
    "[excitation]\ntype = \"pulse\"\nacceleration = 1.0\nperiod = 0.5\n",
    "[excitation]\ntype = \"record\"\nfile = \"../data/records/elcentro_1940_ns.at2\"\n",
    "[excitation]\ntype = \"record\"\nfile = \"/dev/null\"\n",
    "shape = \"polyline\"\npoints = [[0.0, 0.4], [0.25, 0.0], [0.5, 0.4]]\n",
    "points = [[0.0, 0.4], [0.5, 0.0], [0.0, 0.0], [0.5, 0.4]]\n", "points = []\n", "points = [[nan, 1], [1, inf]]\n",
    "shape = \"parabolic\"\ncoefficient = 1e300\n", "shape = \"circular\"\n", "angle = 1.0\nbottom_width = 0.0\n",
    "dp = 1e-300\n", "dp = 0.5\n", "end = 1e300\n", "dt = 1e-300\n", "settle = 1e300\n", "depth = 1e-300\n",
    "sample_interval = 1e-300\n", "snapshot_interval = 4.9e-324\n", "type = \"wcsph\"\n", "type = \"record\"\n",
    "beta = 1.0\nfrequency = 1.0\n", "omega = 1e308\n", "amplitude = 1e308\n", "x = nan\n", "name = \"\"\n",
    "a.b.c = 1\n", "[[fill]]\n", "[tank.sub]\nk = 1\n", "k = { a = 1, b = [1, 2] }\n", "\"quoted key\" = 1\n",
    "s = '''\n", "s = \"\"\"\n", "# comment\n", "\n\n\n", "[\n", "]]\n", "=\n", "\"\n", "title = \"\\uD800\"\n",
    "title = \"\\U0010FFFF\"\n", "t = 1979-05-27\n", "\t \r\n", std::string("\0", 1), "\xef\xbb\xbf"};

const std::vector<std::string> kRecordFragments = {
    "NPTS= 5, DT= .01 SEC\n", "NPTS= 999999999, DT= .01 SEC\n", "NPTS= 0, DT= 1\n", "NPTS= -3, DT= .01\n",
    "NPTS= 2, DT= 1e308\n", "NPTS= 2, DT= 4.9e-324\n", "NPTS= 1.5, DT= .02\n", "NPTS=, DT=\n", "  3    0.0200    NPTS, DT\n",
    "1.0D+308 1.0D+308\n", "-0.12345-0.23456+1.5\n", "1e999\n", "nan, 1\n", "inf\n", "+-1\n", ".\n", "-\n", "1,2,3\n",
    "1 2\n", "0.0, 0.0\n", "1e308, 1e308\n", "time, value\n", "# only a comment\n", "\r\n", ",,,,\n", "1.0,\n",
    std::string("\0\0", 2), "1.0 2.0 3.0 4.0 5.0 6.0 7.0 8.0\n"};

// Positions of numbers (a digit run with sign, point and exponent) in `s`.
std::vector<std::pair<std::size_t, std::size_t>> number_spans(const std::string& s) {
  std::vector<std::pair<std::size_t, std::size_t>> spans;
  std::size_t i = 0;
  while (i < s.size()) {
    if (std::isdigit(static_cast<unsigned char>(s[i]))) {
      std::size_t b = i;
      if (b > 0 && (s[b - 1] == '-' || s[b - 1] == '+' || s[b - 1] == '.')) --b;
      std::size_t e = i;
      while (e < s.size() && (std::isdigit(static_cast<unsigned char>(s[e])) || s[e] == '.' || s[e] == 'e' ||
                              s[e] == 'E' || s[e] == '_' ||
                              ((s[e] == '-' || s[e] == '+') && (s[e - 1] == 'e' || s[e - 1] == 'E'))))
        ++e;
      spans.push_back({b, e - b});
      i = e;
    } else {
      ++i;
    }
  }
  return spans;
}

// Positions of the contents of "..." strings in `s`.
std::vector<std::pair<std::size_t, std::size_t>> string_spans(const std::string& s) {
  std::vector<std::pair<std::size_t, std::size_t>> spans;
  std::size_t i = 0;
  while ((i = s.find('"', i)) != std::string::npos) {
    const std::size_t e = s.find('"', i + 1);
    if (e == std::string::npos || s.find('\n', i) < e) {
      ++i;
      continue;
    }
    spans.push_back({i + 1, e - i - 1});
    i = e + 1;
  }
  return spans;
}

std::size_t line_start(const std::string& s, std::size_t pos) {
  const std::size_t p = pos == 0 ? std::string::npos : s.rfind('\n', pos - 1);
  return p == std::string::npos ? 0 : p + 1;
}

void mutate_once(std::string& s, Rng& rng, const std::vector<std::string>& fragments, bool toml) {
  const std::size_t n = s.size();
  switch (pick(rng, 9)) {
    case 0:  // flip a bit or set a random byte
      if (n) {
        const std::size_t i = pick(rng, n);
        if (pick(rng, 2)) s[i] = static_cast<char>(s[i] ^ (1 << pick(rng, 8)));
        else s[i] = static_cast<char>(pick(rng, 256));
      }
      break;
    case 1:  // delete a span
      if (n) {
        const std::size_t i = pick(rng, n);
        s.erase(i, 1 + pick(rng, std::min<std::size_t>(64, n - i)));
      }
      break;
    case 2:  // duplicate a span somewhere else (duplicate keys and tables)
      if (n) {
        const std::size_t i = pick(rng, n);
        const std::string span = s.substr(i, 1 + pick(rng, 200));
        s.insert(pick(rng, n + 1), span);
      }
      break;
    case 3:  // truncate
      s.resize(pick(rng, n + 1));
      break;
    case 4:  // insert a fragment at the start of a line
      s.insert(line_start(s, pick(rng, n + 1)), pick(rng, fragments));
      break;
    case 5:
    case 6: {  // swap a number for a hostile value
      const auto spans = number_spans(s);
      if (!spans.empty()) {
        const auto [b, len] = pick(rng, spans);
        s.replace(b, len, toml ? pick(rng, kHostileNumbers) : pick(rng, kHostileNumbers).substr(0, 12));
      }
      break;
    }
    case 7: {  // swap a string for another enum word (reaches the other shapes, schemes, types)
      const auto spans = string_spans(s);
      if (!spans.empty()) {
        const auto [b, len] = pick(rng, spans);
        s.replace(b, len, pick(rng, kEnumWords));
      }
      break;
    }
    case 8: {  // swap two lines
      std::vector<std::size_t> starts{0};
      for (std::size_t i = 0; i < n; ++i)
        if (s[i] == '\n' && i + 1 < n) starts.push_back(i + 1);
      if (starts.size() > 1) {
        auto line = [&](std::size_t k) {
          const std::size_t b = starts[k], e = k + 1 < starts.size() ? starts[k + 1] : n;
          return std::make_pair(b, e - b);
        };
        std::size_t a = pick(rng, starts.size()), c = pick(rng, starts.size());
        if (a > c) std::swap(a, c);
        if (a != c) {
          const auto la = line(a), lc = line(c);
          const std::string sa = s.substr(la.first, la.second), sc = s.substr(lc.first, lc.second);
          s.replace(lc.first, lc.second, sa);
          s.replace(la.first, la.second, sc);
        }
      }
      break;
    }
  }
}

const std::vector<std::string> kOverrideKeys = {
    "tank.shape", "tank.length", "tank.height", "tank.points", "tank.coefficient", "fill.depth", "particles.dp",
    "particles.wall_layers", "time.end", "time.dt", "time.settle", "time.dt_min", "excitation.type", "excitation.beta",
    "excitation.frequency", "excitation.amplitude", "scheme.type", "screens", "screens.0.x", "screens.0",
    "probes.gauge.0.x", "probes.gauge.99999999999999999999.x", "probes.gauge.0", "probes.pressure.1.y",
    "probes.pressure.0.size",
    "probes.gauge", "structure.mass", "structure.load.type", "output.sample_interval", "a..b", ".x", "x.",
    "tank.length.x", "fill.depth.0", "0", "0.0", "title"};

std::vector<std::string> random_overrides(Rng& rng) {
  std::vector<std::string> sets;
  const std::size_t count = pick(rng, 5) == 0 ? 1 + pick(rng, 2) : 0;
  for (std::size_t k = 0; k < count; ++k) {
    std::string value = pick(rng, 3) == 0 ? pick(rng, kEnumWords) : pick(rng, kHostileNumbers);
    if (pick(rng, 10) == 0) value = "[{name=\"s\", x=0.2, solidity=0.5}, {name=\"s\", x=1e308}]";
    sets.push_back(pick(rng, 20) == 0 ? value : pick(rng, kOverrideKeys) + "=" + value);
  }
  return sets;
}

// ---- crash and hang reporting ---------------------------------------------------------

// The input under test, for the fatal-signal handler (which may only call async-signal-safe
// functions: open, write, _exit).
const char* g_input = nullptr;
std::size_t g_input_size = 0;
char g_dump_path[4096] = {0};
const char* g_what = "";

void write_str(int fd, const char* s) { (void)!write(fd, s, std::strlen(s)); }

void on_fatal(int sig) {
  const int fd = open(g_dump_path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd >= 0) {
    (void)!write(fd, g_input, g_input_size);
    close(fd);
  }
  write_str(2, sig == SIGALRM ? "\nFAIL: hang (more than 10 s on one input) in " : "\nFAIL: fatal signal in ");
  write_str(2, g_what);
  write_str(2, "; the input is in ");
  write_str(2, g_dump_path);
  write_str(2, "\n");
  if (sig == SIGALRM) _exit(1);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

// Under AddressSanitizer a crash is reported by ASan (and its handler must stay installed);
// only the hang alarm is ours there.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kUnderAsan = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kUnderAsan = true;
#else
constexpr bool kUnderAsan = false;
#endif
#else
constexpr bool kUnderAsan = false;
#endif

void install_handlers() {
  std::signal(SIGALRM, on_fatal);
  if (!kUnderAsan)
    for (int sig : {SIGSEGV, SIGABRT, SIGFPE, SIGBUS, SIGILL}) std::signal(sig, on_fatal);
}

struct Options {
  long cases = 20000, records = 5000;
  double seconds = 20.0;
  std::uint64_t seed = 20240901;
  long only = -1;
  std::string work;
  bool verbose = false;
};

Options parse_options(int argc, char** argv) {
  Options o;
  o.work = (fs::temp_directory_path() / "sloshsph_case_mutation").string();
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    auto next = [&]() -> std::string {
      if (k + 1 >= argc) {
        std::fprintf(stderr, "missing value after %s\n", a.c_str());
        std::exit(2);
      }
      return argv[++k];
    };
    if (a == "--cases") o.cases = std::stol(next());
    else if (a == "--records") o.records = std::stol(next());
    else if (a == "--seconds") o.seconds = std::stod(next());
    else if (a == "--seed") o.seed = std::stoull(next());
    else if (a == "--only") o.only = std::stol(next());
    else if (a == "--work") o.work = next();
    else if (a == "--verbose") o.verbose = true;
    else {
      std::fprintf(stderr, "unknown option %s\n", a.c_str());
      std::exit(2);
    }
  }
  return o;
}

Rng rng_for(const Options& o, std::uint64_t stream, long i) {
  std::seed_seq seq{o.seed, stream, static_cast<std::uint64_t>(i)};
  return Rng(seq);
}

std::string mutant(const std::vector<Seed>& seeds, Rng& rng, const std::vector<std::string>& fragments, bool toml,
                   std::size_t& seed_index) {
  seed_index = pick(rng, seeds.size());
  std::string s = seeds[seed_index].text;
  const std::size_t count = 1 + pick(rng, 4);
  for (std::size_t k = 0; k < count; ++k) mutate_once(s, rng, fragments, toml);
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse_options(argc, argv);
  const fs::path src(SLOSHSPH_SOURCE_DIR);
  fs::create_directories(o.work);
  std::snprintf(g_dump_path, sizeof g_dump_path, "%s", (fs::path(o.work) / "failing_input").c_str());
  install_handlers();

  std::vector<Seed> cases = files_in(src / "cases", {".toml"});
  const std::size_t repository_cases = cases.size();
  cases.push_back({(src / "cases" / "default.toml").string(), default_case_text()});
  for (Seed& s : files_in(src / "tests" / "cli" / "bad_cases", {".toml"})) cases.push_back(std::move(s));
  std::vector<Seed> records = files_in(src / "data" / "records", {".at2", ".csv", ".txt"});
  for (Seed& s : files_in(src / "tests" / "cli" / "bad_cases" / "records", {".at2", ".csv"})) records.push_back(std::move(s));
  records.push_back({"nga.at2", "PEER NGA STRONG MOTION DATABASE RECORD\nX\nACCELERATION TIME SERIES IN UNITS OF G\n"
                                "NPTS=   6, DT=   .0050 SEC,\n  .1E-02 -.2E-02  .3D-02\n-0.12345-0.23456  1.0\n"});
  records.push_back({"old.at2", "a\nb\nc\n  4    0.0200    NPTS, DT\n 1 2\n 3 4\n"});
  records.push_back({"ok.csv", "# time in s, acceleration in g\ntime, acc\n0.0, 0.0\n0.01, 0.1 # peak\n\n0.02,-0.1\n"});
  if (cases.empty() || records.empty()) {
    std::fprintf(stderr, "FAIL: no seeds found under %s\n", src.c_str());
    return 1;
  }

  // The repository's own cases must be read as they are.
  int failures = 0;
  for (std::size_t k = 0; k < repository_cases; ++k) {
    try {
      read_case_text(cases[k].text, cases[k].source);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "FAIL: the repository case %s is not read: %s\n", cases[k].source.c_str(), e.what());
      ++failures;
    }
  }

  const auto start = std::chrono::steady_clock::now();
  auto out_of_time = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > o.seconds;
  };
  long case_execs = 0, case_accepted = 0, record_execs = 0, record_accepts = 0;
  const std::string record_path = (fs::path(o.work) / "record_under_test").string();

  // Case and record executions interleaved, so that a time budget cuts both alike.
  for (long i = 0; (i < o.cases || i < o.records) && !out_of_time(); ++i) {
    if (o.only >= 0 && i != o.only) continue;
    if (i < o.cases) {
      Rng rng = rng_for(o, 1, i);
      std::size_t seed_index = 0;
      const std::string text = mutant(cases, rng, kTomlFragments, true, seed_index);
      const std::vector<std::string> sets = random_overrides(rng);
      g_input = text.data();
      g_input_size = text.size();
      g_what = "the case reader";
      if (o.only >= 0) {
        std::ofstream(g_dump_path, std::ios::binary) << text;
        std::fprintf(stderr, "case input %ld (seed %s) written to %s\n", i, cases[seed_index].source.c_str(), g_dump_path);
        for (const auto& s : sets) std::fprintf(stderr, "  --set %s\n", s.c_str());
      }
      alarm(10);
      try {
        if (fuzz::check_case_text(text, cases[seed_index].source, sets) == fuzz::Outcome::accepted) ++case_accepted;
      } catch (const std::exception& e) {
        ++failures;
        std::fprintf(stderr, "FAIL: case execution %ld (seed %s): %s: %s\n  reproduce: --seed %llu --only %ld\n", i,
                     cases[seed_index].source.c_str(), typeid(e).name(), e.what(),
                     static_cast<unsigned long long>(o.seed), i);
      }
      alarm(0);
      ++case_execs;
    }
    if (i < o.records) {
      Rng rng = rng_for(o, 2, i);
      std::size_t seed_index = 0;
      const std::string bytes = mutant(records, rng, kRecordFragments, false, seed_index);
      g_input = bytes.data();
      g_input_size = bytes.size();
      g_what = "the record readers";
      if (o.only >= 0) std::ofstream(g_dump_path + std::string(".record"), std::ios::binary) << bytes;
      alarm(10);
      try {
        record_accepts += fuzz::check_record_bytes(bytes, record_path);
      } catch (const std::exception& e) {
        ++failures;
        std::fprintf(stderr, "FAIL: record execution %ld (seed %s): %s: %s\n  reproduce: --seed %llu --only %ld\n", i,
                     records[seed_index].source.c_str(), typeid(e).name(), e.what(),
                     static_cast<unsigned long long>(o.seed), i);
      }
      alarm(0);
      ++record_execs;
    }
    if (o.verbose && i % 1000 == 0) std::fprintf(stderr, "execution %ld\n", i);
  }

  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("case reader: %ld executions (%ld accepted, %ld rejected with InputError) from %zu seeds\n", case_execs,
              case_accepted, case_execs - case_accepted, cases.size());
  std::printf("record readers: %ld mutated files, each read by both readers (%ld reads accepted) from %zu seeds\n",
              record_execs, record_accepts, records.size());
  std::printf("%.1f s%s; %d failure(s)\n", wall, out_of_time() ? " (time budget reached)" : "", failures);
  return failures == 0 ? 0 : 1;
}
