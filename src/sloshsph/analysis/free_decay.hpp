#pragma once
// Damping ratio and frequency of a free decay (a sloshing tank left alone, a structure let go).
#include <vector>

namespace sloshsph {

struct FreeDecayFit {
  double zeta = 0.0;    // damping ratio from the logarithmic decrement
  double omega = 0.0;   // rad/s, 2 pi / the mean up-crossing period
  int cycles = 0;       // full cycles used
  double first_height = 0.0;  // crest-to-trough height of the first cycle (units of y)
};

// Fits y(t) over its whole span (cut it to the free part first): the mean is removed, the cycles
// run between successive up-crossings (interpolated), each cycle's crest-to-trough height H_k is
// taken, and ln H_k = c - delta k is fitted by least squares; zeta = delta / sqrt(4 pi^2 +
// delta^2) (the logarithmic decrement of a linear oscillator). Heights rather than crests make it
// insensitive to a steady offset of the signal (e.g. a gauge's bias). Throws
// std::invalid_argument with fewer than 3 full cycles.
FreeDecayFit fit_free_decay(const std::vector<double>& t, const std::vector<double>& y);

}  // namespace sloshsph
