// PEER AT2 and two-column CSV readers (src/sloshsph/signals/record_readers.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/signals/record_readers.hpp"

namespace sloshsph {
namespace {

const std::string kElCentro = std::string(SLOSHSPH_SOURCE_DIR) + "/data/records/elcentro_1940_ns.at2";

// A scratch file in the test temp dir; the name carries the test name so tests do not collide.
std::string write_temp(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::path(testing::TempDir()) / "sloshsph_signals_test";
  std::filesystem::create_directories(dir);
  const auto path = dir / name;
  std::ofstream(path) << text;
  return path.string();
}

// Runs f, expects an InputError, returns it (so the test can check where/key/message).
template <class F>
InputError expect_input_error(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError thrown";
  return InputError("", "", "");
}

TEST(PeerAt2, ReadsElCentro) {
  const GroundRecord rec = read_peer_at2(kElCentro, "excitation.file");
  // Reference: the record's own header (NPTS = 1559, DT = .02000 SEC) and data/records/README.md.
  EXPECT_EQ(rec.acceleration.size(), 1559u);
  EXPECT_DOUBLE_EQ(rec.dt, 0.02);
  EXPECT_DOUBLE_EQ(rec.acceleration.t.front(), 0.0);
  EXPECT_NEAR(rec.acceleration.t.back(), 1558 * 0.02, 1e-12);
  ASSERT_EQ(rec.header.size(), 3u);
  EXPECT_NE(rec.header[0].find("El Centro"), std::string::npos);
  // First and last values of the file, in g, converted with g = 9.80665 m/s^2.
  EXPECT_NEAR(rec.acceleration.value.front(), 0.00630 * kStandardGravity, 1e-15);
  EXPECT_NEAR(rec.acceleration.value.back(), 0.0, 1e-15);
  // Peak |a|: the record's published peak is 0.319 g (README); tolerance 0.5%. The exact value in
  // the file is 0.31882 g, at sample 102 (t = 2.02 s).
  const auto it = std::max_element(rec.acceleration.value.begin(), rec.acceleration.value.end(),
                                   [](double a, double b) { return std::abs(a) < std::abs(b); });
  const double peak_g = std::abs(*it) / kStandardGravity;
  EXPECT_NEAR(peak_g, 0.319, 0.005 * 0.319);
  EXPECT_NEAR(peak_g, 0.31882, 1e-12);
  EXPECT_EQ(it - rec.acceleration.value.begin(), 101);
}

TEST(PeerAt2, ScaleFactorMultipliesValues) {
  const GroundRecord one = read_peer_at2(kElCentro, "k");
  const GroundRecord half = read_peer_at2(kElCentro, "k", 0.5);
  for (std::size_t i = 0; i < one.acceleration.size(); i += 97)
    EXPECT_DOUBLE_EQ(half.acceleration.value[i], 0.5 * one.acceleration.value[i]);
}

TEST(PeerAt2, TolerantHeaderAndFortranNumbers) {
  // NGA format header, lower case, compact spacing, Fortran numbers, a Windows line end,
  // fixed-width fields that run together.
  const std::string text =
      "PEER NGA STRONG MOTION DATABASE RECORD\nSOME EVENT, 1/1/2000\nACCELERATION TIME SERIES IN UNITS OF G\n"
      "npts= 6, dt=   .0050 SEC,\r\n"
      "  .123 -1.2E-02 +2.5d-1\n"
      "-0.10000-0.20000 3\n";
  const GroundRecord rec = read_peer_at2(write_temp("nga.at2", text), "k");
  ASSERT_EQ(rec.acceleration.size(), 6u);
  EXPECT_DOUBLE_EQ(rec.dt, 0.005);
  const double expected[] = {0.123, -0.012, 0.25, -0.1, -0.2, 3.0};
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(rec.acceleration.value[i], expected[i] * kStandardGravity, 1e-14);

  const std::string old_format = "a\nb\nc\n  3    0.0200    NPTS, DT\n 1 2 3\n";
  const GroundRecord rec2 = read_peer_at2(write_temp("old.at2", old_format), "k");
  EXPECT_EQ(rec2.acceleration.size(), 3u);
  EXPECT_DOUBLE_EQ(rec2.dt, 0.02);

  const std::string spaced = "a\nb\nc\nNPTS= 2 , DT= 0.02 SEC\n1.0\n2.0\n";
  EXPECT_EQ(read_peer_at2(write_temp("spaced.at2", spaced), "k").acceleration.size(), 2u);
}

TEST(PeerAt2, Errors) {
  // Missing file: names the file and the key.
  InputError e = expect_input_error([] { read_peer_at2("/nonexistent/x.at2", "excitation.file"); });
  EXPECT_EQ(e.key(), "excitation.file");
  EXPECT_NE(std::string(e.what()).find("/nonexistent/x.at2"), std::string::npos);

  // A corrupted copy of El Centro without its NPTS/DT line.
  std::ifstream in(kElCentro);
  std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::string no_header = all;
  const auto p = no_header.find("NPTS");
  no_header.erase(p, no_header.find('\n', p) - p);
  const std::string f1 = write_temp("no_header.at2", no_header);
  e = expect_input_error([&] { read_peer_at2(f1, "excitation.file"); });
  EXPECT_NE(std::string(e.what()).find("NPTS"), std::string::npos);
  EXPECT_EQ(e.key(), "excitation.file");

  // A non-numeric token on line 10 (line 4 is the header, values start on line 5).
  std::string bad = all;
  std::size_t pos = 0;
  for (int line = 1; line < 10; ++line) pos = bad.find('\n', pos) + 1;
  bad.replace(pos + 3, 7, "0.0x123");  // inside the first value of line 10
  const std::string f2 = write_temp("bad_token.at2", bad);
  e = expect_input_error([&] { read_peer_at2(f2, "excitation.file"); });
  EXPECT_EQ(e.where(), f2 + ":10");
  EXPECT_NE(std::string(e.what()).find("0.0x123"), std::string::npos);

  // Fewer values than NPTS.
  const std::string f3 = write_temp("short.at2", "a\nb\nc\nNPTS= 5, DT= .01 SEC\n1 2 3\n");
  e = expect_input_error([&] { read_peer_at2(f3, "k"); });
  EXPECT_NE(std::string(e.what()).find("NPTS = 5"), std::string::npos);
  // More values than NPTS.
  const std::string f4 = write_temp("long.at2", "a\nb\nc\nNPTS= 2, DT= .01 SEC\n1 2 3\n");
  e = expect_input_error([&] { read_peer_at2(f4, "k"); });
  EXPECT_EQ(e.where(), f4 + ":5");
  // Bad DT.
  const std::string f5 = write_temp("bad_dt.at2", "a\nb\nc\nNPTS= 2, DT= 0 SEC\n1 2\n");
  e = expect_input_error([&] { read_peer_at2(f5, "k"); });
  EXPECT_EQ(e.where(), f5 + ":4");
}

TEST(TwoColumnCsv, ReadsWithHeaderCommentsAndUnits) {
  const std::string text =
      "# ground motion, time in ms, acceleration in g\n"
      "time_ms, acc_g\n"
      "0, 0.0\n"
      "10,0.5   # trailing comment\n"
      "\n"
      "20 -0.25\n"
      "30\t1e-1\n";
  CsvRecordOptions opt;
  opt.time_factor = 1e-3;
  opt.value_factor = kStandardGravity;
  opt.scale = 2.0;
  const TimeSeries s = read_two_column_csv(write_temp("ok.csv", text), "excitation.file", opt);
  ASSERT_EQ(s.size(), 4u);
  EXPECT_DOUBLE_EQ(s.t[1], 0.01);
  EXPECT_DOUBLE_EQ(s.t[3], 0.03);
  EXPECT_DOUBLE_EQ(s.value[1], 0.5 * kStandardGravity * 2.0);
  EXPECT_DOUBLE_EQ(s.value[2], -0.25 * kStandardGravity * 2.0);
  // No header at all is fine too.
  EXPECT_EQ(read_two_column_csv(write_temp("nohdr.csv", "0 1\n1 2\n"), "k").size(), 2u);
}

TEST(TwoColumnCsv, Errors) {
  const std::string f1 = write_temp("dec.csv", "t,a\n0,1\n1,2\n1,3\n");
  InputError e = expect_input_error([&] { read_two_column_csv(f1, "excitation.file"); });
  EXPECT_EQ(e.where(), f1 + ":4");
  EXPECT_EQ(e.key(), "excitation.file");

  const std::string f2 = write_temp("nan.csv", "0,1\n1,nan\n");
  e = expect_input_error([&] { read_two_column_csv(f2, "k"); });
  EXPECT_EQ(e.where(), f2 + ":2");

  const std::string f3 = write_temp("three.csv", "0,1\n1,2,3\n");
  e = expect_input_error([&] { read_two_column_csv(f3, "k"); });
  EXPECT_EQ(e.where(), f3 + ":2");

  const std::string f4 = write_temp("word.csv", "t,a\n0,1\n1,abc\n");
  e = expect_input_error([&] { read_two_column_csv(f4, "k"); });
  EXPECT_EQ(e.where(), f4 + ":3");
  EXPECT_NE(std::string(e.what()).find("abc"), std::string::npos);

  const std::string f5 = write_temp("one.csv", "t,a\n0,1\n");
  e = expect_input_error([&] { read_two_column_csv(f5, "k"); });
  EXPECT_NE(std::string(e.what()).find("at least 2"), std::string::npos);

  e = expect_input_error([] { read_two_column_csv("/nonexistent/r.csv", "k"); });
  EXPECT_EQ(e.where(), "/nonexistent/r.csv");
}

TEST(FortranNumbers, SplitsRunTogetherFields) {
  std::vector<double> v;
  EXPECT_TRUE(parse_fortran_numbers("-0.12345-0.23456+1.5E-02", v));
  ASSERT_EQ(v.size(), 3u);
  EXPECT_DOUBLE_EQ(v[0], -0.12345);
  EXPECT_DOUBLE_EQ(v[1], -0.23456);
  EXPECT_DOUBLE_EQ(v[2], 0.015);
  v.clear();
  EXPECT_FALSE(parse_fortran_numbers("1.2.3", v));
  EXPECT_FALSE(parse_fortran_numbers("abc", v));
  EXPECT_FALSE(parse_fortran_numbers("1.5E", v));
  EXPECT_TRUE(v.empty());
}

}  // namespace
}  // namespace sloshsph
