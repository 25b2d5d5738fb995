#pragma once
// Steady-state response amplitudes and energy dissipated per cycle of harmonically excited
// tanks (thesis sec. 2.6.3 and 4.3.1: average maximum and minimum wave heights and forces over
// the last cycles; eqs. 4.27-4.28).
#include <vector>

namespace sloshsph {

struct SteadyAmplitude {
  double avg_max = 0.0;  // mean of the per-cycle maxima
  double avg_min = 0.0;  // mean of the per-cycle minima
  int cycles = 0;        // cycles used
};

// The last `n_cycles` windows of length `period` counted back from the last sample,
// [t_end - k T, t_end - (k - 1) T], k = 1 .. n; in each window the largest and smallest sample,
// refined by the vertex of the parabola through it and its two neighbours (when it is a local
// extremum of the whole record);
// returns the averages. Uses fewer cycles if the record is shorter (`cycles` says how many).
// Throws std::invalid_argument if not even one full cycle fits, or on a bad series.
SteadyAmplitude steady_state_amplitude(const std::vector<double>& t, const std::vector<double>& x, double period,
                                       int n_cycles);

struct CycleEnergy {
  double energy = 0.0;  // J per cycle
  int cycles = 0;
};

// Energy dissipated per cycle, thesis eq. 4.28: E_w = closed integral of F dX over one cycle,
// averaged over the last `n_cycles` cycles of `period` ending at the last sample:
//   E_w = (1 / n) sum_i (F_i + F_i+1) / 2 (X_i+1 - X_i)   (trapezoid on the samples; the window
//   start is linearly interpolated). F is the force the base exerts on the liquid (the base shear
//   F_w) and X the base displacement: positive E_w = work done on the liquid = energy dissipated
//   in the steady state. Throws std::invalid_argument if not one cycle fits.
CycleEnergy energy_per_cycle(const std::vector<double>& t, const std::vector<double>& force,
                             const std::vector<double>& displacement, double period, int n_cycles);

// The same from the cumulative work W(t) = integral_0^t F dX that the solver sums at every
// time step (the W_base column): E_w = (W(t_end) - W(t_end - n T)) / n, W interpolated at the
// window start. Preferred over the sampled form above when the force samples are interval
// means: pairing a mean over [t - dt_s, t] with the displacement at t lags F by dt_s / 2, which
// alone gives a rigidly moving liquid a spurious E'_w = 2 pi sin(omega dt_s / 2) (0.14 at
// omega = 4.43 rad/s and dt_s = 0.01 s). Throws std::invalid_argument if not one cycle fits.
CycleEnergy energy_per_cycle_from_work(const std::vector<double>& t, const std::vector<double>& work, double period,
                                       int n_cycles);

// Thesis eq. 4.27: E'_w = E_w / (0.5 m_w (X0 omega)^2), the energy per cycle over the largest
// kinetic energy of the liquid moving rigidly with the base.
double normalised_energy(double energy_per_cycle, double water_mass, double amplitude, double omega);

}  // namespace sloshsph
