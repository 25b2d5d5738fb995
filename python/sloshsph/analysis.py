"""Analysis of time series, on NumPy arrays: the engine's own functions (src/sloshsph/analysis),
the ones behind summary.json and the reports. References are in docs/physics.md."""

import json

import numpy as np

from . import _core


def _series(x, name="x"):
    a = np.asarray(x, dtype=float)
    if a.ndim != 1:
        raise ValueError(f"{name} must be a 1-D series, not of shape {a.shape}")
    return a


def lowpass(x, dt, cutoff_hz=5.0, order=4):
    """Zero-phase Butterworth low-pass (forward-backward), as the thesis filters its series at 5 Hz
    (sec. 2.6.3.1). ``dt`` is the sample interval (s)."""
    return _core.lowpass(_series(x), float(dt), float(cutoff_hz), int(order))


def steady_state_amplitude(t, x, period, cycles=10):
    """Mean of the per-cycle maxima and minima over the last ``cycles`` periods (thesis 2.6.3):
    {"avg_max", "avg_min", "cycles"}."""
    return _core.steady_state_amplitude(_series(t, "t"), _series(x), float(period), int(cycles))


def energy_per_cycle(t, force, displacement, period, cycles=10):
    """Energy dissipated per cycle, thesis eq. 4.28, closed integral of F dX averaged over the last
    ``cycles`` periods (J per metre of tank width in 2D). Returns (energy, cycles used)."""
    return _core.energy_per_cycle(_series(t, "t"), _series(force, "force"), _series(displacement, "displacement"),
                                  float(period), int(cycles))


def energy_per_cycle_from_work(t, work, period, cycles=10):
    """The same from the cumulative work column ``W_base`` of a run (preferred: exact at every
    step). Returns (energy, cycles used)."""
    return _core.energy_per_cycle_from_work(_series(t, "t"), _series(work, "work"), float(period), int(cycles))


def normalised_energy(energy, water_mass, amplitude, omega):
    """Thesis eq. 4.27: E / (0.5 m_w (X0 omega)^2)."""
    return _core.normalised_energy(float(energy), float(water_mass), float(amplitude), float(omega))


def welch_psd(x, dt, segment_length, overlap=0.5):
    """One-sided power spectral density (Welch, Hann window, density scaling: its integral is the
    variance). Returns (f in Hz, PSD in unit^2/Hz)."""
    return _core.welch_psd(_series(x), float(dt), int(segment_length), float(overlap))


def spectrum_integral(f, value, f_lo, f_hi):
    """Trapezoid integral of a spectrum (as welch_psd returns it) over [f_lo, f_hi]."""
    return _core.spectrum_integral(_series(f, "f"), _series(value, "value"), float(f_lo), float(f_hi))


def dominant_frequency(x, dt):
    """The dominant frequency (Hz) of a uniformly sampled series: the largest FFT bin refined by
    Jacobsen's three-bin estimator."""
    return _core.dominant_frequency(_series(x), float(dt))


def zero_crossing_period(t, x):
    """Mean period between up-crossings of the mean (s); 0 with fewer than two crossings."""
    return _core.zero_crossing_period(_series(t, "t"), _series(x))


def admittance(f, response_psd, stiffness, force_psd=None, force_psd_level=None, floor=1e-6):
    """Mechanical admittance |H(f)|^2 = S_x(f) K^2 / S_F(f), thesis eq. 4.30, from the response PSD on
    the grid ``f`` and either a measured force PSD on the same grid (bins below ``floor`` x its
    maximum set to 0) or a flat force level (N^2/Hz)."""
    f, s = _series(f, "f"), _series(response_psd, "response_psd")
    if (force_psd is None) == (force_psd_level is None):
        raise ValueError("give exactly one of force_psd and force_psd_level")
    if force_psd is not None:
        return _core.admittance_measured_force(f, s, _series(force_psd, "force_psd"), float(stiffness), float(floor))
    return _core.admittance_flat_force(f, s, float(force_psd_level), float(stiffness))


def sdof_admittance(f, natural_frequency, zeta):
    """|H|^2 of a linear SDOF: 1 / ((1 - r^2)^2 + (2 zeta r)^2), r = f / f_n."""
    return _core.sdof_admittance(_series(np.atleast_1d(f), "f"), float(natural_frequency), float(zeta))


def effective_damping_ratio(f, admittance, natural_frequency, f_lo, f_hi):
    """Effective damping from the area under the admittance (Vickery et al. 1983):
    zeta_eff = pi f_n / (4 A), A the integral of |H|^2 over [f_lo, f_hi]."""
    return _core.effective_damping_ratio(_series(f, "f"), _series(admittance, "admittance"),
                                         float(natural_frequency), float(f_lo), float(f_hi))


def steady_state_response(run, period=None, cycles=None, cutoff_hz=None, energy=True):
    """The steady-state response of a harmonically excited run, as summary.json's ``response``
    (every gauge, pressure probe and force: avg_max, avg_min; energy per cycle), recomputed
    from its time series, for example over other cycles or with another filter.

    ``run`` is a ``Run``; period (s) defaults to the case's 2 pi / omega, cycles and cutoff_hz to
    its output.response_cycles and output.lowpass_hz.
    """
    summary = run.summary
    resolved = run.case.to_dict()
    if period is None:
        omega = summary.get("excitation_omega_rad_s")
        if not omega:
            raise ValueError(f"{run.path}: the run has no periodic excitation; give period")
        period = 2.0 * np.pi / omega
    output = resolved.get("output", {})
    cycles = int(output.get("response_cycles", 10) if cycles is None else cycles)
    cutoff_hz = float(output.get("lowpass_hz", 5.0) if cutoff_hz is None else cutoff_hz)
    series = run.timeseries
    units = run.units
    names = list(series)
    amplitude = float(resolved.get("excitation", {}).get("amplitude", 0.0))
    text = _core.steady_state_response(names, [units.get(n, "") for n in names], [series[n] for n in names],
                                       float(period), cycles, cutoff_hz, float(summary.get("fluid_mass_kg_per_m", 0.0)),
                                       amplitude, bool(energy))
    return json.loads(text)
