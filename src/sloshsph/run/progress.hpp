#pragma once
// Progress of a run on stderr: a one-line bar on a terminal, plain lines every 10% otherwise.
#include <chrono>
#include <string>

namespace sloshsph {

class Progress {
 public:
  Progress(double end_time, bool enabled);
  void update(double time, std::size_t steps);
  void finish(double time, std::size_t steps);

 private:
  void print(double time, std::size_t steps, bool final);
  double end_;
  bool enabled_;
  bool tty_;
  int last_decile_ = -1;
  std::chrono::steady_clock::time_point start_, last_print_;
};

std::string format_duration(double seconds);

}  // namespace sloshsph
