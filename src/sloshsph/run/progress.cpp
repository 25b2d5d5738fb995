#include "sloshsph/run/progress.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>

namespace sloshsph {

std::string format_duration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "--:--";
  const long s = static_cast<long>(seconds + 0.5);
  char buf[32];
  if (s >= 3600) std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  else std::snprintf(buf, sizeof buf, "%ld:%02ld", s / 60, s % 60);
  return buf;
}

Progress::Progress(double end_time, bool enabled)
    : end_(end_time), enabled_(enabled), tty_(isatty(STDERR_FILENO) != 0) {
  start_ = last_print_ = std::chrono::steady_clock::now();
}

void Progress::update(double time, std::size_t steps) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (tty_) {
    if (now - last_print_ < std::chrono::milliseconds(250)) return;
    print(time, steps, false);
    last_print_ = now;
  } else {
    const int decile = static_cast<int>(10.0 * time / end_);
    if (decile <= last_decile_) return;
    last_decile_ = decile;
    print(time, steps, false);
  }
}

void Progress::finish(double time, std::size_t steps) {
  if (!enabled_) return;
  print(time, steps, true);
}

void Progress::print(double time, std::size_t steps, bool final) {
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double fraction = end_ > 0 ? std::min(1.0, time / end_) : 1.0;
  const double rate = wall > 0 ? steps / wall : 0.0;
  const double eta = fraction > 0 ? wall * (1.0 - fraction) / fraction : NAN;
  if (tty_) {
    constexpr int width = 30;
    const int filled = static_cast<int>(fraction * width);
    std::string bar(filled, '#');
    bar += std::string(width - filled, '.');
    std::fprintf(stderr, "\r[%s] %5.1f%%  t = %.3f / %.3f s  %6.0f steps/s  ETA %s   %s", bar.c_str(),
                 100.0 * fraction, time, end_, rate, format_duration(eta).c_str(), final ? "\n" : "");
  } else {
    std::fprintf(stderr, "progress: %5.1f%%  t = %.3f / %.3f s  steps = %zu  %.0f steps/s  elapsed %s  ETA %s\n",
                 100.0 * fraction, time, end_, steps, rate, format_duration(wall).c_str(),
                 format_duration(final ? 0.0 : eta).c_str());
  }
  std::fflush(stderr);
}

}  // namespace sloshsph
