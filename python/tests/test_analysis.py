"""The analysis functions on arrays, against closed forms (issue 32, 1)."""

import numpy as np
import pytest
from sloshsph import analysis

DT = 0.01
T = np.arange(0.0, 60.0, DT)


def test_lowpass_passes_below_and_halves_at_the_cutoff():
    # Zero-phase Butterworth: |H|^2, so -6.02 dB (a factor 0.5 in amplitude) at the cut-off.
    slow = np.sin(2 * np.pi * 0.5 * T)
    assert np.max(np.abs(analysis.lowpass(slow, DT, 5.0) - slow)[500:-500]) < 1e-3
    at_cutoff = np.sin(2 * np.pi * 5.0 * T)
    amplitude = np.max(np.abs(analysis.lowpass(at_cutoff, DT, 5.0)[1000:-1000]))
    assert amplitude == pytest.approx(0.5, abs=0.01)


def test_welch_psd_integrates_to_the_variance():
    x = 0.3 * np.sin(2 * np.pi * 1.25 * T)  # variance A^2 / 2 = 0.045
    f, s = analysis.welch_psd(x, DT, 1024)
    assert analysis.spectrum_integral(f, s, 0.0, f[-1]) == pytest.approx(0.045, rel=0.02)
    assert f[np.argmax(s)] == pytest.approx(1.25, abs=f[1])


def test_dominant_frequency_and_zero_crossing_period():
    x = np.sin(2 * np.pi * 0.7321 * T + 0.3)
    assert analysis.dominant_frequency(x, DT) == pytest.approx(0.7321, rel=1e-3)
    assert analysis.zero_crossing_period(T, x) == pytest.approx(1 / 0.7321, rel=1e-3)


def test_steady_state_amplitude_of_a_sine():
    x = 0.02 * np.sin(2 * np.pi * T / 1.3) + 0.001
    a = analysis.steady_state_amplitude(T, x, 1.3, cycles=10)
    assert a["avg_max"] == pytest.approx(0.021, rel=1e-4)
    assert a["avg_min"] == pytest.approx(-0.019, rel=1e-4)
    assert a["cycles"] == 10


def test_energy_per_cycle_of_a_linear_damper():
    # F = c v, X = X0 sin(w t): closed integral of F dX = pi c w X0^2 per cycle.
    c, w, x0 = 3.0, 2 * np.pi / 1.3, 0.01
    x = x0 * np.sin(w * T)
    v = x0 * w * np.cos(w * T)
    energy, cycles = analysis.energy_per_cycle(T, c * v, x, 1.3, 10)
    assert energy == pytest.approx(np.pi * c * w * x0**2, rel=1e-3)
    work = np.concatenate([[0.0], np.cumsum(0.5 * (c * v[1:] + c * v[:-1]) * np.diff(x))])
    energy_w, _ = analysis.energy_per_cycle_from_work(T, work, 1.3, 10)
    assert energy_w == pytest.approx(np.pi * c * w * x0**2, rel=1e-3)
    assert analysis.normalised_energy(energy, 2.0, x0, w) == pytest.approx(energy / (0.5 * 2.0 * (x0 * w) ** 2))


def test_effective_damping_of_an_sdof_is_its_damping():
    # Vickery et al. (1983): the area method gives back zeta of a linear SDOF (band 0-20 f_n: the
    # tail left out is about 0.2% of the area at zeta = 2%).
    fn, zeta = 0.5, 0.02
    f = np.linspace(0.0, 10.0, 200001)
    h2 = analysis.sdof_admittance(f, fn, zeta)
    assert h2[0] == pytest.approx(1.0)
    assert analysis.effective_damping_ratio(f, h2, fn, 0.0, 10.0) == pytest.approx(zeta, rel=0.01)


def test_admittance_of_a_static_response():
    # x = F / K below resonance: |H|^2 = S_x K^2 / S_F = 1.
    f = np.linspace(0.0, 1.0, 11)
    k = 250.0
    force = np.full(11, 4.0)
    h2 = analysis.admittance(f, force / k**2, k, force_psd=force)
    np.testing.assert_allclose(h2, 1.0)
    np.testing.assert_allclose(analysis.admittance(f, force / k**2, k, force_psd_level=4.0), 1.0)
    with pytest.raises(ValueError, match="exactly one"):
        analysis.admittance(f, force, k)


def test_bad_input_raises_value_error():
    with pytest.raises(ValueError):
        analysis.steady_state_amplitude(T[:10], T[:10], 1.3)  # not one cycle
    with pytest.raises(ValueError, match="1-D"):
        analysis.lowpass(np.zeros((3, 3)), DT)
