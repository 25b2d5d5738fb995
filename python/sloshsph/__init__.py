"""sloshsph: SPH simulation of liquid sloshing in tanks and tuned liquid dampers, from Python.

The same engine as the ``sloshsph`` program (docs/python.md):

    import sloshsph
    case = sloshsph.Case.from_file("cases/liu_lin_2008.toml").set("time.end", 3.0)
    run = sloshsph.run(case, out="runs/liu_lin", threads=2)
    eta = run.timeseries["eta:left"]

Cases (``Case``), runs (``run``, ``resume``, ``read_run``/``Run``), sweeps (``sweep``/``Sweep``),
linear theory (``modes``, ``linear``, ``tune``), analysis (``sloshsph.analysis``) and particle snapshots
(``read_vtu``). Errors: ``CaseError`` (the program's exit 2), ``RunFailed`` (3), ``Interrupted`` (4).
"""

import json as _json

from . import _core, analysis
from .case import Case, as_case
from .errors import CaseError, Interrupted, RunFailed
from .runs import ProgressInfo, Run, read_run, resume, run
from .sweep import Sweep, read_frequency_response, sweep
from .vtu import read_pvd, read_vtu

__version__ = _core.version
git_revision = _core.git_revision


def modes(case, count=4, tank_damping=(), tank_frequency_scale=1.0):
    """The first linear sloshing modes of the case's tank and fill, as ``sloshsph modes --json``:
    {"modes": [{"omega", "frequency", "effective_mass_fraction"}, ...]} and, for a case whose
    [structure] carries the tanks, "equivalent_tmd" (the tanks as a linear TMD, at the tank
    damping ratios 0.5-10% and ``tank_damping``, with the optimum)."""
    c = as_case(case)
    if not 1 <= int(count) <= 50:
        raise ValueError(f"count must be in 1..50, not {count!r}")
    text = _core.modes(c._text, c.source, c.name, c.overrides, int(count), [float(z) for z in tank_damping],
                       float(tank_frequency_scale))
    return _json.loads(text)


def linear(case, modes=10, damping="auto", screens=True):
    """The linear modal solution from rest of the case's tank under its horizontal base motion, as
    ``sloshsph linear`` writes it: {"series": {"time", "eta:<gauge>"..., "F_w", "F_sw"} (lists, every
    ``output.sample_interval`` to ``time.end``), "modes": [{"omega", "zeta", "horizontal_forcing"}, ...],
    "damping_model", "screens": [{"x", "z_from", "z_to", "loss_coefficient", "linear_resistance"}, ...],
    "ignored"}. ``damping`` is "auto" (the laminar boundary layers of a clean
    rectangular tank, none for other sections), "none", "boundary-layer", or a ratio for every mode
    (a number). ``screens``: the pressure loss of the case's vertical screens in a rectangular tank
    acts on the modes (``--screens drag``); False: a clean tank (``--screens none``). Raises
    CaseError for a pitch, a tank on a [structure], or a damping it cannot use."""
    c = as_case(case)
    if not 1 <= int(modes) <= 50:
        raise ValueError(f"modes must be in 1..50, not {modes!r}")
    if not isinstance(damping, str):
        damping = repr(float(damping))
    return _core.linear(c._text, c.source, c.name, c.overrides, int(modes), damping, bool(screens))


def tune(case, target_omega, mass=None):
    """The fill depth that gives the case's tank the first sloshing frequency ``target_omega``
    (rad/s), as ``sloshsph tune --json``: {"target_omega", "depth", "omega", "area"} and, with a
    water mass (kg), "mass" and the tank width "width" that holds it."""
    c = as_case(case)
    if not float(target_omega) > 0:
        raise ValueError(f"target_omega must be positive, not {target_omega!r}")
    if mass is not None and not float(mass) > 0:
        raise ValueError(f"mass must be positive, not {mass!r}")
    return _core.tune(c._text, c.source, c.name, c.overrides, float(target_omega),
                      None if mass is None else float(mass))


__all__ = ["Case", "CaseError", "Interrupted", "ProgressInfo", "Run", "RunFailed", "Sweep", "analysis", "linear", "modes",
           "read_frequency_response", "read_pvd", "read_run", "read_vtu", "resume", "run", "sweep", "tune"]
