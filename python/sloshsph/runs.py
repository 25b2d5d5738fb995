"""Running cases and reading run directories (also those the ``sloshsph`` program made)."""

import json
import os
import sys
import time as _time


from . import _core
from .case import Case, as_case
from .errors import Interrupted, RunFailed
from .vtu import read_pvd, read_vtu

EXIT_SUCCESS, EXIT_RUN_FAILED, EXIT_INTERRUPTED = 0, 3, 4


class ProgressInfo:
    """What a progress callback receives after every sample of a run.

    Attributes: ``time`` (s simulated), ``end`` (s, the case's time.end), ``steps``, ``wall``
    (s since this call started), ``fraction`` (time / end).
    """

    __slots__ = ("time", "end", "steps", "wall", "fraction")

    def __init__(self, time, end, steps, wall):
        self.time, self.end, self.steps, self.wall = time, end, steps, wall
        self.fraction = min(1.0, time / end) if end > 0 else 1.0

    def __repr__(self):
        return f"<ProgressInfo t={self.time:.4g}/{self.end:.4g} s, {self.steps} steps, {self.wall:.1f} s>"


class _Bar:
    """A one-line progress bar on sys.stderr (also in a notebook), at most ten redraws a second."""

    def __init__(self, label):
        self.label = label
        self.last = 0.0

    def __call__(self, info):
        now = _time.monotonic()
        if now - self.last < 0.1 and info.fraction < 1.0:
            return
        self.last = now
        eta = info.wall * (1.0 - info.fraction) / info.fraction if info.fraction > 0 else float("nan")
        filled = int(30 * info.fraction)
        sys.stderr.write(f"\r{self.label} [{'#' * filled}{'.' * (30 - filled)}] "
                         f"t = {info.time:.3f} / {info.end:.3f} s, {info.steps} steps, ETA {eta:.0f} s ")
        if info.fraction >= 1.0:
            sys.stderr.write("\n")
        sys.stderr.flush()


def _progress_function(progress, label):
    """The C++ callback (time, end_time, steps) -> None/False for the ``progress`` argument."""
    if progress is None:
        progress = sys.stderr.isatty()
    if progress is False:
        return None
    report = _Bar(label) if progress is True else progress
    if not callable(report):
        raise TypeError("progress is True, False, None or a callable taking a ProgressInfo")
    start = _time.monotonic()
    state = {"stopped": False}

    def callback(t, end_time, steps):
        result = report(ProgressInfo(t, end_time, steps, _time.monotonic() - start))
        if result is False:
            state["stopped"] = True
        return result

    callback.state = state
    return callback


def _command_line(function):
    return f"python {' '.join(sys.argv) if sys.argv and sys.argv[0] else '(interactive)'}: sloshsph.{function}"


def _finish(code, path, check, stopped_by_callback):
    result = Run(path)
    if not check or code == EXIT_SUCCESS:
        return result
    if code == EXIT_RUN_FAILED:
        raise RunFailed(f"run failed: {result.summary.get('failure', '(no reason recorded)')} ({path})", result)
    if code == EXIT_INTERRUPTED and stopped_by_callback:
        return result  # the callback asked for the stop: not an error
    if code == EXIT_INTERRUPTED:
        raise Interrupted(f"interrupted at t = {result.summary.get('simulated_time_s', float('nan')):.6g} s; "
                          f"resume with sloshsph.resume({path!r})", result)
    raise RuntimeError(f"unexpected exit code {code} from the engine ({path})")


def _threads(threads):
    if threads is None:
        return 0
    if int(threads) < 1:
        raise ValueError(f"threads must be a positive number, not {threads!r}")
    return int(threads)


def _checkpoint(every):
    if every is None:
        return 0.0
    if not float(every) > 0.0:
        raise ValueError(f"checkpoint_every must be a positive number of seconds, not {every!r}")
    return float(every)


def run(case, out=None, *, threads=None, force=False, progress=None, checkpoint_every=None, check=True):
    """Runs a case into a run directory, as ``sloshsph run`` does, and returns its ``Run``.

    Args:
        case: a ``Case``, a case file's path, or a dict of tables.
        out: the run directory (default ``out/<case name>``); an existing, non-empty one is
            refused unless ``force``.
        threads: OpenMP threads (default: all cores); results do not depend on it.
        progress: None (a bar when stderr is a terminal), True (a bar), False, or a callable
            taking a ``ProgressInfo`` after every sample; a callable that returns False stops the
            run (it is then resumable, and no exception is raised).
        checkpoint_every: write checkpoint.bin every so many simulated seconds.
        check: raise ``RunFailed`` (exit 3) and ``Interrupted`` (exit 4); with False, return the
            ``Run`` whatever its status.

    The engine runs without Python's global lock: other Python threads go on meanwhile. Ctrl-C
    (SIGINT) or SIGTERM stops the run after its current step with consistent, resumable
    outputs, and raises ``Interrupted`` (a KeyboardInterrupt). A bad case raises ``CaseError``
    before anything is written.
    """
    case = as_case(case)
    callback = _progress_function(progress, case.name)
    path = os.fspath(out) if out is not None else os.path.join("out", case.name)
    code = _core.run_case(case._text, case.source, case.name, case.overrides, path, bool(force), _threads(threads),
                          _checkpoint(checkpoint_every), _command_line("run"), callback)
    return _finish(code, path, check, callback is not None and callback.state["stopped"])


def resume(run_dir, *, threads=None, progress=None, checkpoint_every=None, check=True):
    """Continues an interrupted run from its checkpoint.bin, as ``sloshsph resume`` does. With the
    thread count of the first part, the results are bitwise those of an unbroken run. Raises
    ``CaseError`` when the directory has no checkpoint or its case.toml changed."""
    path = os.fspath(run_dir)
    callback = _progress_function(progress, os.path.basename(os.path.normpath(path)))
    code = _core.resume_run(path, _threads(threads), _checkpoint(checkpoint_every), _command_line("resume"), callback)
    return _finish(code, path, check, callback is not None and callback.state["stopped"])


class Run:
    """A run directory, read lazily: what ``sloshsph run`` (or ``sloshsph.run``) wrote.

    Attributes and methods:
        path: the directory.
        summary: summary.json as a dict (status, counts, throughput, ``response``, ...).
        status: "completed", "failed", "interrupted" (or "" when summary.json is missing).
        info: run.json (provenance) as a dict.
        case: the resolved case (case.toml) as a ``Case``.
        timeseries: timeseries.csv as a dict {column: float64 array}, in file order.
        units: {column: unit} (from summary.json).
        dataframe(): the time series as a pandas DataFrame (needs pandas).
        snapshots: [(time, vtu path), ...] from particles.pvd.
        snapshot(k): snapshot k (negative counts from the end) as a dict of arrays.
        response: summary.json's steady-state response (harmonic runs), or None.
    """

    def __init__(self, path):
        self.path = os.fspath(path)
        if not os.path.isdir(self.path):
            from .errors import CaseError

            raise CaseError(f"{self.path}: not a run directory", self.path, "", "not a run directory")
        self._timeseries = None

    def _file(self, name):
        return os.path.join(self.path, name)

    def _json(self, name):
        try:
            with open(self._file(name), encoding="utf-8") as f:
                return json.load(f)
        except FileNotFoundError:
            return {}

    @property
    def summary(self):
        return self._json("summary.json")

    @property
    def info(self):
        return self._json("run.json")

    @property
    def status(self):
        return self.summary.get("status", "")

    @property
    def case(self):
        return Case.from_file(self._file("case.toml"))

    @property
    def timeseries(self):
        if self._timeseries is None:
            names, columns = _core.read_csv_table(self._file("timeseries.csv"))
            self._timeseries = dict(zip(names, columns))
        return self._timeseries

    def reload(self):
        """Forgets the cached time series (for a run still being written)."""
        self._timeseries = None
        return self

    @property
    def units(self):
        return dict(self.summary.get("columns", {}))

    def dataframe(self):
        """The time series as a pandas DataFrame indexed by time (pandas is optional: ImportError
        with a hint when it is not installed)."""
        try:
            import pandas as pd
        except ImportError as e:
            raise ImportError("Run.dataframe() needs pandas (Debian: apt install python3-pandas); "
                              "Run.timeseries gives the same columns as NumPy arrays") from e
        frame = pd.DataFrame(self.timeseries)
        return frame.set_index("time") if "time" in frame else frame

    @property
    def snapshots(self):
        pvd = self._file("particles.pvd")
        return read_pvd(pvd) if os.path.isfile(pvd) else []

    def snapshot(self, k=-1):
        """Snapshot ``k`` of ``snapshots`` as a dict of arrays (``sloshsph.read_vtu``), with its
        ``time``."""
        entries = self.snapshots
        if not entries:
            raise IndexError(f"{self.path} has no particle snapshots (output.snapshot_interval = 0?)")
        t, vtu = entries[k]
        arrays = read_vtu(vtu)
        arrays["time"] = t
        return arrays

    @property
    def response(self):
        return self.summary.get("response")

    def __repr__(self):
        return f"<sloshsph.Run {self.path!r} {self.status or 'no summary'}>"


def read_run(path):
    """The run directory at ``path`` as a ``Run``."""
    return Run(path)


__all__ = ["run", "resume", "read_run", "Run", "ProgressInfo"]
